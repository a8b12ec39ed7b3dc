// cbd_render: small offscreen software renderer for cbd results (README / report figures).
// Orthographic flat-shaded z-buffer rasterizer; PNG through ImageMagick's `convert`.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "cbd/mesh.h"  // vcglib's complex.h first: the importers below rely on it

#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>

namespace {
namespace fs = std::filesystem;
using cbd::Vec3;
using RGB = std::array<float, 3>;

constexpr int kSS = 2;  // supersampling factor per axis

const char* kUsage =
    "usage: cbd_render --out image.png [options] mesh.ply [mesh2.ply ...]\n"
    "Software (offscreen) renderer: each mesh gets its own auto-framed tile, tiles in a row.\n"
    "  --out FILE          output image (.png or anything ImageMagick writes; .ppm written directly)\n"
    "  --size WxH          whole image size (default 640x480 per tile)\n"
    "  --view V            side|front|top|iso|all (default side); all = 2x2 grid of\n"
    "                      side,front/top,iso per mesh, meshes stacked top to bottom\n"
    "  --up x|y|z          up axis (default y). With up=y: side looks along -z, front along -x,\n"
    "                      top along -y, iso from (+x,+y,+z); other axes permute cyclically\n"
    "  --flip              look from the opposite side\n"
    "  --color C           auto|face|vertex|quality|uniform (default auto: face colour if the\n"
    "                      file has it, else vertex colour, else uniform grey); quality uses\n"
    "                      face quality if present, else vertex quality, mapped through viridis\n"
    "  --lines FILE        edge-only PLY drawn on top of the surface (depth-tested); repeat it,\n"
    "                      the i-th --lines goes with the i-th mesh; polyline ends drawn as dots\n"
    "  --line-width PX     line width in output pixels (default 2)\n"
    "  --line-color C      dark|vertex (default dark; vertex = the file's vertex colours)\n"
    "  --title TEXT        title above the tiles\n"
    "  --labels            write file name and view in each tile\n"
    "  -h, --help          this text\n";

[[noreturn]] void fail(const std::string& msg) {
  std::cerr << "cbd_render: error: " << msg << "\n";
  std::exit(1);
}

struct Options {
  std::string out, view = "side", color = "auto", lineColor = "dark", title;
  int width = 0, height = 0, up = 1;
  double lineWidth = 2;
  bool flip = false, labels = false;
  std::vector<std::string> meshes, lines;
};

Options parseArgs(int argc, char** argv) {
  Options o;
  auto value = [&](int& i) -> std::string {
    if (i + 1 >= argc) fail(std::string("option ") + argv[i] + " needs a value");
    return argv[++i];
  };
  auto oneOf = [](const std::string& v, std::initializer_list<const char*> ok, const char* what) {
    for (const char* s : ok)
      if (v == s) return v;
    fail(std::string("unknown ") + what + " '" + v + "' (see --help)");
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") { std::cout << kUsage; std::exit(0); }
    else if (a == "--out") o.out = value(i);
    else if (a == "--size") {
      const std::string v = value(i);
      char x = 0, rest = 0;
      if (std::sscanf(v.c_str(), "%d%c%d%c", &o.width, &x, &o.height, &rest) != 3 || (x != 'x' && x != 'X') ||
          o.width < 16 || o.height < 16 || o.width > 16384 || o.height > 16384)
        fail("bad --size '" + v + "': expected WxH, 16..16384 pixels each");
    }
    else if (a == "--view") o.view = oneOf(value(i), {"side", "front", "top", "iso", "all"}, "view");
    else if (a == "--color") o.color = oneOf(value(i), {"auto", "face", "vertex", "quality", "uniform"}, "colour mode");
    else if (a == "--line-color") o.lineColor = oneOf(value(i), {"dark", "vertex"}, "line colour");
    else if (a == "--up") o.up = oneOf(value(i), {"x", "y", "z"}, "up axis")[0] - 'x';
    else if (a == "--lines") o.lines.push_back(value(i));
    else if (a == "--line-width") {
      const std::string v = value(i);
      char* end = nullptr;
      o.lineWidth = std::strtod(v.c_str(), &end);
      if (*end || !(o.lineWidth > 0 && o.lineWidth <= 50)) fail("bad --line-width '" + v + "': expected 0 < PX <= 50");
    }
    else if (a == "--title") o.title = value(i);
    else if (a == "--flip") o.flip = true;
    else if (a == "--labels") o.labels = true;
    else if (a.size() > 1 && a[0] == '-') fail("unknown option '" + a + "' (see --help)");
    else o.meshes.push_back(a);
  }
  if (o.out.empty()) fail("--out FILE is required (see --help)");
  if (o.meshes.empty()) fail("no mesh given (see --help)");
  if (o.lines.size() > o.meshes.size()) fail("more --lines files than meshes (the i-th --lines goes with the i-th mesh)");
  return o;
}

// ---------------------------------------------------------------------------- scene data
struct Segment { Vec3 a, b; RGB ca, cb; };
struct Model {
  std::string name;
  std::vector<Vec3> pos;
  std::vector<std::array<int, 3>> tris;
  std::vector<std::array<RGB, 3>> triColor;  // per face corner
  std::vector<Segment> segs;
  std::vector<Vec3> dots;                     // polyline ends
  bool quality = false;
  double qmin = 0, qmax = 0;
};

RGB toRGB(const vcg::Color4b& c) { return {c[0] / 255.f, c[1] / 255.f, c[2] / 255.f}; }

RGB viridis(double t) {
  static const float k[9][3] = {{68, 1, 84},    {71, 45, 123},  {59, 82, 139},  {44, 114, 142}, {33, 144, 140},
                                {39, 173, 129}, {93, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 8;
  const int i = std::min(7, static_cast<int>(t));
  const float f = static_cast<float>(t - i);
  RGB c;
  for (int j = 0; j < 3; ++j) c[j] = ((1 - f) * k[i][j] + f * k[i + 1][j]) / 255.f;
  return c;
}

int fileMask(const std::string& path, const cbd::LoadResult& r) {
  namespace io = vcg::tri::io;
  std::string ext = fs::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  int mask = 0;
  if (ext == ".ply") io::ImporterPLY<cbd::Mesh>::LoadMask(path.c_str(), mask);
  else if (ext == ".off") io::ImporterOFF<cbd::Mesh>::LoadMask(path.c_str(), mask);
  if (r.hasVertexColor) mask |= io::Mask::IOM_VERTCOLOR;
  if (r.hasVertexQuality) mask |= io::Mask::IOM_VERTQUALITY;
  return mask;
}

// Loads a file; a file without faces (e.g. a polyline PLY) is accepted when it has vertices.
int loadAny(const std::string& path, cbd::Mesh& m) {
  const cbd::LoadResult r = cbd::loadMesh(path, m);
  if (!r.status && r.status.code == cbd::ErrorCode::EmptyMesh && m.VN() == 0) fail("'" + path + "' has no vertices: nothing to draw");
  if (!r.status && r.status.code != cbd::ErrorCode::EmptyMesh) fail(r.status.message);
  return fileMask(path, r);
}

void addLines(Model& model, const std::string& path, bool vertexColor) {
  cbd::Mesh m;
  const int mask = loadAny(path, m);
  if (m.EN() == 0) std::cerr << "cbd_render: warning: '" << path << "' has no edges: nothing to draw\n";
  const bool useColor = vertexColor && (mask & vcg::tri::io::Mask::IOM_VERTCOLOR);
  const RGB dark = {0.1f, 0.1f, 0.1f};
  std::vector<int> degree(m.vert.size(), 0);
  for (const auto& e : m.edge) {
    if (e.IsD()) continue;
    const auto *a = e.cV(0), *b = e.cV(1);
    model.segs.push_back({Vec3(a->cP()[0], a->cP()[1], a->cP()[2]), Vec3(b->cP()[0], b->cP()[1], b->cP()[2]),
                          useColor ? toRGB(a->cC()) : dark, useColor ? toRGB(b->cC()) : dark});
    ++degree[vcg::tri::Index(m, a)];
    ++degree[vcg::tri::Index(m, b)];
  }
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (degree[i] == 1) model.dots.emplace_back(m.vert[i].cP()[0], m.vert[i].cP()[1], m.vert[i].cP()[2]);
}

Model loadModel(const std::string& path, std::string mode, const Options& o) {
  namespace io = vcg::tri::io;
  cbd::Mesh m;
  const int mask = loadAny(path, m);
  Model model;
  const fs::path fp(path);  // label: parent folder and file name ("target/layout.ply")
  model.name = (fp.parent_path().filename() / fp.filename()).string();
  const bool fc = mask & io::Mask::IOM_FACECOLOR, vc = mask & io::Mask::IOM_VERTCOLOR;
  const bool fq = mask & io::Mask::IOM_FACEQUALITY, vq = mask & io::Mask::IOM_VERTQUALITY;
  if (mode == "auto") mode = fc ? "face" : vc ? "vertex" : "uniform";
  if ((mode == "face" && !fc) || (mode == "vertex" && !vc) || (mode == "quality" && !fq && !vq)) {
    if (m.FN() > 0)
      std::cerr << "cbd_render: warning: '" << path << "' has no " << (mode == "face" ? "face colour" : mode == "vertex" ? "vertex colour" : "quality")
                << ": drawn in uniform grey\n";
    mode = "uniform";
  }
  std::vector<int> index(m.vert.size(), -1);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD()) continue;
    index[i] = static_cast<int>(model.pos.size());
    model.pos.emplace_back(m.vert[i].cP()[0], m.vert[i].cP()[1], m.vert[i].cP()[2]);
  }
  if (mode == "quality") {
    model.quality = true;
    model.qmin = std::numeric_limits<double>::max();
    model.qmax = std::numeric_limits<double>::lowest();
    for (const auto& f : m.face)
      for (int k = 0; k < 3 && !f.IsD(); ++k) {
        const double q = fq ? f.cQ() : f.cV(k)->cQ();
        model.qmin = std::min(model.qmin, q), model.qmax = std::max(model.qmax, q);
      }
  }
  const RGB grey = {0.78f, 0.78f, 0.76f};
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    std::array<int, 3> t;
    std::array<RGB, 3> c;
    for (int k = 0; k < 3; ++k) {
      t[k] = index[vcg::tri::Index(m, f.cV(k))];
      if (mode == "face") c[k] = toRGB(f.cC());
      else if (mode == "vertex") c[k] = toRGB(f.cV(k)->cC());
      else if (mode == "quality") {
        const double q = fq ? f.cQ() : f.cV(k)->cQ(), span = model.qmax - model.qmin;
        c[k] = viridis(span > 0 ? (q - model.qmin) / span : 0.5);
      } else c[k] = grey;
    }
    model.tris.push_back(t);
    model.triColor.push_back(c);
  }
  if (m.EN() > 0) addLines(model, path, o.lineColor == "vertex");  // a polyline file given as a mesh
  if (model.tris.empty() && model.segs.empty())
    std::cerr << "cbd_render: warning: '" << path << "' has no faces and no edges: its tile is empty\n";
  return model;
}

