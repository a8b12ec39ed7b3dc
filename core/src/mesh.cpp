#include "cbd/mesh.h"
#include "cbd/files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <type_traits>
#include <sstream>
#include <string_view>
#include <system_error>
#include <unordered_map>

#include <unistd.h>

#include <vcg/complex/append.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

namespace cbd {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Vertices (with colours) and triangles read by our own readers into the vcglib mesh.
void fill(Mesh& mesh, const std::vector<Vec3>& pos, const std::vector<vcg::Color4b>& col,
          const std::vector<std::array<int, 3>>& tris) {
  auto vi = vcg::tri::Allocator<Mesh>::AddVertices(mesh, pos.size());
  for (size_t i = 0; i < pos.size(); ++i, ++vi) {
    vi->P() = vcg::Point3d(pos[i].x(), pos[i].y(), pos[i].z());
    vi->C() = col[i];
  }
  auto fi = vcg::tri::Allocator<Mesh>::AddFaces(mesh, tris.size());
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &mesh.vert[t[k]];
    ++fi;
  }
}

// A whole token as a number, NaN and infinity included (validation reports those as
// InvalidCoordinates, naming the vertex, where a parse error could only name the line).
bool parseNumber(const std::string& t, double& v) {
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return !t.empty() && end && *end == '\0';
}

// Wavefront OBJ: `v x y z [r g b]` and `f a[/t[/n]] b c ...` (1-based or negative indices);
// polygons are fan-triangulated and flagged. Returns an error text, empty on success.
std::string readObj(const std::string& path, Mesh& mesh, int& mask) {
  namespace io = vcg::tri::io;
  std::ifstream in(path);
  std::vector<Vec3> pos;
  std::vector<vcg::Color4b> col;
  bool hasColor = false;
  std::vector<std::array<int, 3>> tris;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream ls(line);
    std::string head;
    if (!(ls >> head)) continue;
    if (head == "v") {
      std::string xs, ys, zs;
      double x, y, z;
      if (!(ls >> xs >> ys >> zs) || !parseNumber(xs, x) || !parseNumber(ys, y) || !parseNumber(zs, z))
        return "line " + std::to_string(lineNo) + ": bad vertex statement";
      pos.emplace_back(x, y, z);
      double r, g, b;
      if (ls >> r >> g >> b) {
        hasColor = true;
        auto c8 = [](double c) { return static_cast<unsigned char>(std::clamp(c <= 1.0 ? c * 255.0 : c, 0.0, 255.0)); };
        col.emplace_back(c8(r), c8(g), c8(b), 255);
      } else {
        col.emplace_back(vcg::Color4b::LightGray);
      }
    } else if (head == "f") {
      std::vector<int> idx;
      std::string tok;
      while (ls >> tok) {
        const long v = std::strtol(tok.c_str(), nullptr, 10);
        const long n = static_cast<long>(pos.size());
        const long i = v > 0 ? v - 1 : n + v;
        if (v == 0 || i < 0 || i >= n)
          return "line " + std::to_string(lineNo) + ": face index " + tok + " refers to no vertex";
        idx.push_back(static_cast<int>(i));
      }
      if (idx.size() < 3) return "line " + std::to_string(lineNo) + ": face with fewer than 3 vertices";
      if (idx.size() > 3) mask |= io::Mask::IOM_BITPOLYGONAL;
      for (size_t k = 1; k + 1 < idx.size(); ++k) tris.push_back({idx[0], idx[k], idx[k + 1]});
    }
  }
  if (in.bad()) return "read error";
  fill(mesh, pos, col, tris);
  if (hasColor) mask |= io::Mask::IOM_VERTCOLOR;
  return {};
}

