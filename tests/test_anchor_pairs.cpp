// Anchor pairs added where the source layout gets stuck (anchor_pairs.h): the distances inside a
// region, the refusal of a layout that is not stuck, and on femur.off (genus 2, whose tunnels are
// small next to the anchor spacing) complete layouts at every sampling count and a map onto a
// warped copy with the known correspondence recovered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cbd/anchor_pairs.h"
#include "cbd/anchor_sampling.h"
#include "cbd/pipeline.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// The complete layout of an icosphere with 12 anchors, and the signature of its patch 0.
struct SphereCase {
  IndexedMesh mesh = fx::icosphere(3);
  std::vector<int> anchors = farthestPointSampling(mesh, 12);
  SourceLayoutResult layout;
  RegionSignature patch0;
  SphereCase() {
    layout = buildSourceLayout(mesh, anchors);
    const Layout& L = layout.layout;
    std::vector<int> anchorOf(L.mesh.vertexCount(), -1);
    for (int i = 0; i < L.anchorCount(); ++i) anchorOf[L.anchorVertices[i]] = i;
    const int face = static_cast<int>(std::find(L.facePatch.begin(), L.facePatch.end(), 0) - L.facePatch.begin());
    RegionScratch scratch;
    patch0 = regionSignaturesAt(L.mesh, L.edgePath, anchorOf, L.edges, {face}, scratch).front();
  }
};

/// femur.off from Debian's libcgal-demo, or an empty mesh when setup has not unpacked it.
IndexedMesh femur() { return fx::readMeshOrEmpty(std::string(CBD_CGAL_MESHES) + "/femur.off"); }

}  // namespace

TEST(RegionDistances, MeasureFromThePathsAroundAPatch) {
  const SphereCase c;
  ASSERT_TRUE(c.layout.status.ok()) << c.layout.status.message;
  RegionDistances d;
  ASSERT_TRUE(regionDistances(c.layout.layout, c.patch0, d));
  // The sides are the patch's three paths.
  std::vector<int> sides = d.sides, expected(c.layout.layout.patches[0].edges.begin(), c.layout.layout.patches[0].edges.end());
  std::sort(sides.begin(), sides.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(sides, expected);
  ASSERT_FALSE(d.vertices.empty());
  const double diagonal = boundingBoxDiagonal(c.mesh);
  for (size_t k = 0; k < d.vertices.size(); ++k) {
    // The boundary is the three paths (the anchors are their ends): the nearest of them.
    const double nearest = *std::min_element(d.toSide[k].begin(), d.toSide[k].end());
    EXPECT_NEAR(d.toBoundary[k], nearest, 1e-12);
    EXPECT_GT(d.toBoundary[k], 0.0);
    // Inside one patch of 12 on the unit sphere: no distance is longer than its diameter.
    for (double s : d.toSide[k]) EXPECT_LT(s, 0.5 * diagonal);
  }
  const int deepest = d.deepest();
  ASSERT_GE(deepest, 0);
  EXPECT_EQ(*std::max_element(d.toBoundary.begin(), d.toBoundary.end()), d.toBoundary[deepest]);
  // A region no layout has: none.
  RegionSignature none = c.patch0;
  none.loops.front().front().first = static_cast<int>(c.layout.layout.edges.size()) + 5;
  EXPECT_FALSE(regionDistances(c.layout.layout, none, d));
}

TEST(PlaceAnchorPair, RefusesALayoutThatIsNotStuck) {
  const SphereCase c;
  ASSERT_TRUE(c.layout.status.ok());
  EXPECT_FALSE(c.layout.stuck);
  const AnchorPairResult r = placeAnchorPair(c.layout, c.mesh, c.anchors);
  EXPECT_EQ(r.status.code, ErrorCode::LayoutFailed);
  EXPECT_EQ(r.sourceVertex, -1);
}

TEST(AnchorPairsOnRealMeshes, CompleteFemurLayoutsAtEverySamplingCount) {
  const IndexedMesh m = femur();
  if (m.vertexCount() == 0) GTEST_SKIP() << "scripts/setup.sh unpacks " << CBD_CGAL_MESHES;
  const int chi = closedEulerCharacteristic(m);
  ASSERT_EQ(chi, -2);
  for (int n : {8, 12, 16, 20, 24, 32}) {
    const std::vector<int> a = farthestPointSampling(m, n);
    // Without added anchors the layout fails in a region with a tunnel and no anchor inside.
    const SourceLayoutResult alone = buildSourceLayout(m, a);
    ASSERT_FALSE(alone.status.ok()) << n;
    EXPECT_TRUE(alone.stuck) << n;
    ASSERT_GE(alone.stuckVertex, 0) << n;
    EXPECT_EQ(std::count(a.begin(), a.end(), alone.stuckVertex), 0) << n;
    CrossParameterizationOptions none;
    none.maxAnchorPairs = 0;
    const LayoutPair refused = buildLayouts(m, a, m, a, chi, none);
    EXPECT_EQ(refused.status.code, ErrorCode::LayoutFailed) << n;
    EXPECT_NE(refused.status.message.find("no path can split"), std::string::npos) << refused.status.message;
    // With them it completes, within the cap, and says so.
    const LayoutPair p = buildLayouts(m, a, m, a, chi, {});
    ASSERT_TRUE(p.status.ok()) << n << ": " << p.status.message;
    EXPECT_TRUE(p.sameSurface);
    EXPECT_GE(p.addedAnchors.size(), 1u) << n;
    EXPECT_LE(p.addedAnchors.size(), 10u) << n;  // 4 x genus + 2
    EXPECT_EQ(p.source.anchorCount(), n + static_cast<int>(p.addedAnchors.size()));
    EXPECT_EQ(validateLayout(p.source, chi).eulerCharacteristic, chi);
    EXPECT_TRUE(validateLayout(p.source, chi).status.ok());
    for (const auto& [s, t] : p.addedAnchors) {
      EXPECT_EQ(s, t);
      EXPECT_EQ(std::count(a.begin(), a.end(), s), 0);
    }
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("added1"), std::string::npos) << p.warnings[0];
  }
}

