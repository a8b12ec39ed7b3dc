// Outputs of a cross-parameterization (map_io.h): the stretch colour scale, the mapped mesh (the
// source's connectivity at the image, attributes of the other surface interpolated there), the
// correspondence text round trip, and the morph sequence (anchor-fitted source to image, stale
// frames of a longer sequence removed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <Eigen/Geometry>

#include "cbd/anchor_sampling.h"
#include "cbd/map_io.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / ("cbd_test_map_io_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::array<unsigned char, 3> rgb(unsigned char r, unsigned char g, unsigned char b) { return {r, g, b}; }

Vec3 at(const Mesh& m, int v) {
  const auto& p = m.vert[v].cP();
  return Vec3(p[0], p[1], p[2]);
}

std::vector<Vec3> positions(const Mesh& m) {
  std::vector<Vec3> out;
  for (int v = 0; v < m.VN(); ++v) out.push_back(at(m, v));
  return out;
}

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// Functions of position the attributes of the target are sampled from: linear, so that
/// barycentric interpolation inside a face gives their value at the interpolated point exactly.
double qualityAt(const Vec3& p) { return 2 * p.x() - p.y() + 3 * p.z() + 0.5; }
Vec2 texAt(const Vec3& p) { return Vec2(p.x() + p.y(), p.z() - 0.5 * p.x()); }

}  // namespace

TEST(MapIO, StretchColourRunsFromBlueThroughWhiteToRed) {
  EXPECT_EQ(stretchColor(1.0), rgb(255, 255, 255));
  EXPECT_EQ(stretchColor(2.0), rgb(255, 0, 0));
  EXPECT_EQ(stretchColor(0.5), rgb(0, 0, 255));
  // Clamped beyond a factor of two either way, and for what is not a stretch at all.
  for (double s : {3.0, 100.0, std::numeric_limits<double>::infinity()}) EXPECT_EQ(stretchColor(s), rgb(255, 0, 0)) << s;
  for (double s : {0.25, 1e-12, 0.0, -1.0}) EXPECT_EQ(stretchColor(s), rgb(0, 0, 255)) << s;
  EXPECT_EQ(stretchColor(std::numeric_limits<double>::quiet_NaN()), rgb(128, 128, 128));
  // A log scale: 2^(1/4) is a quarter of the way to red, 2^(-1/4) a quarter of the way to blue
  // (255 * 3/4 = 191.25).
  EXPECT_EQ(stretchColor(std::pow(2.0, 0.25)), rgb(255, 191, 191));
  EXPECT_EQ(stretchColor(std::pow(2.0, -0.25)), rgb(191, 191, 255));
  // Monotone: redder as the stretch grows, bluer as it shrinks.
  for (double s = 1.0; s < 2.0; s *= 1.05) {
    const auto a = stretchColor(s), b = stretchColor(s * 1.05);
    EXPECT_EQ(b[0], 255);
    EXPECT_LE(b[1], a[1]);
    EXPECT_LE(b[2], a[2]);
    const auto c = stretchColor(1 / s), d = stretchColor(1 / (s * 1.05));
    EXPECT_EQ(d[2], 255);
    EXPECT_LE(d[0], c[0]);
    EXPECT_LE(d[1], c[1]);
  }
}