// OFF (also COFF, NOFF, CNOFF, STOFF...): read here rather than by vcglib 2020.09's
// ImporterOFF, which fuzzing showed indexing out of bounds on malformed files (negative
// indices, binary junk, counts it parses differently). Vertex colours (0-255 integers or 0-1
// floats) are kept. Returns an error text, empty on success.
std::string readOff(const std::string& path, Mesh& mesh, int& mask, std::vector<std::string>& warnings) {
  namespace io = vcg::tri::io;
  std::ifstream in(path);
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(in, line);) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    for (unsigned char c : line)
      if ((c < 32 && c != '\t' && c != '\r') || c > 126) return "binary data in a text format";
    std::istringstream ls(line);
    std::vector<std::string> tok;
    for (std::string t; ls >> t;) tok.push_back(t);
    if (!tok.empty()) lines.push_back(std::move(tok));
  }
  if (lines.empty()) return "empty file";
  std::string magic = lines[0][0];
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) return "no OFF header";
  const std::string flags = magic.substr(0, magic.size() - 3);
  if (flags.find('n') != std::string::npos || flags.find('4') != std::string::npos)
    return "only 3D OFF is supported (found '" + magic + "')";
  const bool hasST = flags.find("ST") != std::string::npos, hasC = flags.find('C') != std::string::npos,
             hasN = flags.find('N') != std::string::npos;
  auto integer = [](const std::string& t, long& v) {
    char* end = nullptr;
    v = std::strtol(t.c_str(), &end, 10);
    return end && *end == '\0';
  };
  size_t next = 1;
  std::vector<std::string> counts(lines[0].begin() + 1, lines[0].end());
  if (counts.empty()) {
    if (lines.size() < 2) return "no vertex/face counts";
    counts = lines[next++];
  }
  long nv = -1, nf = -1;
  if (counts.size() < 2 || !integer(counts[0], nv) || !integer(counts[1], nf) || nv < 0 || nf < 0)
    return "bad vertex/face counts";
  if (static_cast<size_t>(nv) > lines.size() || static_cast<size_t>(nf) > lines.size() ||
      lines.size() < next + static_cast<size_t>(nv) + static_cast<size_t>(nf))
    return "fewer lines than the header's " + std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces";
  std::vector<Vec3> pos(nv);
  std::vector<vcg::Color4b> col(nv, vcg::Color4b::LightGray);
  bool anyColor = false;
  for (long v = 0; v < nv; ++v) {
    const auto& t = lines[next++];
    double x, y, z;
    if (t.size() < 3 || !parseNumber(t[0], x) || !parseNumber(t[1], y) || !parseNumber(t[2], z))
      return "vertex " + std::to_string(v) + " has no three numeric coordinates";
    pos[v] = Vec3(x, y, z);
    const size_t c0 = 3 + (hasN ? 3 : 0);
    if (hasC && t.size() >= c0 + 3) {
      double c[4] = {0, 0, 0, 255};
      const size_t nc = std::min<size_t>(4, t.size() - c0 - (hasST ? 2 : 0));
      bool ok = nc >= 3;
      for (size_t k = 0; k < nc && ok; ++k) ok = parseNumber(t[c0 + k], c[k]) && std::isfinite(c[k]);
      if (ok) {
        const bool unit = c[0] <= 1.0 && c[1] <= 1.0 && c[2] <= 1.0 && (nc < 4 || c[3] <= 1.0);
        auto b = [&](double x) { return static_cast<unsigned char>(std::clamp(unit ? x * 255.0 : x, 0.0, 255.0)); };
        col[v] = vcg::Color4b(b(c[0]), b(c[1]), b(c[2]), nc == 4 ? b(c[3]) : 255);
        anyColor = true;
      }
    }
  }
  std::vector<std::array<int, 3>> tris;
  for (long f = 0; f < nf; ++f) {
    const auto& t = lines[next++];
    long k = 0;
    if (t.empty() || !integer(t[0], k) || k < 3 || t.size() < static_cast<size_t>(k) + 1)
      return "face " + std::to_string(f) + " does not list at least 3 vertices";
    std::vector<int> idx(k);
    for (long i = 0; i < k; ++i) {
      long v = -1;
      if (!integer(t[1 + i], v) || v < 0 || v >= nv)
        return "face " + std::to_string(f) + " refers to vertex " + t[1 + i] + " of " + std::to_string(nv);
      idx[i] = static_cast<int>(v);
    }
    if (k > 3) mask |= io::Mask::IOM_BITPOLYGONAL;
    for (long i = 1; i + 1 < k; ++i) tris.push_back({idx[0], idx[i], idx[i + 1]});
  }
  // Data past the last face: read as the header says (as MeshLab does), with a warning, since
  // the counts may be too low and faces left out (CGAL's prim.off lists one face more).
  if (next < lines.size())
    warnings.push_back(counted(static_cast<long long>(lines.size() - next), "line", "lines") +
                       " after the header's " + std::to_string(nv) +
                       " vertices and " + std::to_string(nf) + " faces were not read (if they are faces, correct "
                       "the counts line)");
  fill(mesh, pos, col, tris);
  mask |= io::Mask::IOM_VERTCOORD | io::Mask::IOM_FACEINDEX;
  if (anyColor) mask |= io::Mask::IOM_VERTCOLOR;
  return {};
}

