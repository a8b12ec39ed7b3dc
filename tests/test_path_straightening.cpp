// Path straightening of finished layouts: combinatorics kept, slivers fattened.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cbd/anchor_sampling.h"
#include "cbd/path_straightening.h"
#include "cbd/source_layout.h"
#include "cbd/target_layout.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

std::vector<double> patchAreas(const Layout& L) {
  std::vector<double> area(L.patches.size(), 0.0);
  for (int f = 0; f < L.mesh.faceCount(); ++f) {
    const auto v = L.mesh.faceVertices(f);
    area[L.facePatch[f]] +=
        0.5 * (L.mesh.position(v[1]) - L.mesh.position(v[0])).cross(L.mesh.position(v[2]) - L.mesh.position(v[0])).norm();
  }
  return area;
}

double smallestOverMean(const std::vector<double>& area) {
  double sum = 0;
  for (double a : area) sum += a;
  return *std::min_element(area.begin(), area.end()) / (sum / static_cast<double>(area.size()));
}

/// Everything that must survive straightening: validity, the same edges, patches and rotation
/// (the layout stays isomorphic to what it was, so to the other surface's), paths that lie
/// on the surface, faces that still tile it.
void expectSameCombinatorics(const Layout& before, const Layout& after, int euler) {
  const LayoutCheck c = validateLayout(after, euler);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  const Status iso = checkIsomorphic(before, after);
  EXPECT_TRUE(iso.ok()) << iso.message;
  ASSERT_EQ(before.edges.size(), after.edges.size());
  for (size_t e = 0; e < after.edges.size(); ++e) {
    EXPECT_EQ(after.edges[e].vertices.front(), after.anchorVertices[after.edges[e].a]);
    EXPECT_EQ(after.edges[e].vertices.back(), after.anchorVertices[after.edges[e].b]);
    double len = 0;
    for (size_t k = 1; k < after.edges[e].vertices.size(); ++k)
      len += (after.mesh.position(after.edges[e].vertices[k]) - after.mesh.position(after.edges[e].vertices[k - 1])).norm();
    EXPECT_NEAR(len, after.edges[e].length, 1e-9 * (1 + len));
  }
  EXPECT_EQ(before.rotation, after.rotation);
  std::vector<int> count(after.patches.size(), 0);
  for (int p : after.facePatch) ++count[p];
  for (size_t p = 0; p < after.patches.size(); ++p) EXPECT_EQ(count[p], after.patches[p].faces);
  // Splits cut faces, they do not move the surface: the patches still add up to its area.
  double a0 = 0, a1 = 0;
  for (double a : patchAreas(before)) a0 += a;
  for (double a : patchAreas(after)) a1 += a;
  EXPECT_NEAR(a0, a1, 1e-9 * a0);
  // Every vertex inserted lies on the input surface where it says it does.
  for (int v = before.mesh.vertexCount(); v < after.mesh.vertexCount(); ++v) {
    const SurfacePoint& p = after.mesh.location(v);
    ASSERT_GE(p.face, 0);
    EXPECT_NEAR(p.bary.sum(), 1.0, 1e-9);
    EXPECT_GE(p.bary.minCoeff(), -1e-9);
  }
}

}  // namespace

TEST(PathStraightening, CollinearAnchorsOnATubeLoseTheirSliverPatch) {
  // Three anchors on one generator of a tube, plus its cap centres: the traced layout closes
  // the region beside the three with a path hugging the other two, a patch of a few faces'
  // width. Its quadrilateral's diagonal runs round the far side of the tube instead.
  const IndexedMesh m = fx::cappedCylinder(0.5, 4.0, 32, 40);
  std::vector<int> anchors;
  for (const Vec3& p : {Vec3(0, 0, 4), Vec3(0, 0, 0), Vec3(0.5, 0, 1), Vec3(0.5, 0, 2), Vec3(0.5, 0, 3)})
    anchors.push_back(fx::nearestVertex(m, p));
  const SourceLayoutResult r = buildSourceLayout(m, anchors);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double tracedSliver = smallestOverMean(patchAreas(r.layout));
  EXPECT_LT(tracedSliver, 0.2);
  Layout L = r.layout;
  PathStraighteningOptions o;
  o.rounds = 2;
  const PathStraighteningResult s = straightenPaths(L, o);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_EQ(s.straightened, static_cast<int>(L.edges.size()));
  EXPECT_GT(s.splits, 0);
  expectSameCombinatorics(r.layout, L, 2);
  EXPECT_GT(smallestOverMean(patchAreas(L)), 0.5);
}

TEST(PathStraightening, KeepsTheCombinatoricsOfSphereTorusAndDoubleTorusLayouts) {
  struct Case {
    IndexedMesh mesh;
    int anchors;
  };
  std::vector<Case> cases;
  cases.push_back({fx::icosphere(3), 12});
  cases.push_back({fx::torus(2.0, 0.7, 60, 24), 9});
  cases.push_back({fx::holedPlate(2, 4, 20), 16});
  for (const Case& c : cases) {
    const int euler = fx::eulerCharacteristic(c.mesh);
    const SourceLayoutResult r = buildSourceLayout(c.mesh, farthestPointSampling(c.mesh, c.anchors));
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    Layout L = r.layout;
    PathStraighteningOptions o;
    o.rounds = 2;
    const PathStraighteningResult s = straightenPaths(L, o);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    EXPECT_GT(s.straightened, 0);
    EXPECT_EQ(s.straightened + s.skipped, static_cast<int>(L.edges.size()));
    expectSameCombinatorics(r.layout, L, euler);
    // Straightened paths are no shortest paths any more, but they stay close to them.
    EXPECT_LT(s.lengthAfter, 1.5 * s.lengthBefore);
  }
}

TEST(PathStraightening, ZeroRoundsLeaveTheLayoutAlone) {
  const IndexedMesh m = fx::icosphere(2);
  const SourceLayoutResult r = buildSourceLayout(m, farthestPointSampling(m, 8));
  ASSERT_TRUE(r.status.ok());
  Layout L = r.layout;
  PathStraighteningOptions o;
  o.rounds = 0;
  const PathStraighteningResult s = straightenPaths(L, o);
  EXPECT_TRUE(s.status.ok());
  EXPECT_EQ(s.straightened, 0);
  EXPECT_EQ(L.mesh.vertexCount(), r.layout.mesh.vertexCount());
  for (size_t e = 0; e < L.edges.size(); ++e) EXPECT_EQ(L.edges[e].vertices, r.layout.edges[e].vertices);
}
