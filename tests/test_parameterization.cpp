// Stage 4: patch parameterizations, the composed cross-map and its distortion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cbd/anchor_sampling.h"
#include "cbd/pipeline.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {
double signedArea(const std::array<Vec2, 3>& t) {
  return 0.5 * ((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
}
}  // namespace

TEST(Parameterization, EveryPatchMapsBijectivelyOntoTheTriangle) {
  const IndexedMesh m = fx::icosphere(3);
  SourceLayoutResult r = buildSourceLayout(m, farthestPointSampling(m, 12));
  ASSERT_TRUE(r.status.ok());
  splitCollinearFaces(r.layout);
  ASSERT_TRUE(validateLayout(r.layout, 2).status.ok());
  const PatchParameterization p = parameterizePatches(r.layout);
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  // Positive orientation everywhere and the areas of each patch add up to the domain's.
  std::vector<double> area(r.layout.patches.size(), 0.0);
  for (int f = 0; f < r.layout.mesh.faceCount(); ++f) {
    const double a = signedArea(p.cornerUV[f]);
    EXPECT_GT(a, 0.0) << "face " << f << " folds over";
    area[r.layout.facePatch[f]] += a;
  }
  const double domain = std::sqrt(3.0) / 4.0;
  for (double a : area) EXPECT_NEAR(a, domain, 1e-9);
  // Corners land on the domain's corners.
  for (int f = 0; f < r.layout.mesh.faceCount(); ++f) {
    const Patch& patch = r.layout.patches[r.layout.facePatch[f]];
    const auto v = r.layout.mesh.faceVertices(f);
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        if (v[k] == r.layout.anchorVertices[patch.corners[c]]) EXPECT_LT((p.cornerUV[f][k] - domainCorner(c)).norm(), 1e-15);
  }
}

TEST(Parameterization, ADiskWithCollapsedFacesStillMapsBijectively) {
  // A vertex and its whole ring at one point (edge splits along many paths leave such slivers):
  // its mean-value weights are all zero, and a vertex's weights must be positive. The disk of
  // faces within three rings of it, its rim fixed on the unit circle, still maps onto the disk
  // with every face positive, the collapsed ones included.
  const IndexedMesh sphere = fx::icosphere(2);
  const int centre = fx::nearestVertex(sphere, Vec3(0, 0, 1));
  std::vector<int> ringOf(sphere.vertexCount(), -1);
  ringOf[centre] = 0;
  for (int ring = 1; ring <= 3; ++ring)
    for (const auto& f : sphere.faces)
      for (int k = 0; k < 3; ++k)
        if (ringOf[f[k]] == ring - 1)
          for (int j = 0; j < 3; ++j)
            if (ringOf[f[j]] < 0) ringOf[f[j]] = ring;
  IndexedMesh collapsed = sphere;
  for (const auto& f : sphere.faces)
    for (int k = 0; k < 3; ++k)
      if (ringOf[f[k]] == 1) collapsed.positions[f[k]] = sphere.positions[centre];
  const RefinedMesh mesh(collapsed);
  std::vector<int> disk;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const auto v = mesh.faceVertices(f);
    if (ringOf[v[0]] >= 0 && ringOf[v[1]] >= 0 && ringOf[v[2]] >= 0) disk.push_back(f);
  }
  // The rim: the third ring, in the order of its angle about the z axis on the sphere.
  auto fixedAt = [&](int f, int k, Vec2& at) {
    const int v = mesh.faceVertices(f)[k];
    if (ringOf[v] != 3) return false;
    const Vec3& p = sphere.positions[v];
    const double angle = std::atan2(p.y(), p.x());
    at = Vec2(std::cos(angle), std::sin(angle));
    return true;
  };
  std::vector<std::array<Vec2, 3>> uv;
  int unknowns = 0;
  ASSERT_TRUE(meanValueMap(mesh, disk, fixedAt, uv, &unknowns));
  EXPECT_EQ(unknowns, std::count_if(ringOf.begin(), ringOf.end(), [](int r) { return r >= 0 && r < 3; }));
  double area = 0.0;
  for (const auto& t : uv) {
    EXPECT_GT(signedArea(t), 0.0);
    area += signedArea(t);
  }
  double rim = 0.0;  // the area of the polygon of the rim
  std::vector<double> angles;
  for (int v = 0; v < sphere.vertexCount(); ++v)
    if (ringOf[v] == 3) angles.push_back(std::atan2(sphere.positions[v].y(), sphere.positions[v].x()));
  std::sort(angles.begin(), angles.end());
  for (size_t k = 0; k < angles.size(); ++k) rim += 0.5 * std::sin(angles[(k + 1) % angles.size()] - angles[k] + (k + 1 == angles.size() ? 2 * M_PI : 0));
  EXPECT_NEAR(area, rim, 1e-9);
}