// vcglib 2020.09's ImporterPLY trusts the file: a face element without a vertex_indices list,
// a list count out of range or a vertex index outside the vertex element all read or write
// out of bounds (found by fuzzing). The whole file is walked here first, header and body,
// ASCII or binary. Returns an error text, empty when the file is safe to hand to vcglib.
// vcglib 2020.09's PLY importer misreads many face index lists (ushort/short/uint counts,
// uchar/char/ushort indices, an int count with short indices...: faces lost, or wrong indices
// loaded without an error). These it reads, as MeshIO.FaceListsOfEveryIntegerTypeGiveTheSameMesh
// checks (11 x 11 type pairs, ASCII and both byte orders): uchar / char counts with short, int
// or uint indices (MeshLab writes uchar int, Blender uchar uint), and int counts with int indices.
bool vcglibReadsFaceList(const std::string& countType, const std::string& indexType) {
  const bool byteCount = countType == "uchar" || countType == "uint8" || countType == "char";
  const bool intCount = countType == "int" || countType == "int32";
  const bool intIndex = indexType == "int" || indexType == "int32";
  const bool wideIndex = intIndex || indexType == "uint" || indexType == "uint32" || indexType == "short" ||
                         indexType == "int16";
  return (byteCount && wideIndex) || (intCount && intIndex);
}

// A temporary file in TMPDIR (else /tmp), created exclusively, removed with the object.
struct TempFile {
  std::string path;
  bool write(const std::string& data) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
    std::string name = (ec ? std::string("/tmp") : dir.string()) + "/cbd-ply-XXXXXX";
    const int fd = ::mkstemp(name.data());
    if (fd < 0) return false;
    path = name;
    size_t done = 0;
    while (done < data.size()) {
      const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
      if (n <= 0) break;
      done += static_cast<size_t>(n);
    }
    return ::close(fd) == 0 && done == data.size();
  }
  ~TempFile() {
    if (!path.empty()) ::unlink(path.c_str());
  }
};

