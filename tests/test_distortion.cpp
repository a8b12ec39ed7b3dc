// The distortion of M_st (distortion.h): L2-stretch and angle distortion at their optimum for an
// isometry or a similarity, the closed-form values of a stretch along one axis, flipped and
// degenerate image triangles counted, per-face shares that add up to the means.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "cbd/distortion.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// The square [-1, 1]^2 in the plane z = 0, n x n cells, each split along its rising diagonal,
/// counter-clockwise seen from +z (an open surface: the metrics do not need a closed one).
IndexedMesh grid(int n) {
  IndexedMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.emplace_back(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

IndexedMesh bumpySphere(int level) {
  IndexedMesh m = fx::icosphere(level);
  for (auto& p : m.positions) p *= 1.0 + 0.1 * std::sin(5 * p.x()) * std::cos(4 * p.y());
  return m;
}

double area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

/// The face of a planar mesh holding p (in the plane z = 0) and p's barycentric coordinates.
FacePoint locateInPlane(const IndexedMesh& m, const Vec3& p) {
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const double whole = (b - a).cross(c - a).z();
    const Vec3 bary((b - p).cross(c - p).z() / whole, (c - p).cross(a - p).z() / whole,
                    (a - p).cross(b - p).z() / whole);
    if (bary.minCoeff() >= -1e-12) return {f, bary};
  }
  return {};
}

void expectOptimal(const DistortionMetrics& d, int faces) {
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_NEAR(d.eL2, 1.0, 1e-12);
  EXPECT_NEAR(d.eL2Inverse, 1.0, 1e-12);
  EXPECT_NEAR(d.eAng, 0.0, 1e-12);
  EXPECT_NEAR(d.eAngDegrees, 0.0, 1e-9);
  EXPECT_EQ(d.flipped, 0);
  EXPECT_EQ(d.degenerate, 0);
  ASSERT_EQ(static_cast<int>(d.faceStretch.size()), faces);
  for (int f = 0; f < faces; ++f) {
    EXPECT_NEAR(d.faceStretch[f], 1.0, 1e-12) << "face " << f;
    EXPECT_NEAR(d.faceAngleShare[f], 0.0, 1e-12) << "face " << f;
  }
}

}  // namespace

TEST(Distortion, TheIdentityIsOptimal) {
  const IndexedMesh m = bumpySphere(2);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  fx::identityMap(m, on, image);
  expectOptimal(computeDistortion(m, image, m, on), m.faceCount());
}

TEST(Distortion, ASimilarityIsOptimalToo) {
  // E_L2 is normalised by the total areas, E_ang is scale-free: a rotation, a uniform scale by 3
  // and a translation leave both at their optimum.
  const IndexedMesh m = bumpySphere(2);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  IndexedMesh target = m;
  for (auto& p : target.positions) p = 3.0 * R * p + Vec3(5, -2, 1);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  fx::identityMap(target, on, image);  // vertex v onto target vertex v
  expectOptimal(computeDistortion(m, image, target, on), m.faceCount());
}

TEST(Distortion, AStretchAlongOneAxisHasTheClosedFormValues) {
  // (x, y) -> (2x, y) on a planar grid: every triangle's Jacobian has singular values 2 and 1, so
  // E_ang = (2/1 + 1/2)/2 - 1 = 1/4, and E_L2 = sqrt((4 + 1)/2) * sqrt(A_s / A_t) = sqrt(5/4),
  // its inverse sqrt((1/4 + 1)/2) * sqrt(A_t / A_s) = sqrt(5/4) too. Each half-square's corner
  // angles 45, 45, 90 become atan(1/2), atan(2), 90 degrees. Scaling the image as well changes
  // nothing.
  const IndexedMesh m = grid(6);
  const double angleError = 2.0 / 3.0 * (45.0 - std::atan(0.5) * 180.0 / M_PI);
  for (double scale : {1.0, 0.25}) {
    IndexedMesh target = m;
    for (auto& p : target.positions) p = scale * Vec3(2 * p.x(), p.y(), 0);
    std::vector<FacePoint> on;
    std::vector<Vec3> image;
    fx::identityMap(target, on, image);
    const DistortionMetrics d = computeDistortion(m, image, target, on);
    ASSERT_TRUE(d.status.ok()) << d.status.message;
    EXPECT_NEAR(d.eAng, 0.25, 1e-12);
    EXPECT_NEAR(d.eL2, std::sqrt(1.25), 1e-12);
    EXPECT_NEAR(d.eL2Inverse, std::sqrt(1.25), 1e-12);
    EXPECT_NEAR(d.eAngDegrees, angleError, 1e-9);
    EXPECT_EQ(d.flipped, 0);
    EXPECT_EQ(d.degenerate, 0);
    for (int f = 0; f < m.faceCount(); ++f) EXPECT_NEAR(d.faceStretch[f], std::sqrt(1.25), 1e-12) << "face " << f;
  }
}

TEST(Distortion, AMirroredMapIsAnIsometryWithEveryTriangleFlipped) {
  // (x, y) -> (x, -y) maps the grid onto itself: lengths and angles are kept, so the metrics are
  // optimal, but every image triangle faces -z over a surface facing +z.
  const int n = 4;
  const IndexedMesh m = grid(n);
  std::vector<FacePoint> on(m.vertexCount());
  std::vector<Vec3> image(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) {
    image[v] = Vec3(m.positions[v].x(), -m.positions[v].y(), 0);
    on[v] = locateInPlane(m, image[v]);
    ASSERT_GE(on[v].face, 0);
  }
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  ASSERT_TRUE(d.status.ok());
  EXPECT_EQ(d.flipped, m.faceCount());
  EXPECT_NEAR(d.eL2, 1.0, 1e-12);
  EXPECT_NEAR(d.eAng, 0.0, 1e-12);
}