// ---------------------------------------------------------------------------- camera
struct Camera { Vec3 right, up, toward; };  // toward: from the scene to the eye

Camera makeCamera(const std::string& view, int upAxis, bool flip) {
  Vec3 u = Vec3::Zero(), a = Vec3::Zero(), b = Vec3::Zero();
  u[upAxis] = 1, a[(upAxis + 1) % 3] = 1, b[(upAxis + 2) % 3] = 1;  // (b, u, a) is right-handed
  Vec3 t = view == "front" ? b : view == "top" ? u : view == "iso" ? Vec3(a + b + u).normalized() : a;
  const Vec3 hint = view == "top" ? Vec3(-a) : u;
  if (flip) t = -t;
  Camera c;
  c.toward = t;
  c.right = hint.cross(t).normalized();
  c.up = t.cross(c.right);
  return c;
}

// ---------------------------------------------------------------------------- rasterizer
struct Buffer {
  int w, h;
  std::vector<RGB> color;
  std::vector<float> depth;
  Buffer(int w_, int h_) : w(w_), h(h_), color(size_t(w) * h, RGB{1, 1, 1}), depth(size_t(w) * h, -std::numeric_limits<float>::infinity()) {}
};
struct SV { double x, y, z; };

// Edge function evaluated with the endpoints in a canonical order, so the two triangles sharing
// an edge get exactly opposite values: with the inclusive test below no pixel falls in between.
double edgeFn(const SV& p, const SV& q, double x, double y) {
  const bool swap = p.x > q.x || (p.x == q.x && p.y > q.y);
  const SV& s = swap ? q : p;
  const SV& e = swap ? p : q;
  const double v = (e.x - s.x) * (y - s.y) - (e.y - s.y) * (x - s.x);
  return swap ? -v : v;
}