// Check a PLY file fully (vcglib trusts its counts and indices). When its face index list has
// types vcglib misreads, another list with a count wider than a byte (vcglib misreads those, or
// crashes), or is big-endian binary (vcglib misreads big-endian doubles), `transcoded` receives
// the same file, binary ones little-endian, with every list's count as uchar and the face index
// list as `uchar int`.
std::string checkPly(const std::string& path, std::string& transcoded) {
  transcoded.clear();
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return "no 'ply' magic line";
  std::vector<std::string> header{"ply"};
  bool transcode = false;
  struct Property {
    bool list = false;
    int countSize = 0, itemSize = 0;  // bytes (binary); list count and item (or scalar) type
    bool countSigned = false, itemSigned = false, itemFloat = false;
    std::string name;
    bool faceIndices = false;  // the face element's vertex index list
    std::string itemType;       // of a list
    size_t headerLine = 0;      // its line in `header`
  };
  struct Element {
    std::string name;
    long long count = 0;
    std::vector<Property> props;
  };
  auto typeSize = [](const std::string& t, bool& isSigned, bool& isFloat) {
    isSigned = t == "char" || t == "short" || t == "int" || t == "int8" || t == "int16" || t == "int32";
    isFloat = t == "float" || t == "double" || t == "float32" || t == "float64";
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
  };
  std::vector<Element> elements;
  std::string format;
  bool ended = false;
  for (int n = 0; !ended && std::getline(in, line) && n < 100000; ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    for (unsigned char c : line)
      if ((c < 32 && c != '\t') || c > 126) return "a header line holds binary data";
    header.push_back(line);
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "end_header") {
      ended = true;
    } else if (word == "format") {
      ls >> format;
    } else if (word == "element") {
      Element e;
      if (!(ls >> e.name >> e.count) || e.count < 0) return "an element line without a count";
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) return "a property before any element";
      Property pr;
      std::string type;
      ls >> type;
      bool f = false;
      if (type == "list") {
        std::string ct, it;
        ls >> ct >> it >> pr.name;
        pr.list = true;
        pr.itemType = it;
        pr.headerLine = header.size() - 1;
        pr.countSize = typeSize(ct, pr.countSigned, f);
        pr.itemSize = typeSize(it, pr.itemSigned, pr.itemFloat);
        if (!pr.countSize || f || !pr.itemSize) return "an unknown list type '" + ct + "'/'" + it + "'";
        pr.faceIndices = elements.back().name == "face" && (pr.name == "vertex_indices" || pr.name == "vertex_index");
        if (pr.faceIndices ? !pr.itemFloat && !vcglibReadsFaceList(ct, it) : ct != "uchar" && ct != "uint8")
          transcode = true;
      } else {
        ls >> pr.name;
        pr.itemSize = typeSize(type, pr.itemSigned, pr.itemFloat);
        if (!pr.itemSize) return "an unknown property type '" + type + "'";
      }
      elements.back().props.push_back(pr);
    }
  }
  if (!ended) return "no end_header line";
  const std::streampos dataStart = in.tellg();
  long long vertices = 0;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertices = e.count;
    if (e.name == "face" && e.count > 0) {
      bool hasList = false;
      for (const Property& pr : e.props) hasList = hasList || (pr.list && (pr.name == "vertex_indices" || pr.name == "vertex_index"));
      if (!hasList) return "the face element has no vertex_indices list";
    }
  }
  const bool ascii = format == "ascii";
  const bool little = format == "binary_little_endian";
  if (!ascii && !little && format != "binary_big_endian") return "an unknown format '" + format + "'";
  // The transcoded copy: the header with the lists' types replaced (and little-endian); then the
  // ASCII data as it is, or the binary data copied value by value (`copy`, little-endian) with the
  // lists' counts and the face indices re-encoded.
  if (format == "binary_big_endian") transcode = true;
  if (transcode) {
    for (Element& e : elements)
      for (Property& pr : e.props)
        if (pr.list) header[pr.headerLine] = "property list uchar " + (pr.faceIndices ? std::string("int") : pr.itemType) + " " + pr.name;
    for (std::string& h : header)
      if (h.rfind("format ", 0) == 0 && !ascii) h = "format binary_little_endian 1.0";
    for (const std::string& h : header) transcoded += h + "\n";
    if (ascii) {
      std::ostringstream rest;
      rest << in.rdbuf();
      transcoded += rest.str();
      in.clear();
      in.seekg(dataStart);
    }
  }
  bool copy = transcode && !ascii;
  auto put = [&](std::int64_t value, int size) {  // little-endian
    for (int k = 0; k < size; ++k) transcoded += static_cast<char>(static_cast<unsigned char>(value >> (8 * k)));
  };
  // Read one value of a property's type as a double (integers exact below 2^53).
  auto readValue = [&](int size, bool isSigned, bool isFloat, double& v) -> bool {
    if (ascii) {
      std::string t;
      if (!(in >> t) || !parseNumber(t, v)) return false;
      return std::isfinite(v) || isFloat;  // NaN / infinity: in float properties only
    }
    unsigned char b[8];
    if (!in.read(reinterpret_cast<char*>(b), size)) return false;
    if (!little) std::reverse(b, b + size);
    if (copy) transcoded.append(reinterpret_cast<const char*>(b), size);
    if (isFloat) {
      if (size == 4) { float x; std::memcpy(&x, b, 4); v = x; } else { double x; std::memcpy(&x, b, 8); v = x; }
    } else {
      uint64_t u = 0;
      for (int i = size - 1; i >= 0; --i) u = (u << 8) | b[i];
      if (isSigned && (b[size - 1] & 0x80)) v = static_cast<double>(static_cast<int64_t>(u | (~uint64_t(0) << (8 * size))));
      else v = static_cast<double>(u);
    }
    return std::isfinite(v) || isFloat;
  };
  in.seekg(0, std::ios::end);
  const long long fileSize = static_cast<long long>(in.tellg());
  in.seekg(dataStart);
  for (const Element& e : elements) {
    if (e.props.empty()) continue;  // nothing to read, whatever the count
    // Every instance takes at least one byte (binary) or one character (ASCII).
    if (e.count > fileSize) return "element '" + e.name + "' claims more items than the file has bytes";
    for (long long i = 0; i < e.count; ++i)
      for (const Property& pr : e.props) {
        double v = 0;
        if (!pr.list) {
          if (!readValue(pr.itemSize, pr.itemSigned, pr.itemFloat, v)) return "the file ends inside element '" + e.name + "'";
          continue;
        }
        double count = 0;
        const bool recode = transcode && !ascii;  // the count as uchar, face indices as int
        copy = false;
        if (!readValue(pr.countSize, pr.countSigned, false, count)) return "the file ends inside element '" + e.name + "'";
        if (count < 0 || count != std::floor(count) || count > (transcode ? 255 : 256))  // a uchar count in a copy
          return "a list of " + std::to_string(count) + " items";
        if (recode) put(static_cast<std::int64_t>(count), 1);
        copy = recode && !pr.faceIndices;
        if (pr.faceIndices && count < 3) return "face " + std::to_string(i) + " has fewer than 3 vertices";
        for (int k = 0; k < static_cast<int>(count); ++k) {
          if (!readValue(pr.itemSize, pr.itemSigned, pr.itemFloat, v)) return "the file ends inside element '" + e.name + "'";
          if (pr.faceIndices && (v < 0 || v >= static_cast<double>(vertices) || v != std::floor(v)))
            return "face " + std::to_string(i) + " refers to vertex " + std::to_string(v) + " of " +
                   std::to_string(vertices);
          if (recode && pr.faceIndices) put(static_cast<std::int64_t>(v), 4);
        }
        copy = recode;
      }
  }
  return {};
}