TEST(Distortion, FlippedTrianglesAreCountedAsTheyTurnOver) {
  // One interior vertex of a planar grid slid along +x past its neighbour: the triangles that
  // turn over are exactly those whose image faces -z.
  const int n = 6;
  const IndexedMesh m = grid(n);
  for (double shift : {0.2, 0.5, 0.9}) {
    SCOPED_TRACE(shift);
    std::vector<FacePoint> on;
    std::vector<Vec3> image;
    fx::identityMap(m, on, image);
    const int v = 3 * (n + 1) + 3;  // the centre vertex; its neighbour along +x is 1/3 away
    image[v] += Vec3(shift, 0, 0);
    on[v] = locateInPlane(m, image[v]);
    ASSERT_GE(on[v].face, 0);
    int turned = 0;
    for (const auto& t : m.faces) turned += (image[t[1]] - image[t[0]]).cross(image[t[2]] - image[t[0]]).z() < 0;
    const DistortionMetrics d = computeDistortion(m, image, m, on);
    ASSERT_TRUE(d.status.ok());
    EXPECT_EQ(d.flipped, turned);
    if (shift > 1.0 / 3) {
      EXPECT_GT(turned, 0);
    } else {
      EXPECT_EQ(turned, 0);
    }
  }
}

TEST(Distortion, DegenerateImagesAreCountedAndLeftOutOfTheMeans) {
  // Two vertices of an edge mapped onto one point: the two triangles on that edge collapse. They
  // are counted, take no share, and the means are over the other triangles.
  const IndexedMesh m = grid(4);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  fx::identityMap(m, on, image);
  const int v = 2 * 5 + 2, w = v + 1;  // the centre and its neighbour along +x
  image[v] = image[w];
  on[v] = on[w];
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  ASSERT_TRUE(d.status.ok());
  EXPECT_EQ(d.degenerate, 2);
  int collapsed = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    if (std::count(t.begin(), t.end(), v) && std::count(t.begin(), t.end(), w)) {
      ++collapsed;
      EXPECT_EQ(d.faceAngleShare[f], 0.0);
      EXPECT_EQ(d.faceL2Share[f], 0.0);
    }
  }
  EXPECT_EQ(collapsed, 2);
  EXPECT_TRUE(std::isfinite(d.eL2) && std::isfinite(d.eAng) && std::isfinite(d.eL2Inverse));
  EXPECT_GT(d.eAng, 0.0);
  // Every triangle collapsed: nothing to measure.
  std::vector<Vec3> point(m.vertexCount(), Vec3(0.1, 0.2, 0));
  EXPECT_EQ(computeDistortion(m, point, m, on).status.code, ErrorCode::InternalError);
}

TEST(Distortion, FaceSharesAddUpToTheMetricsAndSitWhereTheMapDistorts) {
  // The identity of a bumpy sphere with one vertex's image slid into one of its faces: only
  // that vertex's star is distorted, and the per-face shares must say so.
  const IndexedMesh m = bumpySphere(2);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  fx::identityMap(m, on, image);
  const int v = 7;
  const auto& t = m.faces[on[v].face];
  const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
  on[v].bary = Vec3::Constant(0.2);
  on[v].bary[k] = 0.6;
  image[v] = fx::pointOn(m, on[v]);
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  ASSERT_TRUE(d.status.ok());
  ASSERT_EQ(d.degenerate, 0);
  ASSERT_EQ(static_cast<int>(d.faceAngleShare.size()), m.faceCount());
  ASSERT_EQ(static_cast<int>(d.faceL2Share.size()), m.faceCount());
  double ang = 0, l2sq = 0, star = 0, sumAs = 0, sumAt = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& u = m.faces[f];
    sumAs += area(m.positions[u[0]], m.positions[u[1]], m.positions[u[2]]);
    sumAt += area(image[u[0]], image[u[1]], image[u[2]]);
  }
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& u = m.faces[f];
    ang += d.faceAngleShare[f], l2sq += d.faceL2Share[f];
    if (u[0] == v || u[1] == v || u[2] == v) {
      EXPECT_GT(d.faceAngleShare[f], 1e-6) << "face " << f << " of the moved vertex's star";
      star += d.faceAngleShare[f];
      continue;
    }
    // Untouched: no angle distortion, and a stretch share of its area at the map's scale.
    const double as = area(m.positions[u[0]], m.positions[u[1]], m.positions[u[2]]);
    EXPECT_NEAR(d.faceAngleShare[f], 0.0, 1e-12) << "face " << f;
    EXPECT_NEAR(d.faceL2Share[f], as * sumAs / (sumAt * sumAt), 1e-12) << "face " << f;
  }
  EXPECT_GT(d.eAng, 0.0);
  EXPECT_NEAR(ang, d.eAng, 1e-12);
  EXPECT_NEAR(star, d.eAng, 1e-12);
  EXPECT_NEAR(l2sq, d.eL2 * d.eL2, 1e-12);
}