void drawTriangle(Buffer& buf, const std::array<SV, 3>& v, const std::array<RGB, 3>& c, float shade) {
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
  const int x1 = std::min(buf.w - 1, static_cast<int>(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
  const int y1 = std::min(buf.h - 1, static_cast<int>(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double e0 = edgeFn(v[1], v[2], px, py), e1 = edgeFn(v[2], v[0], px, py), e2 = edgeFn(v[0], v[1], px, py);
      const double area = e0 + e1 + e2;  // twice the signed area, either orientation (back faces too)
      if (area == 0 || (area > 0 ? std::min({e0, e1, e2}) < 0 : std::max({e0, e1, e2}) > 0)) continue;
      const double w0 = e0 / area, w1 = e1 / area, w2 = e2 / area;
      const float z = static_cast<float>(w0 * v[0].z + w1 * v[1].z + w2 * v[2].z);
      const size_t i = size_t(y) * buf.w + x;
      if (z <= buf.depth[i]) continue;
      buf.depth[i] = z;
      for (int j = 0; j < 3; ++j) buf.color[i][j] = shade * float(w0 * c[0][j] + w1 * c[1][j] + w2 * c[2][j]);
    }
}

void stamp(Buffer& buf, double cx, double cy, double r, const RGB& c) {
  for (int y = std::max(0, int(std::floor(cy - r))); y <= std::min(buf.h - 1, int(std::ceil(cy + r))); ++y)
    for (int x = std::max(0, int(std::floor(cx - r))); x <= std::min(buf.w - 1, int(std::ceil(cx + r))); ++x)
      if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) <= r * r) buf.color[size_t(y) * buf.w + x] = c;
}

// A line sample is drawn when the surface under its centre is not in front of it (minus a bias).
bool visible(const Buffer& buf, const SV& p, double bias) {
  const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
  if (x < 0 || y < 0 || x >= buf.w || y >= buf.h) return false;
  return p.z + bias >= buf.depth[size_t(y) * buf.w + x];
}

// Renders one model into a w x h (output pixels) tile; returns the supersampled buffer.
Buffer renderTile(const Model& m, const Camera& cam, int w, int h, double lineWidth) {
  Buffer buf(w * kSS, h * kSS);
  auto view = [&](const Vec3& p) { return SV{p.dot(cam.right), p.dot(cam.up), p.dot(cam.toward)}; };
  std::vector<SV> pts;
  for (const Vec3& p : m.pos) pts.push_back(view(p));
  for (const Segment& s : m.segs) pts.push_back(view(s.a)), pts.push_back(view(s.b));
  if (pts.empty()) return buf;
  SV lo = pts[0], hi = pts[0];
  for (const SV& p : pts) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double margin = 0.06 * std::min(buf.w, buf.h);
  const double ext = std::max({hi.x - lo.x, hi.y - lo.y, 1e-12});
  const double s = std::min((buf.w - 2 * margin) / std::max(hi.x - lo.x, 1e-9 * ext),
                            (buf.h - 2 * margin) / std::max(hi.y - lo.y, 1e-9 * ext));
  const double mx = 0.5 * (lo.x + hi.x), my = 0.5 * (lo.y + hi.y);
  auto screen = [&](const Vec3& p) {
    const SV v = view(p);
    return SV{0.5 * buf.w + s * (v.x - mx), 0.5 * buf.h - s * (v.y - my), v.z};
  };
  std::vector<SV> sp;
  for (const Vec3& p : m.pos) sp.push_back(screen(p));
  for (size_t f = 0; f < m.tris.size(); ++f) {
    const auto& t = m.tris[f];
    const Vec3 n = (m.pos[t[1]] - m.pos[t[0]]).cross(m.pos[t[2]] - m.pos[t[0]]);
    const double len = n.norm();
    const float shade = 0.25f + 0.75f * float(len > 0 ? std::abs(n.dot(cam.toward)) / len : 0.0);  // headlight
    drawTriangle(buf, {sp[t[0]], sp[t[1]], sp[t[2]]}, m.triColor[f], shade);
  }
  const double bias = 0.012 * std::sqrt((hi.x - lo.x) * (hi.x - lo.x) + (hi.y - lo.y) * (hi.y - lo.y) + (hi.z - lo.z) * (hi.z - lo.z));
  const Buffer surface = buf;  // lines are tested against the surface only
  const double r = 0.5 * lineWidth * kSS;
  for (const Segment& g : m.segs) {
    const SV a = screen(g.a), b = screen(g.b);
    const int n = std::max(1, int(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / 0.5)));
    for (int k = 0; k <= n; ++k) {
      const double t = double(k) / n;
      const SV p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
      if (!visible(surface, p, bias)) continue;
      RGB c;
      for (int j = 0; j < 3; ++j) c[j] = float((1 - t) * g.ca[j] + t * g.cb[j]);
      stamp(buf, p.x, p.y, r, c);
    }
  }
  for (const Vec3& d : m.dots) {
    const SV p = screen(d);
    if (visible(surface, p, bias)) stamp(buf, p.x, p.y, 1.6 * r + kSS, {0.05f, 0.05f, 0.05f});
  }
  return buf;
}