// Welds an STL's triangle soup: corners with the same coordinates (-0 as +0, every NaN as one
// NaN) become one vertex, the first of them in file order, so vertex i is the file's i-th
// distinct corner (as vcglib's RemoveDuplicateVertex left it for finite coordinates). Corners at
// a NaN point weld too, where vcglib's sort by position is undefined behaviour (its comparator
// orders nothing against NaN) and left them apart: validation then counts a bad vertex once,
// not once per facet using it. Facets left with a repeated corner (a sliver whose two corners
// coincide) are dropped, as RemoveDuplicateVertex did.
void weldStlCorners(Mesh& mesh) {
  struct Key {
    std::uint64_t b[3];
    bool operator==(const Key& o) const { return b[0] == o.b[0] && b[1] == o.b[1] && b[2] == o.b[2]; }
  };
  struct KeyHash {  // the key's 24 bytes, hashed as the standard library hashes a string
    size_t operator()(const Key& k) const {
      return std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(k.b), sizeof k.b));
    }
  };
  std::unordered_map<Key, MeshVertex*, KeyHash> first;
  first.reserve(mesh.vert.size());
  std::vector<MeshVertex*> to(mesh.vert.size(), nullptr);
  for (size_t i = 0; i < mesh.vert.size(); ++i) {
    MeshVertex& v = mesh.vert[i];
    if (v.IsD()) continue;
    Key k;
    for (int c = 0; c < 3; ++c) {
      double x = static_cast<double>(v.cP()[c]) + 0.0;  // -0 + 0 = +0
      if (std::isnan(x)) x = std::numeric_limits<double>::quiet_NaN();
      std::memcpy(&k.b[c], &x, sizeof x);
    }
    const auto [it, inserted] = first.emplace(k, &v);
    to[i] = it->second;
    if (!inserted) vcg::tri::Allocator<Mesh>::DeleteVertex(mesh, v);
  }
  for (auto& f : mesh.face) {
    if (f.IsD()) continue;
    for (int k = 0; k < 3; ++k) f.V(k) = to[f.V(k) - &mesh.vert.front()];
    if (f.V(0) == f.V(1) || f.V(1) == f.V(2) || f.V(2) == f.V(0)) vcg::tri::Allocator<Mesh>::DeleteFace(mesh, f);
  }
  vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
}