TEST(MapIO, TheMappedMeshIsTheSourceAtItsImageWithTheTargetsAttributes) {
  Mesh from, onto;
  fromIndexed(fx::icosphere(2), from);
  IndexedMesh target = fx::icosphere(3);
  for (auto& p : target.positions) p = Vec3(1.5 * p.x(), p.y(), 0.7 * p.z());
  fromIndexed(target, onto);
  for (int v = 0; v < onto.VN(); ++v) {
    const Vec3 p = at(onto, v);
    onto.vert[v].Q() = qualityAt(p);
    onto.vert[v].T().U() = texAt(p).x();
    onto.vert[v].T().V() = texAt(p).y();
    onto.vert[v].T().N() = 3;
    onto.vert[v].C() = vcg::Color4b(static_cast<unsigned char>(v % 256), static_cast<unsigned char>(3 * v % 256),
                                    static_cast<unsigned char>(255 - v % 256), 200);
  }
  for (int v = 0; v < from.VN(); ++v) from.vert[v].Q() = -7.0, from.vert[v].C() = vcg::Color4b(1, 2, 3, 4);
  // Every source vertex somewhere inside some target face; the last on no face (unreferenced).
  std::vector<FacePoint> points(from.VN());
  std::vector<Vec3> image(from.VN());
  for (int v = 0; v < from.VN(); ++v) {
    const double a = 0.1 + 0.8 * std::abs(std::sin(1.3 * v)), b = (1 - a) * std::abs(std::cos(0.7 * v));
    points[v] = {(7 * v) % onto.FN(), Vec3(a, b, 1 - a - b)};
    image[v] = fx::pointOn(target, points[v]);
  }
  const int loose = from.VN() - 1;
  points[loose] = FacePoint{};
  image[loose] = Vec3(9, 9, 9);
  std::vector<double> stretch(from.FN());
  for (int f = 0; f < from.FN(); ++f) stretch[f] = 0.4 + 0.02 * f;
  const std::vector<Vec3> before = positions(from);

  Mesh out;
  buildMappedMesh(from, image, points, onto, TransferOptions{true, true, true}, stretch, out);
  ASSERT_EQ(out.VN(), from.VN());
  ASSERT_EQ(out.FN(), from.FN());
  for (int f = 0; f < out.FN(); ++f) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(out.face[f].cV(k) - &out.vert[0], from.face[f].cV(k) - &from.vert[0]);
    EXPECT_EQ(out.face[f].cQ(), stretch[f]);
    const auto c = stretchColor(stretch[f]);
    EXPECT_EQ(out.face[f].cC(), vcg::Color4b(c[0], c[1], c[2], 255)) << "face " << f;
  }
  for (int v = 0; v < out.VN(); ++v) {
    EXPECT_EQ(at(out, v), image[v]) << "vertex " << v;
    if (v == loose) {
      EXPECT_EQ(out.vert[v].cQ(), -7.0) << "a vertex on no face keeps its own attributes";
      EXPECT_EQ(out.vert[v].cC(), vcg::Color4b(1, 2, 3, 4));
      continue;
    }
    EXPECT_NEAR(out.vert[v].cQ(), qualityAt(image[v]), 1e-12) << "vertex " << v;
    EXPECT_NEAR(out.vert[v].cT().U(), texAt(image[v]).x(), 1e-12) << "vertex " << v;
    EXPECT_NEAR(out.vert[v].cT().V(), texAt(image[v]).y(), 1e-12) << "vertex " << v;
    EXPECT_EQ(out.vert[v].cT().N(), 3);
    const auto& t = onto.face[points[v].face];
    for (int i = 0; i < 4; ++i) {
      double c = 0;
      for (int k = 0; k < 3; ++k) c += points[v].bary[k] * t.cV(k)->cC()[i];
      EXPECT_EQ(out.vert[v].cC()[i], std::lround(c)) << "vertex " << v << ", channel " << i;
    }
  }
  EXPECT_EQ(positions(from), before) << "the source mesh was changed";
  // Nothing asked for, nothing transferred: the source's own attributes stay.
  Mesh plain;
  buildMappedMesh(from, image, points, onto, TransferOptions{}, stretch, plain);
  for (int v = 0; v < plain.VN(); ++v) {
    EXPECT_EQ(at(plain, v), image[v]);
    EXPECT_EQ(plain.vert[v].cQ(), -7.0);
    EXPECT_EQ(plain.vert[v].cC(), vcg::Color4b(1, 2, 3, 4));
  }
}

TEST(MapIO, TheCorrespondenceFileRoundTripsEveryDigit) {
  std::vector<FacePoint> points;
  std::vector<Vec3> image;
  for (int v = 0; v < 50; ++v) {
    const double a = 1.0 / (3 + v), b = M_PI / (10 + v);
    points.push_back({v * 3, Vec3(a, b, 1 - a - b)});
    image.push_back(Vec3(std::exp(0.1 * v), -1.0 / 7.0 * v, 1e-300 * v));
  }
  points[17] = FacePoint{};  // unreferenced: face -1, zeros, its own position
  image[17] = Vec3(0.1, 0.2, 0.3);
  TempDir tmp("correspondence");
  const fs::path file = tmp.path / kCorrespondenceFile;
  std::ofstream(file) << "an older, longer file\n" << std::string(10000, 'x') << "\n";
  ASSERT_TRUE(writeCorrespondence(file.string(), points, image).ok());
  std::ifstream in(file);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line[0], '#');
  int count = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    size_t v;
    int face;
    std::string b[3], x[3];
    ASSERT_TRUE(ls >> v >> face >> b[0] >> b[1] >> b[2] >> x[0] >> x[1] >> x[2]) << line;
    std::string rest;
    EXPECT_FALSE(ls >> rest) << "more than eight fields: " << line;
    ASSERT_EQ(v, static_cast<size_t>(count));
    EXPECT_EQ(face, points[v].face);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(std::strtod(b[k].c_str(), nullptr), points[v].bary[k]) << line;
      EXPECT_EQ(std::strtod(x[k].c_str(), nullptr), image[v][k]) << line;
    }
    ++count;
  }
  EXPECT_EQ(count, 50);
  EXPECT_EQ(filesIn(tmp.path), (std::set<std::string>{kCorrespondenceFile})) << "a temporary was left behind";
  // A folder that does not exist: an OutputError naming the file.
  const std::string nowhere = (tmp.path / "missing" / kCorrespondenceFile).string();
  const Status s = writeCorrespondence(nowhere, points, image);
  EXPECT_EQ(s.code, ErrorCode::OutputError);
  EXPECT_NE(s.message.find(nowhere), std::string::npos) << s.message;
  // A device is written in place.
  EXPECT_TRUE(writeCorrespondence("/dev/null", points, image).ok());
}

