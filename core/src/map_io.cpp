#include "cbd/map_io.h"
#include "cbd/files.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <Eigen/Geometry>

#include <vcg/complex/append.h>

namespace cbd {

std::array<unsigned char, 3> stretchColor(double s) {
  if (std::isnan(s)) return {128, 128, 128};
  const double t = std::clamp(std::log2(std::max(s, 1e-9)), -1.0, 1.0);
  const double r = t < 0 ? 1.0 + t : 1.0, g = 1.0 - std::abs(t), b = t > 0 ? 1.0 - t : 1.0;
  auto c = [](double x) { return static_cast<unsigned char>(std::lround(255 * x)); };
  return {c(r), c(g), c(b)};
}

VertexValues interpolateAtPoints(const std::vector<std::array<int, 3>>& faces, const std::vector<FacePoint>& points,
                                 const VertexValues& values, const Eigen::Vector4d& outside) {
  VertexValues out(points.size(), outside);
  for (size_t v = 0; v < points.size(); ++v) {
    const FacePoint& p = points[v];
    if (p.face < 0 || p.face >= static_cast<int>(faces.size())) continue;
    const auto& f = faces[static_cast<size_t>(p.face)];
    out[v] = p.bary[0] * values[f[0]] + p.bary[1] * values[f[1]] + p.bary[2] * values[f[2]];
  }
  return out;
}

unsigned char colorByte(double value) {
  return static_cast<unsigned char>(std::clamp(std::lround(value), 0L, 255L));
}

void buildMappedMesh(const Mesh& from, const std::vector<Vec3>& image, const std::vector<FacePoint>& points,
                     const Mesh& onto, const TransferOptions& transfer, const std::vector<double>& faceStretch,
                     Mesh& out) {
  // vcglib 2020.09's MeshCopy takes a non-const source although it only reads it.
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(out, const_cast<Mesh&>(from));
  for (size_t v = 0; v < out.vert.size(); ++v) out.vert[v].P() = vcg::Point3d(image[v].x(), image[v].y(), image[v].z());
  // The attributes of `onto`, blended at the images (faces and vertices of `onto` in file order,
  // as FacePoint counts them).
  std::vector<std::array<int, 3>> faces(onto.face.size());
  for (size_t f = 0; f < onto.face.size(); ++f)
    for (int k = 0; k < 3; ++k) faces[f][k] = static_cast<int>(vcg::tri::Index(onto, onto.face[f].cV(k)));
  auto transferred = [&](auto value) {
    VertexValues at(onto.vert.size());
    for (size_t v = 0; v < onto.vert.size(); ++v) at[v] = value(onto.vert[v]);
    return interpolateAtPoints(faces, points, at, Eigen::Vector4d::Constant(std::nan("")));
  };
  auto known = [](const Eigen::Vector4d& x) { return !std::isnan(x[0]); };
  if (transfer.vertexColor) {
    const VertexValues c = transferred([](const auto& v) {
      return Eigen::Vector4d(v.cC()[0], v.cC()[1], v.cC()[2], v.cC()[3]);
    });
    for (size_t v = 0; v < out.vert.size(); ++v)
      if (known(c[v])) out.vert[v].C() = vcg::Color4b(colorByte(c[v][0]), colorByte(c[v][1]), colorByte(c[v][2]), colorByte(c[v][3]));
  }
  if (transfer.vertexQuality) {
    const VertexValues q = transferred([](const auto& v) { return Eigen::Vector4d(v.cQ(), 0, 0, 0); });
    for (size_t v = 0; v < out.vert.size(); ++v)
      if (known(q[v])) out.vert[v].Q() = q[v][0];
  }
  if (transfer.vertexTexCoord) {
    const VertexValues t = transferred([](const auto& v) { return Eigen::Vector4d(v.cT().U(), v.cT().V(), 0, 0); });
    for (size_t v = 0; v < out.vert.size(); ++v) {
      if (!known(t[v])) continue;
      out.vert[v].T().U() = t[v][0];
      out.vert[v].T().V() = t[v][1];
      out.vert[v].T().N() = onto.face[points[v].face].cV(0)->cT().N();
    }
  }
  for (size_t f = 0; f < out.face.size() && f < faceStretch.size(); ++f) {
    out.face[f].Q() = faceStretch[f];
    const auto c = stretchColor(faceStretch[f]);
    out.face[f].C() = vcg::Color4b(c[0], c[1], c[2], 255);
  }
}

Status writeCorrespondence(const std::string& path, const std::vector<FacePoint>& points, const std::vector<Vec3>& image) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path tmp = writeTarget(path);
  {
    std::ofstream out(tmp);
    if (!out) return Status::error(ErrorCode::OutputError, "cannot write '" + path + "'");
    out << "# cbd correspondence: source_vertex target_face b0 b1 b2 x y z (0-based, input order)\n";
    char buf[256];
    for (size_t v = 0; v < points.size(); ++v) {
      std::snprintf(buf, sizeof buf, "%zu %d %.17g %.17g %.17g %.17g %.17g %.17g\n", v, points[v].face, points[v].bary[0],
                    points[v].bary[1], points[v].bary[2], image[v].x(), image[v].y(), image[v].z());
      out << buf;
    }
    if (!out.good()) return Status::error(ErrorCode::OutputError, "cannot write '" + path + "'");
  }
  if (tmp == target) return Status::success();  // a device, written in place
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) return Status::error(ErrorCode::OutputError, "cannot move the finished file into '" + path + "'");
  return Status::success();
}