// The facets of an ASCII STL after its 'solid' word: `vertex x y z` triples, three per facet.
std::string readAsciiStl(std::istream& in, Mesh& mesh) {
  std::vector<Vec3> corners;
  std::string word;
  while (in >> word) {
    if (word != "vertex") continue;
    std::string xs, ys, zs;
    if (!(in >> xs >> ys >> zs)) return "a vertex line without three coordinates";
    double x, y, z;
    if (!parseNumber(xs, x) || !parseNumber(ys, y) || !parseNumber(zs, z)) return "a vertex with a non-numeric coordinate";
    corners.emplace_back(x, y, z);
  }
  if (corners.empty() || corners.size() % 3 != 0) return "the facets do not have three vertices each";
  auto vi = vcg::tri::Allocator<Mesh>::AddVertices(mesh, corners.size());
  auto fi = vcg::tri::Allocator<Mesh>::AddFaces(mesh, corners.size() / 3);
  for (size_t i = 0; i < corners.size(); ++i, ++vi) {
    vi->P() = vcg::Point3d(corners[i].x(), corners[i].y(), corners[i].z());
    fi->V(static_cast<int>(i % 3)) = &*vi;
    if (i % 3 == 2) ++fi;
  }
  return {};
}

}  // namespace

namespace {
LoadResult loadMeshUnchecked(const std::string& path, Mesh& mesh);
}  // namespace

LoadResult loadMesh(const std::string& path, Mesh& mesh) {
  // A malformed file must never take the caller down: allocation failures inside the readers
  // (absurd counts) become MalformedMesh too.
  try {
    return loadMeshUnchecked(path, mesh);
  } catch (const std::exception& e) {
    mesh.Clear();
    LoadResult r;
    r.status = Status::error(ErrorCode::MalformedMesh,
                             "cannot parse mesh '" + path + "': " + e.what() + " (the file is not a valid mesh file)");
    return r;
  }
}