TEST(CrossMap, SameLayoutOnBothSidesIsTheIdentity) {
  // Stage-4 identity: with the very same layout on both sides the composed map must be the
  // identity to rounding, and the metrics optimal.
  const IndexedMesh m = fx::icosphere(3);
  SourceLayoutResult r = buildSourceLayout(m, farthestPointSampling(m, 10));
  ASSERT_TRUE(r.status.ok());
  splitCollinearFaces(r.layout);
  const PatchParameterization p = parameterizePatches(r.layout);
  const CrossMap map = composeCrossMap(r.layout, p, r.layout, p);
  ASSERT_TRUE(map.status.ok()) << map.status.message;
  const double diag = boundingBoxDiagonal(m);
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_LT((map.sourceImage[v] - m.positions[v]).norm(), 1e-9 * diag);
  const DistortionMetrics d = computeDistortion(m, map.sourceImage, m, map.sourceToTarget);
  ASSERT_TRUE(d.status.ok());
  EXPECT_NEAR(d.eL2, 1.0, 1e-6);
  EXPECT_NEAR(d.eL2Inverse, 1.0, 1e-6);
  EXPECT_NEAR(d.eAng, 0.0, 1e-6);
  EXPECT_NEAR(d.eAngDegrees, 0.0, 1e-6);
  EXPECT_EQ(d.flipped, 0);
  EXPECT_EQ(d.degenerate, 0);
}

TEST(CrossMap, SphereToEllipsoidRoundTripAndGroundTruth) {
  const IndexedMesh s = fx::icosphere(3);
  const IndexedMesh tu = fx::icosphere(4);
  IndexedMesh t = tu;
  auto deform = [](const Vec3& p) { return Vec3(1.6 * p.x(), p.y(), 0.8 * p.z()); };
  for (auto& p : t.positions) p = deform(p);
  const std::vector<int> sa = farthestPointSampling(s, 20);
  std::vector<int> ta;
  for (int v : sa) ta.push_back(fx::nearestVertex(tu, s.positions[v]));
  for (LayoutMethod method : {LayoutMethod::Voronoi, LayoutMethod::Greedy}) {
    SCOPED_TRACE(layoutMethodName(method));
    CrossParameterizationOptions o;
    o.method = method;
    const CrossParameterizationResult r = crossParameterize(s, sa, t, ta, 2, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const double diagS = boundingBoxDiagonal(s), diagT = boundingBoxDiagonal(t);
    // Anchors land exactly on anchors.
    for (size_t k = 0; k < sa.size(); ++k) EXPECT_LT((r.map.sourceImage[sa[k]] - t.positions[ta[k]]).norm(), 1e-12 * diagT);
    // Every image lies on the target surface: on its face, inside it.
    for (int v = 0; v < s.vertexCount(); ++v) {
      const FacePoint& fp = r.map.sourceToTarget[v];
      ASSERT_GE(fp.face, 0);
      EXPECT_GE(fp.bary.minCoeff(), -1e-9);
      EXPECT_NEAR(fp.bary.sum(), 1.0, 1e-9);
      const auto& f = t.faces[fp.face];
      const Vec3 q = fp.bary[0] * t.positions[f[0]] + fp.bary[1] * t.positions[f[1]] + fp.bary[2] * t.positions[f[2]];
      EXPECT_LT((q - r.map.sourceImage[v]).norm(), 1e-9 * diagT);
    }
    // Source -> target -> source is the identity: each source vertex is carried to the
    // target through the domain and back again.
    const PatchLocator onTarget(r.layouts.target, r.targetParam), onSource(r.layouts.source, r.sourceParam);
    double worst = 0;
    const Layout& Ls = r.layouts.source;
    for (int v = 0; v < s.vertexCount(); ++v) {
      const int f = Ls.mesh.face(Ls.mesh.outgoing(v));
      const auto corners = Ls.mesh.faceVertices(f);
      Vec3 b = Vec3::Zero();
      b[std::find(corners.begin(), corners.end(), v) - corners.begin()] = 1.0;
      const int p = Ls.facePatch[f];
      int g, h;
      Vec3 bg, bh;
      ASSERT_TRUE(onTarget.locate(p, uvAt(r.sourceParam, f, b), g, bg));
      ASSERT_TRUE(onSource.locate(p, uvAt(r.targetParam, g, bg), h, bh));
      const auto hv = Ls.mesh.faceVertices(h);
      const Vec3 back = bh[0] * Ls.mesh.position(hv[0]) + bh[1] * Ls.mesh.position(hv[1]) + bh[2] * Ls.mesh.position(hv[2]);
      worst = std::max(worst, (back - s.positions[v]).norm());
          }
    EXPECT_LT(worst, 1e-6 * diagS);
    // Ground truth: the deformation is known; report the mean correspondence error.
    double err = 0;
    for (int v = 0; v < s.vertexCount(); ++v) err += (r.map.sourceImage[v] - deform(s.positions[v])).norm();
    err /= s.vertexCount() * diagT;
    RecordProperty(std::string("mean_ground_truth_error_") + layoutMethodName(method), std::to_string(err));
    EXPECT_LT(err, 0.05);
    // Metrics are finite and no better than their optimum.
    EXPECT_GE(r.metrics.eL2, 1.0 - 1e-9);
    EXPECT_GE(r.metrics.eL2Inverse, 1.0 - 1e-9);
    EXPECT_GE(r.metrics.eAng, 0.0);
    EXPECT_TRUE(std::isfinite(r.metrics.eL2) && std::isfinite(r.metrics.eAng));
    EXPECT_EQ(r.metrics.flipped, 0);
  }
}