std::string morphFileName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "%s%03d.ply", kMorphPrefix, k);
  return name;
}

std::vector<std::string> staleMorphFrames(const std::string& dir, int count) {
  std::vector<std::string> frames;
  for (int k = std::max(count, 0);; ++k) {
    const std::filesystem::path frame = std::filesystem::path(dir) / morphFileName(k);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(frame, ec)) break;
    frames.push_back(frame.string());
  }
  return frames;
}

Status writeMorph(const std::string& dir, const Mesh& from, const std::vector<Vec3>& image,
                  const std::vector<int>& anchors, int count, int* staleRemoved) {
  if (staleRemoved) *staleRemoved = 0;
  if (count < 2) return Status::error(ErrorCode::InvalidArgument, "a morph needs at least 2 frames");
  // Best similarity taking the source anchors onto their images.
  Eigen::Matrix3Xd src(3, anchors.size()), dst(3, anchors.size());
  for (size_t k = 0; k < anchors.size(); ++k) {
    const auto& p = from.vert[anchors[k]].cP();
    src.col(k) = Vec3(p[0], p[1], p[2]);
    dst.col(k) = image[anchors[k]];
  }
  const Eigen::Matrix4d fit = anchors.size() >= 3 ? Eigen::umeyama(src, dst, true) : Eigen::Matrix4d::Identity();
  Mesh m;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(m, const_cast<Mesh&>(from));
  SavePlyOptions opt;
  for (int k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) / (count - 1);
    for (size_t v = 0; v < m.vert.size(); ++v) {
      const auto& p = from.vert[v].cP();
      const Vec3 aligned = (fit * Eigen::Vector4d(p[0], p[1], p[2], 1.0)).head<3>();
      const Vec3 q = (1.0 - t) * aligned + t * image[v];
      m.vert[v].P() = vcg::Point3d(q.x(), q.y(), q.z());
    }
    if (Status s = savePly((std::filesystem::path(dir) / morphFileName(k)).string(), m, opt); !s) return s;
  }
  // The rest of a longer sequence written there before: a mixed sequence would be misread.
  for (const std::string& stale : staleMorphFrames(dir, count)) {
    std::error_code ec;
    if (!std::filesystem::remove(stale, ec))
      return Status::error(ErrorCode::OutputError, "cannot remove '" + stale +
                                                       "', a frame of an earlier, longer morph sequence");
    if (staleRemoved) ++*staleRemoved;
  }
  return Status::success();
}

}  // namespace cbd