namespace {
LoadResult loadMeshUnchecked(const std::string& path, Mesh& mesh) {
  LoadResult r;
  mesh.Clear();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    r.status = Status::error(ErrorCode::FileNotFound, "cannot read mesh '" + path + "': " + notAFileReason(path));
    return r;
  }
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) {
      r.status = Status::error(ErrorCode::FileNotFound,
                               "cannot open mesh '" + path + "' for reading (check permissions)");
      return r;
    }
    if (probe.peek() == std::ifstream::traits_type::eof()) {
      r.status = Status::error(ErrorCode::MalformedMesh, "mesh '" + path + "' is an empty file");
      return r;
    }
  }

  const std::string ext = lowerExtension(path);
  int mask = 0;
  int err = 0;
  std::string what;
  namespace io = vcg::tri::io;
  if (ext == ".ply") {
    std::string transcoded;
    what = checkPly(path, transcoded);
    if (what.empty() && transcoded.empty()) {
      err = io::ImporterPLY<Mesh>::Open(mesh, path.c_str(), mask);
    } else if (what.empty()) {
      // The copy with a face list vcglib reads, through a temporary file (its importer reads
      // files only), created exclusively (mkstemp) and removed whatever happens.
      TempFile tmp;
      if (!tmp.write(transcoded)) {
        r.status = Status::error(ErrorCode::OutputError,
                                 "cannot write a temporary copy of '" + path + "' with a face list vcglib reads" +
                                     (tmp.path.empty() ? std::string() : " ('" + tmp.path + "')") +
                                     ": check that TMPDIR (or /tmp) is a writable folder");
        return r;
      }
      std::string().swap(transcoded);  // on disk now: not a second copy in memory while importing
      err = io::ImporterPLY<Mesh>::Open(mesh, tmp.path.c_str(), mask);
    }
    if (err != 0 && io::ImporterPLY<Mesh>::ErrorCritical(err)) what = io::ImporterPLY<Mesh>::ErrorMsg(err);
  } else if (ext == ".off") {
    what = readOff(path, mesh, mask, r.warnings);
    for (std::string& w : r.warnings) w = "'" + path + "': " + w;
  } else if (ext == ".obj") {
    // vcglib 2020.09's ImporterOBJ drops every face that uses the file's first vertex
    // (SplitToken makes indices 0-based, then GoodObjIndex rejects index 0), so OBJ is read here.
    what = readObj(path, mesh, mask);
  } else if (ext == ".stl") {
    // vcglib's binary/ASCII guess reads 4 bytes past what it read from the file, its binary
    // reader trusts the face count and its ASCII reader can loop forever (all found by fuzzing):
    // binary through vcglib only when the size matches the count exactly, ASCII read here.
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    const auto size = static_cast<long long>(f.tellg());
    f.seekg(80);
    uint32_t count = 0;
    const bool haveCount = size >= 84 && f.read(reinterpret_cast<char*>(&count), 4);
    if (haveCount && size == 84 + 50LL * count) {
      err = io::ImporterSTL<Mesh>::OpenBinary(mesh, path.c_str(), mask);
    } else {
      f.seekg(0);
      std::string word;
      f >> word;
      if (word != "solid") {
        what = "neither a binary STL of the right size nor an ASCII STL starting with 'solid'";
      } else {
        // ASCII STL is read here: vcglib's OpenAscii loops forever on some malformed files.
        what = readAsciiStl(f, mesh);
        mask |= io::Mask::IOM_VERTCOORD | io::Mask::IOM_FACEINDEX;
      }
    }
    if (err != 0) what = io::ImporterSTL<Mesh>::ErrorMsg(err);
  } else {
    r.status = Status::error(ErrorCode::UnsupportedFormat,
                             "mesh '" + path + "' has extension '" + ext +
                                 "': supported formats are .ply, .off, .obj and .stl");
    return r;
  }
  if (!what.empty()) {
    mesh.Clear();
    r.status = Status::error(ErrorCode::MalformedMesh,
                             "cannot parse mesh '" + path + "': " + what +
                                 " (the file is truncated or not a valid " + ext.substr(1) + " file)");
    return r;
  }
  // Every face must refer to vertices of this mesh: vcglib's importers do not all check
  // (found by fuzzing the OFF reader with malformed vertex lines).
  if (what.empty() && !mesh.vert.empty()) {
    const MeshVertex* first = &mesh.vert.front();
    const MeshVertex* last = &mesh.vert.back();
    for (const auto& f : mesh.face)
      for (int k = 0; k < 3 && what.empty(); ++k)
        if (f.cV(k) == nullptr || f.cV(k) < first || f.cV(k) > last) what = "a face refers to a vertex that does not exist";
  } else if (what.empty() && !mesh.face.empty()) {
    what = "faces without vertices";
  }
  if (!what.empty()) {
    mesh.Clear();
    r.status = Status::error(ErrorCode::MalformedMesh,
                             "cannot parse mesh '" + path + "': " + what + " (the file is truncated or not a valid " +
                                 ext.substr(1) + " file)");
    return r;
  }
  if (ext == ".stl") {
    // STL stores triangle soups: merge coincident vertices so the surface has connectivity.
    weldStlCorners(mesh);
  }
  r.hadPolygons = (mask & io::Mask::IOM_BITPOLYGONAL) != 0;
  r.hasVertexColor = (mask & io::Mask::IOM_VERTCOLOR) != 0;
  r.hasVertexQuality = (mask & io::Mask::IOM_VERTQUALITY) != 0;
  r.hasVertexTexCoord = (mask & io::Mask::IOM_VERTTEXCOORD) != 0;
  if (mesh.VN() == 0 || mesh.FN() == 0) {
    r.status = Status::error(ErrorCode::EmptyMesh,
                             "mesh '" + path + "' has " + counted(mesh.VN(), "vertex", "vertices") + " and " +
                                 counted(mesh.FN(), "face", "faces") + ": a closed triangle surface is needed");
    return r;
  }
  return r;
}

}  // namespace

