// The experimental map stage (map_optimization.h), through the pipeline: injective in the base
// domain, M_ts the exact inverse of M_st (on spheres and on cow -> bull), the distortion energy
// lowered, and a known smooth correspondence recovered.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cbd/anchor_sampling.h"
#include "cbd/pipeline.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// A smooth warp: turned, scaled by 1.5 and bumped by 3 % along the normal.
Vec3 bumpy(const Vec3& x) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const double bump = 1.0 + 0.03 * std::sin(3 * x.x()) * std::cos(2 * x.y());
  return 1.5 * bump * (R * x);
}

CrossParameterizationResult optimized(const fx::AnchoredPair& p) {
  CrossParameterizationOptions o;
  o.mapStage = MapStage::Optimize;
  return crossParameterize(p.source, p.sourceAnchors, p.target, p.targetAnchors, 2, o);
}

/// The farthest any source vertex lands from itself, as a fraction of the source's bounding-box
/// diagonal, when M_st carries it to the target and the source's faces in D (as the optimization
/// left them) carry it back: M_ts and M_st are one bijection when this is rounding.
double worstRoundTrip(const IndexedMesh& source, const CrossParameterizationResult& r) {
  const BaseDomain D(r.layouts.source);
  const SurfaceInDomain targetInD(r.layouts.target, r.targetParam, D);
  const IndexedMesh faces = r.layouts.source.mesh.toIndexed();
  const TrianglesInDomain sourceFaces(D, faces.faces, r.optimization.sourcePoints, r.optimization.sourceCharts);
  const double diag = boundingBoxDiagonal(source);
  double worst = 0;
  for (int v = 0; v < source.vertexCount(); ++v) {
    DomainPoint x;
    FacePoint back;
    if (!targetInD.toDomain(r.map.sourceToTarget[v], x) || !sourceFaces.locate(x, back)) return 1.0;
    const auto& t = faces.faces[back.face];
    const Vec3 q = back.bary[0] * faces.positions[t[0]] + back.bary[1] * faces.positions[t[1]] +
                   back.bary[2] * faces.positions[t[2]];
    worst = std::max(worst, (q - source.positions[v]).norm() / diag);
  }
  return worst;
}

}  // namespace

TEST(MapOptimization, IsInjectiveInTheDomainAndLowersTheEnergy) {
  const fx::AnchoredPair p = fx::anchoredSpheres(20, bumpy);
  const CrossParameterizationResult r = optimized(p);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.optimization.injective);
  EXPECT_GT(r.optimization.iterations, 0);
  EXPECT_LT(r.optimization.energyAfter, r.optimization.energyBefore);
  EXPECT_TRUE(std::isfinite(r.optimization.energyAfter));
  // On a smooth pair Newton's last step is whole: the stop on tolerance is a minimum.
  EXPECT_EQ(r.optimization.stop, MapOptimizationStop::Tolerance);
  EXPECT_LT(r.optimization.boundedSteps, r.optimization.iterations);
  EXPECT_TRUE(r.optimization.converged);
  EXPECT_TRUE(std::isfinite(r.metrics.eL2) && std::isfinite(r.metrics.eAng));
  EXPECT_EQ(r.metrics.degenerate, 0);
  // Anchors map onto anchors.
  for (size_t a = 0; a < p.sourceAnchors.size(); ++a)
    EXPECT_NEAR((r.map.sourceImage[p.sourceAnchors[a]] - p.target.positions[p.targetAnchors[a]]).norm(), 0.0, 1e-9);
}

TEST(MapOptimization, MapsTargetToSourceByTheExactInverse) {
  const fx::AnchoredPair p = fx::anchoredSpheres(20, bumpy);
  const CrossParameterizationResult r = optimized(p);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LT(worstRoundTrip(p.source, r), 1e-6);
  // M_ts puts every target vertex on the source surface (the unit sphere, up to its facets).
  for (const Vec3& y : r.map.targetImage) EXPECT_NEAR(y.norm(), 1.0, 0.02);
}

TEST(MapOptimizationOnRealMeshes, CarriesTheCowToTheBullAndBackByTheExactInverse) {
  const std::string meshes = std::string(CBD_CGAL_MESHES);
  if (!std::filesystem::exists(meshes + "/cow.off")) GTEST_SKIP() << "scripts/setup.sh unpacks the CGAL meshes";
  LoadedInput in;
  loadAndValidate({meshes + "/cow.off", meshes + "/bull.off", std::string(CBD_EXAMPLES) + "/cow_picked_points.pp",
                   std::string(CBD_EXAMPLES) + "/bull_picked_points.pp"},
                  {}, in);
  ASSERT_TRUE(in.report.status.ok()) << in.report.status.message;
  std::vector<int> sa, ta;
  for (const auto& a : in.report.anchors.source) sa.push_back(a.vertex);
  for (const auto& a : in.report.anchors.target) ta.push_back(a.vertex);
  CrossParameterizationOptions o;
  o.mapStage = MapStage::Optimize;
  const CrossParameterizationResult r =
      crossParameterize(in.source, sa, in.target, ta, in.report.source.eulerCharacteristic, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.optimization.injective);
  EXPECT_LT(r.optimization.energyAfter, r.optimization.energyBefore);
  EXPECT_LT(worstRoundTrip(in.source, r), 1e-6);
}

TEST(MapOptimization, RecoversAKnownSmoothCorrespondence) {
  const fx::AnchoredPair p = fx::anchoredSpheres(24, bumpy);
  const CrossParameterizationResult r = optimized(p);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  // The warp of each source vertex lies on the target (up to its facets): the map should find it.
  double sum = 0;
  for (int v = 0; v < p.source.vertexCount(); ++v) sum += (r.map.sourceImage[v] - bumpy(p.source.positions[v])).norm();
  EXPECT_LT(sum / p.source.vertexCount(), 0.01 * boundingBoxDiagonal(p.target));
}

TEST(MapOptimization, SaysItStoppedAtTheCapWithoutConverging) {
  const fx::AnchoredPair p = fx::anchoredSpheres(20, bumpy);
  CrossParameterizationOptions o;
  o.mapStage = MapStage::Optimize;
  o.optimization.maxIterations = 1;
  const CrossParameterizationResult capped =
      crossParameterize(p.source, p.sourceAnchors, p.target, p.targetAnchors, 2, o);
  ASSERT_TRUE(capped.status.ok()) << capped.status.message;
  EXPECT_EQ(capped.optimization.stop, MapOptimizationStop::MaxIterations);
  EXPECT_EQ(capped.optimization.iterations, 1);
  EXPECT_FALSE(capped.optimization.converged);
}

TEST(MapOptimization, CancelsWhenTheCallbackSaysStop) {
  const fx::AnchoredPair p = fx::anchoredSpheres(12, bumpy);
  CrossParameterizationOptions o;
  o.mapStage = MapStage::Optimize;
  int calls = 0;
  const ProgressCallback stop = [&](int, const char*) { return ++calls < 1; };
  const CrossParameterizationResult r = crossParameterize(p.source, p.sourceAnchors, p.target, p.targetAnchors, 2, o, stop);
  EXPECT_EQ(r.status.code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 1);  // the first report of the optimization ends it
}
