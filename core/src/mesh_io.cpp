#include "cbd/mesh.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_off.h>
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
      double x, y, z;
      if (!(ls >> x >> y >> z)) return "line " + std::to_string(lineNo) + ": bad vertex statement";
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
  if (hasColor) mask |= io::Mask::IOM_VERTCOLOR;
  return {};
}

}  // namespace

LoadResult loadMesh(const std::string& path, Mesh& mesh) {
  LoadResult r;
  mesh.Clear();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    r.status = Status::error(ErrorCode::FileNotFound, "cannot read mesh '" + path +
                                                          "': no such file (check the path)");
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
    err = io::ImporterPLY<Mesh>::Open(mesh, path.c_str(), mask);
    if (err != 0 && io::ImporterPLY<Mesh>::ErrorCritical(err)) what = io::ImporterPLY<Mesh>::ErrorMsg(err);
  } else if (ext == ".off") {
    err = io::ImporterOFF<Mesh>::Open(mesh, path.c_str(), mask);
    if (err != 0) what = io::ImporterOFF<Mesh>::ErrorMsg(err);
  } else if (ext == ".obj") {
    // vcglib 2020.09's ImporterOBJ drops every face that uses the file's first vertex
    // (SplitToken makes indices 0-based, then GoodObjIndex rejects index 0), so OBJ is read here.
    what = readObj(path, mesh, mask);
  } else if (ext == ".stl") {
    err = io::ImporterSTL<Mesh>::Open(mesh, path.c_str(), mask);
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
  if (ext == ".stl") {
    // STL stores triangle soups: merge coincident vertices so the surface has connectivity.
    vcg::tri::Clean<Mesh>::RemoveDuplicateVertex(mesh);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  }
  r.hadPolygons = (mask & io::Mask::IOM_BITPOLYGONAL) != 0;
  r.hasVertexColor = (mask & io::Mask::IOM_VERTCOLOR) != 0;
  r.hasVertexQuality = (mask & io::Mask::IOM_VERTQUALITY) != 0;
  r.hasVertexTexCoord = (mask & io::Mask::IOM_VERTTEXCOORD) != 0;
  if (mesh.VN() == 0 || mesh.FN() == 0) {
    r.status = Status::error(ErrorCode::EmptyMesh,
                             "mesh '" + path + "' has " + std::to_string(mesh.VN()) + " vertices and " +
                                 std::to_string(mesh.FN()) + " faces: a closed triangle surface is needed");
    return r;
  }
  return r;
}

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
  const fs::path tmp = dir / ("." + target.filename().string() + ".tmp");
  // vcglib's exporter takes a non-const mesh although it does not modify it.
  int err = io::ExporterPLY<Mesh>::Save(const_cast<Mesh&>(mesh), tmp.string().c_str(), mask,
                                        options.binary);
  if (err != 0) {
    fs::remove(tmp, ec);
    return Status::error(ErrorCode::OutputError,
                         "cannot write '" + path + "': " + io::ExporterPLY<Mesh>::ErrorMsg(err) +
                             " (check that the folder is writable)");
  }
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

}  // namespace cbd