Status savePly(const std::string& path, const Mesh& mesh, const SavePlyOptions& options) {
  namespace io = vcg::tri::io;
  int mask = 0;
  if (options.vertexColor) mask |= io::Mask::IOM_VERTCOLOR;
  if (options.vertexQuality) mask |= io::Mask::IOM_VERTQUALITY;
  if (options.faceColor) mask |= io::Mask::IOM_FACECOLOR;
  if (options.faceQuality) mask |= io::Mask::IOM_FACEQUALITY;
  if (options.edges) mask |= io::Mask::IOM_EDGEINDEX;

  const fs::path target(path);
  std::error_code ec;
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) {
    return Status::error(ErrorCode::OutputError, "cannot write '" + path + "': folder '" +
                                                     dir.string() + "' does not exist");
  }
  const fs::path tmp = writeTarget(path);
  int err = 0;
  if (options.vertexTexCoord) {
    // vcglib 2020.09 declares per-vertex texture_u/texture_v as float but writes the mesh's
    // scalar (double) in binary files, which no reader can parse: they go out as float
    // attributes of a copy instead, under the names its importer (and MeshLab) reads.
    Mesh copy;
    vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, const_cast<Mesh&>(mesh));
    auto u = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<float>(copy, std::string("texture_u"));
    auto v = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<float>(copy, std::string("texture_v"));
    for (auto& vert : copy.vert) u[vert] = static_cast<float>(vert.T().U()), v[vert] = static_cast<float>(vert.T().V());
    io::PlyInfo pi;
    pi.mask = mask;
    pi.AddPerVertexFloatAttribute("texture_u");
    pi.AddPerVertexFloatAttribute("texture_v");
    err = io::ExporterPLY<Mesh>::Save(copy, tmp.string().c_str(), options.binary, pi);
    // vcglib 2020.09's PlyInfo strdup()s the property names and never frees them (later vcglibs,
    // which the MeshLab 2025.07 plugin's core is built with, keep them as std::string).
    auto freeName = [](auto& d) {
      if constexpr (std::is_pointer_v<std::decay_t<decltype(d.propname)>>) std::free(const_cast<char*>(d.propname));
    };
    for (auto& d : pi.VertDescriptorVec) freeName(d);
    vcg::tri::Allocator<Mesh>::DeletePerVertexAttribute(copy, u);
    vcg::tri::Allocator<Mesh>::DeletePerVertexAttribute(copy, v);
  } else {
    // vcglib's exporter takes a non-const mesh although it does not modify it.
    err = io::ExporterPLY<Mesh>::Save(const_cast<Mesh&>(mesh), tmp.string().c_str(), mask, options.binary);
  }
  if (err != 0) {
    if (tmp != target) fs::remove(tmp, ec);
    return Status::error(ErrorCode::OutputError,
                         "cannot write '" + path + "': " + io::ExporterPLY<Mesh>::ErrorMsg(err) +
                             " (check that the folder is writable)");
  }
  if (tmp == target) return Status::success();  // a device, written in place
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return Status::error(ErrorCode::OutputError, "cannot move the finished file into '" + path + "'");
  }
  return Status::success();
}

IndexedMesh toIndexed(const Mesh& mesh) {
  IndexedMesh out;
  std::vector<int> remap(mesh.vert.size(), -1);
  out.positions.reserve(mesh.VN());
  for (size_t i = 0; i < mesh.vert.size(); ++i) {
    const auto& v = mesh.vert[i];
    if (v.IsD()) continue;
    remap[i] = static_cast<int>(out.positions.size());
    out.positions.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
  }
  out.faces.reserve(mesh.FN());
  for (const auto& f : mesh.face) {
    if (f.IsD()) continue;
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = remap[vcg::tri::Index(mesh, f.cV(k))];
    out.faces.push_back(t);
  }
  return out;
}

void fromIndexed(const IndexedMesh& in, Mesh& out) {
  out.Clear();
  auto vi = vcg::tri::Allocator<Mesh>::AddVertices(out, in.positions.size());
  for (const Vec3& p : in.positions) {
    vi->P() = vcg::Point3d(p.x(), p.y(), p.z());
    ++vi;
  }
  auto fi = vcg::tri::Allocator<Mesh>::AddFaces(out, in.faces.size());
  for (const auto& t : in.faces) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &out.vert[t[k]];
    ++fi;
  }
}

double boundingBoxDiagonal(const IndexedMesh& mesh) {
  if (mesh.positions.empty()) return 0.0;
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

double surfaceArea(const IndexedMesh& m) {
  double a = 0;
  for (const auto& f : m.faces)
    a += 0.5 * (m.positions[f[1]] - m.positions[f[0]]).cross(m.positions[f[2]] - m.positions[f[0]]).norm();
  return a;
}

int closedEulerCharacteristic(const IndexedMesh& m) {
  std::vector<char> used(m.vertexCount(), 0);
  for (const auto& f : m.faces)
    for (int v : f) used[v] = 1;
  const int referenced = static_cast<int>(std::count(used.begin(), used.end(), 1));
  return referenced - m.faceCount() / 2;
}

}  // namespace cbd