// ---------------------------------------------------------------------------- output
struct Text { int x, y, size; std::string s; bool centered = false; };

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
std::string imText(const std::string& s) {  // -annotate expands % escapes and reads @files
  std::string r = (!s.empty() && s[0] == '@') ? " " : "";
  for (char c : s) r += c == '%' ? std::string("%%") : std::string(1, c);
  return r;
}

void writeImage(const std::string& out, int w, int h, const std::vector<unsigned char>& rgb, const std::vector<Text>& texts) {
  std::string ext = fs::path(out).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const bool direct = ext == ".ppm" && texts.empty();
  const std::string ppm = direct ? out : (fs::temp_directory_path() / ("cbd_render_" + std::to_string(getpid()) + ".ppm")).string();
  {
    std::ofstream f(ppm, std::ios::binary);
    f << "P6\n" << w << " " << h << "\n255\n";
    f.write(reinterpret_cast<const char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
    if (!f) fail("cannot write '" + ppm + "'");
  }
  if (direct) return;
  std::string cmd = "convert " + shellQuote("ppm:" + ppm) + " -font DejaVu-Sans -fill black";
  for (const Text& t : texts)
    cmd += std::string(t.centered ? " -gravity North" : " -gravity NorthWest") + " -pointsize " + std::to_string(t.size) + " -annotate +" + std::to_string(t.x) + "+" + std::to_string(t.y) + " " + shellQuote(imText(t.s));
  cmd += " " + shellQuote(out) + " 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  std::error_code ec;
  fs::remove(ppm, ec);
  if (rc != 0) fail("ImageMagick 'convert' could not write '" + out + "' (is it installed? is the folder writable?)");
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parseArgs(argc, argv);
  if (fs::path(o.out).has_parent_path() && !fs::is_directory(fs::path(o.out).parent_path()))
    fail("output folder '" + fs::path(o.out).parent_path().string() + "' does not exist");
  std::vector<Model> models;
  for (size_t i = 0; i < o.meshes.size(); ++i) {
    models.push_back(loadModel(o.meshes[i], o.color, o));
    if (i < o.lines.size()) addLines(models.back(), o.lines[i], o.lineColor == "vertex");
  }
  const bool all = o.view == "all";
  const std::vector<std::string> views = all ? std::vector<std::string>{"side", "front", "top", "iso"} : std::vector<std::string>{o.view};
  const int n = static_cast<int>(models.size());
  const int cols = all ? 2 : n, rows = all ? 2 * n : 1;
  const int band = o.title.empty() ? 0 : 36;
  const int W = o.width ? o.width : cols * 640, H = o.height ? o.height : rows * 480 + band;
  const int tw = W / cols, th = (H - band) / rows;
  if (tw < 8 || th < 8) fail("--size " + std::to_string(W) + "x" + std::to_string(H) + " is too small for " + std::to_string(cols * rows) + " tiles");

  std::vector<unsigned char> img(size_t(W) * H * 3, 255);
  std::vector<Text> texts;
  if (band) texts.push_back({0, 6, 20, o.title, true});
  for (int mi = 0; mi < n; ++mi)
    for (size_t vi = 0; vi < views.size(); ++vi) {
      const int col = all ? int(vi % 2) : mi, row = all ? 2 * mi + int(vi / 2) : 0;
      const int ox = col * tw, oy = band + row * th;
      const Buffer buf = renderTile(models[mi], makeCamera(views[vi], o.up, o.flip), tw, th, o.lineWidth);
      for (int y = 0; y < th; ++y)
        for (int x = 0; x < tw; ++x)
          for (int j = 0; j < 3; ++j) {
            float acc = 0;
            for (int sy = 0; sy < kSS; ++sy)
              for (int sx = 0; sx < kSS; ++sx) acc += buf.color[size_t(y * kSS + sy) * buf.w + x * kSS + sx][j];
            img[(size_t(oy + y) * W + ox + x) * 3 + j] = static_cast<unsigned char>(std::lround(255 * std::clamp(acc / (kSS * kSS), 0.f, 1.f)));
          }
      if (o.labels) texts.push_back({ox + 6, oy + 4, 13, models[mi].name + (all || vi ? "  " + views[vi] : "")});
      if (models[mi].quality && !models[mi].tris.empty()) {  // viridis legend bar with its range
        const int bx0 = ox + tw * 3 / 10, bx1 = ox + tw * 7 / 10, by0 = oy + th - 22, by1 = oy + th - 12;
        for (int y = by0; y < by1; ++y)
          for (int x = bx0; x < bx1; ++x) {
            const RGB c = viridis(double(x - bx0) / std::max(1, bx1 - bx0 - 1));
            for (int j = 0; j < 3; ++j) img[(size_t(y) * W + x) * 3 + j] = static_cast<unsigned char>(std::lround(255 * c[j]));
          }
        const std::string lo = fmt(models[mi].qmin);
        texts.push_back({std::max(ox, bx0 - 6 - 7 * int(lo.size())), by0 - 3, 12, lo});
        texts.push_back({bx1 + 6, by0 - 3, 12, fmt(models[mi].qmax)});
      }
    }
  writeImage(o.out, W, H, img, texts);
  return 0;
}