TEST(AnchorPairsOnRealMeshes, FemurMapsOntoAWarpedCopy) {
  const IndexedMesh s = femur();
  if (s.vertexCount() == 0) GTEST_SKIP() << "scripts/setup.sh unpacks " << CBD_CGAL_MESHES;
  IndexedMesh t = s;
  for (Vec3& x : t.positions) x = fx::warpedCopyPoint(x);
  const int chi = closedEulerCharacteristic(s);
  const double diagonal = boundingBoxDiagonal(t);
  // One count, where several pairs are added: the sanitizer build runs this map slowly.
  for (int n : {12}) {
    const std::vector<int> a = farthestPointSampling(s, n);
    const CrossParameterizationResult r = crossParameterize(s, a, t, a, chi);
    ASSERT_TRUE(r.status.ok()) << n << ": " << r.status.message;
    ASSERT_FALSE(r.layouts.addedAnchors.empty());
    EXPECT_TRUE(checkIsomorphic(r.layouts.source, r.layouts.target).ok());
    EXPECT_EQ(r.metrics.flipped, 0) << n;
    EXPECT_EQ(r.metrics.degenerate, 0) << n;
    // Every given anchor maps onto its partner (added pairs are only placed: the untangling may
    // move them).
    for (int v : a) EXPECT_NEAR((r.map.sourceImage[v] - t.positions[v]).norm(), 0.0, 1e-9);
    // The known correspondence (vertex v onto warped vertex v) recovered on average within 1 %
    // of the diagonal.
    double sum = 0;
    for (int v = 0; v < s.vertexCount(); ++v) sum += (r.map.sourceImage[v] - t.positions[v]).norm();
    EXPECT_LT(sum / s.vertexCount(), 0.01 * diagonal) << n;
  }
}