TEST(MapIO, TheMorphBlendsTheAnchorFittedSourceIntoItsImage) {
  const IndexedMesh source = fx::icosphere(2);
  Mesh from;
  fromIndexed(source, from);
  const std::vector<int> anchors = farthestPointSampling(source, 6);
  // The image: the source under a similarity (rotation, scale 2.5, translation), then every
  // vertex but the anchors pushed along its normal. The best similarity onto the anchors' images
  // is the one applied, so frame 0 is the source under it, everywhere.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 0.5).normalized()).toRotationMatrix();
  auto similarity = [&](const Vec3& p) { return Vec3(2.5 * R * p + Vec3(4, -1, 2)); };
  std::vector<Vec3> image(source.vertexCount());
  for (int v = 0; v < source.vertexCount(); ++v)
    image[v] = similarity(source.positions[v] * (1 + 0.2 * std::sin(3 * source.positions[v].x())));
  for (int a : anchors) image[a] = similarity(source.positions[a]);

  TempDir tmp("morph");
  const int count = 5;
  int stale = -1;
  ASSERT_TRUE(writeMorph(tmp.path.string(), from, image, anchors, count, &stale).ok());
  EXPECT_EQ(stale, 0);
  std::set<std::string> expected;
  for (int k = 0; k < count; ++k) expected.insert(morphFileName(k));
  EXPECT_EQ(filesIn(tmp.path), expected);
  for (int k = 0; k < count; ++k) {
    Mesh frame;
    const LoadResult r = loadMesh((tmp.path / morphFileName(k)).string(), frame);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    ASSERT_EQ(frame.VN(), from.VN());
    ASSERT_EQ(frame.FN(), from.FN());
    for (int f = 0; f < frame.FN(); ++f)
      for (int i = 0; i < 3; ++i) EXPECT_EQ(frame.face[f].cV(i) - &frame.vert[0], source.faces[f][i]);
    const double t = k / (count - 1.0);
    for (int v = 0; v < frame.VN(); ++v)
      EXPECT_LT((at(frame, v) - ((1 - t) * similarity(source.positions[v]) + t * image[v])).norm(), 1e-9)
          << "frame " << k << ", vertex " << v;
  }

  // A shorter sequence into the same folder removes the frames it does not rewrite.
  ASSERT_TRUE(writeMorph(tmp.path.string(), from, image, anchors, 3, &stale).ok());
  EXPECT_EQ(stale, 2);
  EXPECT_EQ(filesIn(tmp.path), (std::set<std::string>{morphFileName(0), morphFileName(1), morphFileName(2)}));
  EXPECT_TRUE(staleMorphFrames(tmp.path.string(), 3).empty());
  // ... up to the first missing number: a frame after a gap is not of that sequence.
  for (int k : {3, 4, 6}) std::ofstream(tmp.path / morphFileName(k)) << "ply";
  EXPECT_EQ(staleMorphFrames(tmp.path.string(), 3),
            (std::vector<std::string>{(tmp.path / morphFileName(3)).string(), (tmp.path / morphFileName(4)).string()}));
  ASSERT_TRUE(writeMorph(tmp.path.string(), from, image, anchors, 3, &stale).ok());
  EXPECT_EQ(stale, 2);
  EXPECT_TRUE(fs::exists(tmp.path / morphFileName(6)));
  EXPECT_FALSE(fs::exists(tmp.path / morphFileName(3)));
}

TEST(MapIO, AMorphNeedsTwoFramesAWritableFolderAndThreeAnchorsToFit) {
  const IndexedMesh source = fx::icosphere(1);
  Mesh from;
  fromIndexed(source, from);
  std::vector<Vec3> image = source.positions;
  for (auto& p : image) p = 2.0 * p + Vec3(1, 0, 0);
  TempDir tmp("morph_errors");
  EXPECT_EQ(writeMorph(tmp.path.string(), from, image, {0, 1, 2}, 1).code, ErrorCode::InvalidArgument);
  EXPECT_TRUE(filesIn(tmp.path).empty());
  EXPECT_EQ(writeMorph((tmp.path / "missing").string(), from, image, {0, 1, 2}, 2).code, ErrorCode::OutputError);
  // With fewer than three anchors no similarity is fitted: frame 0 is the source as it is.
  ASSERT_TRUE(writeMorph(tmp.path.string(), from, image, {0, 1}, 2).ok());
  Mesh first;
  ASSERT_TRUE(loadMesh((tmp.path / morphFileName(0)).string(), first).status.ok());
  for (int v = 0; v < first.VN(); ++v) EXPECT_LT((at(first, v) - source.positions[v]).norm(), 1e-12);
  EXPECT_EQ(morphFileName(7), "morph_007.ply");
  EXPECT_EQ(morphFileName(123), "morph_123.ply");
}
