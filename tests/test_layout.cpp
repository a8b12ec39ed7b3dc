// Patch layouts (layout.h): patches assembled from the paths of a hand-made layout, validateLayout
// accepting it and rejecting every way of breaking it, checkIsomorphic, the split of faces whose
// corners lie on one side of their patch, input faces labelled by patch, chains and rotations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "cbd/anchor_sampling.h"
#include "cbd/layout.h"
#include "cbd/parameterization.h"
#include "cbd/source_layout.h"
#include "cbd/target_layout.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// A tetrahedron (vertices 0..3, the anchors) whose face (1, 3, 2) is split by a vertex 4 near its
/// centre into (1, 3, 4), (3, 2, 4), (2, 1, 4). The layout edges are the tetrahedron's edges,
/// except that 2 - 1 runs through 4: then the face (2, 1, 4) has all three corners on that one
/// path. Patches: {(0, 1, 2), (2, 1, 4)}, {(1, 3, 4), (3, 2, 4)}, {(0, 3, 1)}, {(0, 2, 3)}.
IndexedMesh splitTetrahedron() {
  IndexedMesh m = fx::tetrahedron();
  // Raised off the face, and off its symmetry axis so no three points line up with a fourth.
  m.positions.push_back((m.positions[1] + m.positions[2] + m.positions[3]) / 3 * 1.2 + Vec3(0.05, -0.03, 0.02));
  m.faces.pop_back();  // (1, 3, 2)
  m.faces.push_back({1, 3, 4});
  m.faces.push_back({3, 2, 4});
  m.faces.push_back({2, 1, 4});
  return m;
}

Layout handMadeLayout() {
  Layout L;
  L.mesh = RefinedMesh(splitTetrahedron());
  L.anchorVertices = {0, 1, 2, 3};
  const std::vector<std::vector<int>> chains = {{0, 1}, {0, 2}, {0, 3}, {1, 3}, {3, 2}, {2, 4, 1}};
  L.edgePath.assign(L.mesh.edgeCount(), -1);
  for (size_t p = 0; p < chains.size(); ++p) {
    LayoutEdge e;
    e.a = chains[p].front();
    e.b = chains[p].back();
    e.kind = EdgeKind::Triangulation;
    e.vertices = chains[p];
    e.length = chainLength(L.mesh, chains[p]);
    for (size_t k = 0; k + 1 < chains[p].size(); ++k)
      L.edgePath[RefinedMesh::edgeOf(L.mesh.findHalfedge(chains[p][k], chains[p][k + 1]))] = static_cast<int>(p);
    L.edges.push_back(e);
  }
  EXPECT_TRUE(assemblePatches(L).ok());
  return L;
}

/// Faces whose three corners lie on one side (a path with its end anchors) of their patch.
int collinearFaces(const Layout& L) {
  int n = 0;
  for (int f = 0; f < L.mesh.faceCount(); ++f) {
    const auto v = L.mesh.faceVertices(f);
    const Patch& p = L.patches[L.facePatch[f]];
    bool any = false;
    for (int e : p.edges) {
      const auto& chain = L.edges[e].vertices;
      any = any || std::all_of(v.begin(), v.end(), [&](int x) { return std::count(chain.begin(), chain.end(), x) > 0; });
    }
    n += any;
  }
  return n;
}

double faceArea(const RefinedMesh& m, int f) {
  const auto v = m.faceVertices(f);
  return 0.5 * (m.position(v[1]) - m.position(v[0])).cross(m.position(v[2]) - m.position(v[0])).norm();
}

/// A Voronoi source layout of a small sphere.
Layout sphereLayout(int anchors) {
  const IndexedMesh m = fx::icosphere(2);
  SourceLayoutResult r = buildSourceLayout(m, farthestPointSampling(m, anchors));
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return std::move(r.layout);
}

}  // namespace

TEST(Layout, PatchesAreAssembledFromThePathsOfAHandMadeLayout) {
  const Layout L = handMadeLayout();
  const LayoutCheck c = validateLayout(L, 2);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(c.eulerCharacteristic, 2);
  ASSERT_EQ(L.patches.size(), 4u);
  EXPECT_EQ(L.multipleLinkages(), 0);
  // Every patch: three distinct corners, its sides joining them in order, each side once in each
  // direction over all patches.
  std::vector<int> forward(L.edges.size(), 0), backward(L.edges.size(), 0);
  int faces = 0;
  for (const Patch& p : L.patches) {
    EXPECT_EQ(std::set<int>(p.corners.begin(), p.corners.end()).size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const LayoutEdge& e = L.edges[p.edges[k]];
      const int from = p.forward[k] ? e.a : e.b, to = p.forward[k] ? e.b : e.a;
      EXPECT_EQ(from, p.corners[k]);
      EXPECT_EQ(to, p.corners[(k + 1) % 3]);
      ++(p.forward[k] ? forward : backward)[p.edges[k]];
    }
    faces += p.faces;
  }
  EXPECT_EQ(faces, L.mesh.faceCount());
  for (size_t e = 0; e < L.edges.size(); ++e) {
    EXPECT_EQ(forward[e], 1) << "edge " << e;
    EXPECT_EQ(backward[e], 1) << "edge " << e;
  }
  // The faces (0, 1, 2) and (2, 1, 4) form one patch with corners 0, 1, 2.
  const int f012 = 0, f214 = 5;
  ASSERT_EQ(L.mesh.faceVertices(f214), (std::array<int, 3>{2, 1, 4}));
  EXPECT_EQ(L.facePatch[f012], L.facePatch[f214]);
  EXPECT_EQ(L.patches[L.facePatch[f214]].faces, 2);
  // The rotation at every anchor is its paths counter-clockwise seen from outside.
  for (int a = 0; a < L.anchorCount(); ++a) {
    const auto& rot = L.rotation[a];
    ASSERT_EQ(rot.size(), 3u);
    EXPECT_EQ(rot, rotationAt(L.mesh, L.edgePath, a));
    const Vec3 x = L.mesh.position(a);
    Vec3 normal = Vec3::Zero();  // the sum of the area normals of the faces at the anchor
    for (int f = 0; f < L.mesh.faceCount(); ++f) {
      const auto v = L.mesh.faceVertices(f);
      if (std::count(v.begin(), v.end(), a))
        normal += (L.mesh.position(v[1]) - L.mesh.position(v[0])).cross(L.mesh.position(v[2]) - L.mesh.position(v[0]));
    }
    // The paths' first steps, projected onto the plane across the normal, sorted by angle
    // counter-clockwise about it: the rotation up to where it starts.
    const Vec3 n = normal.normalized();
    const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
    std::vector<std::pair<double, int>> byAngle;
    for (int e : rot) {
      const int h1 = leavingHalfedge(L.mesh, L.edges[e].vertices, a);
      ASSERT_EQ(L.mesh.from(h1), a);
      const Vec3 d = L.mesh.position(L.mesh.to(h1)) - x;
      byAngle.emplace_back(std::atan2(d.dot(w), d.dot(u)), e);
    }
    std::sort(byAngle.begin(), byAngle.end());
    std::vector<int> ccw;
    for (const auto& [angle, e] : byAngle) ccw.push_back(e);
    std::rotate(ccw.begin(), std::find(ccw.begin(), ccw.end(), rot[0]), ccw.end());
    EXPECT_EQ(ccw, rot) << "anchor " << a;
  }
}

TEST(Layout, ValidateLayoutRejectsEveryBrokenInvariant) {
  const Layout good = handMadeLayout();
  ASSERT_TRUE(validateLayout(good, 2).status.ok());
  const int pathEdge = RefinedMesh::edgeOf(good.mesh.findHalfedge(4, 1));
  const std::vector<std::pair<std::string, std::function<void(Layout&)>>> breaks = {
      {"patch count off by one", [](Layout& L) { L.patches.pop_back(); }},
      {"a loop edge", [](Layout& L) { L.edges[0].b = L.edges[0].a; }},
      {"a path not ending at its anchor", [](Layout& L) { L.edges[0].b = 3; }},
      {"a path skipping its middle vertex", [](Layout& L) { L.edges[5].vertices = {2, 1}; }},
      {"a path edge unlabelled", [pathEdge](Layout& L) { L.edgePath[pathEdge] = -1; }},
      {"a free edge labelled as a path's", [](Layout& L) { L.edgePath[RefinedMesh::edgeOf(L.mesh.findHalfedge(3, 4))] = 5; }},
      {"edgePath too short", [](Layout& L) { L.edgePath.pop_back(); }},
      {"a patch's corners out of order", [](Layout& L) { std::swap(L.patches[0].corners[1], L.patches[0].corners[2]); }},
      {"a patch's sides out of order", [](Layout& L) { std::swap(L.patches[0].edges[1], L.patches[0].edges[2]); }},
      {"a patch miscounting its faces", [](Layout& L) { L.patches[0].faces += 1; }},
      {"a face in another patch", [](Layout& L) { L.facePatch[0] = (L.facePatch[0] + 1) % 4; }},
      {"facePatch too short", [](Layout& L) { L.facePatch.pop_back(); }},
      {"a rotation turning the other way", [](Layout& L) { std::reverse(L.rotation[0].begin(), L.rotation[0].end()); }},
      {"a rotation missing", [](Layout& L) { L.rotation.pop_back(); }},
      {"a rotation listing a path twice", [](Layout& L) { L.rotation[0].push_back(L.rotation[0].front()); }},
      {"a patch side in the wrong direction", [](Layout& L) { L.patches[0].forward[0] = !L.patches[0].forward[0]; }},
      {"an anchor beyond the mesh", [](Layout& L) { L.anchorVertices[0] = L.mesh.vertexCount() + 7; }},
      {"an anchor before the mesh", [](Layout& L) { L.anchorVertices[1] = -1; }},
      {"a path ending at no anchor", [](Layout& L) { L.edges[0].b = 99; }},
      {"a mesh edge naming no path", [pathEdge](Layout& L) { L.edgePath[pathEdge] = 1000; }},
  };
  for (const auto& [what, breakIt] : breaks) {
    Layout L = good;
    breakIt(L);
    const LayoutCheck c = validateLayout(L, 2);
    EXPECT_EQ(c.status.code, ErrorCode::InternalError) << what;
    EXPECT_FALSE(c.status.message.empty()) << what;
  }
  EXPECT_EQ(validateLayout(good, 0).status.code, ErrorCode::InternalError) << "the torus's Euler characteristic";
  // Vertex 4, in the middle of the path 2 - 1, made an anchor of its own: five anchors, so
  // V - E + F = 3 passes, but a path runs through an anchor.
  Layout through = good;
  through.anchorVertices.push_back(4);
  const LayoutCheck c = validateLayout(through, 3);
  EXPECT_EQ(c.status.code, ErrorCode::InternalError);
  EXPECT_NE(c.status.message.find("passes through anchor 4"), std::string::npos) << c.status.message;
}

TEST(Layout, RealLayoutsOfEveryGenusValidate) {
  for (const fx::LayoutCase& c : fx::genusZeroToTwoLayouts()) {
    const SourceLayoutResult r = buildSourceLayout(c.mesh, farthestPointSampling(c.mesh, c.anchors));
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const int chi = fx::eulerCharacteristic(c.mesh);
    const LayoutCheck check = validateLayout(r.layout, chi);
    EXPECT_TRUE(check.status.ok()) << check.status.message;
    EXPECT_EQ(check.eulerCharacteristic, chi);
    EXPECT_FALSE(validateLayout(r.layout, chi + 2).status.ok());
    // No path passes through an anchor other than its ends.
    std::set<int> anchors(r.layout.anchorVertices.begin(), r.layout.anchorVertices.end());
    for (const LayoutEdge& e : r.layout.edges)
      for (size_t k = 1; k + 1 < e.vertices.size(); ++k) EXPECT_EQ(anchors.count(e.vertices[k]), 0u);
  }
}

TEST(Layout, CheckIsomorphicComparesEdgesPatchesAndRotationsUpToAShift) {
  const Layout L = sphereLayout(8);
  EXPECT_TRUE(checkIsomorphic(L, L).ok());
  {
    Layout M = L;  // the same rotation system, each started elsewhere
    for (auto& r : M.rotation) std::rotate(r.begin(), r.begin() + 1, r.end());
    EXPECT_TRUE(checkIsomorphic(L, M).ok());
  }
  const std::vector<std::pair<std::string, std::function<void(Layout&)>>> differences = {
      {"an anchor more", [](Layout& M) { M.anchorVertices.push_back(0); M.rotation.emplace_back(); }},
      {"an edge less", [](Layout& M) { M.edges.pop_back(); }},
      {"an edge the other way", [](Layout& M) { std::swap(M.edges[0].a, M.edges[0].b); }},
      {"patches in another order", [](Layout& M) { std::swap(M.patches[0], M.patches[1]); }},
      {"a side in the other direction", [](Layout& M) { M.patches[2].forward[0] = !M.patches[2].forward[0]; }},
      {"a rotation turning the other way", [](Layout& M) {
         for (auto& r : M.rotation)
           if (r.size() >= 3) {
             std::reverse(r.begin(), r.end());
             break;
           }
       }},
  };
  for (const auto& [what, change] : differences) {
    Layout M = L;
    change(M);
    EXPECT_EQ(checkIsomorphic(L, M).code, ErrorCode::InternalError) << what;
  }
}

TEST(Layout, SplitCollinearFacesLeavesNoFaceOnOneSideOfItsPatch) {
  Layout L = handMadeLayout();
  L.faceCluster.assign(L.mesh.faceCount(), 0);
  for (int f = 0; f < L.mesh.faceCount(); ++f) L.faceCluster[f] = L.facePatch[f] + 10;
  ASSERT_EQ(collinearFaces(L), 1);
  const int faces = L.mesh.faceCount(), vertices = L.mesh.vertexCount();
  const double area = surfaceArea(L.mesh);
  EXPECT_EQ(splitCollinearFaces(L), 1);
  EXPECT_EQ(collinearFaces(L), 0);
  EXPECT_EQ(L.mesh.faceCount(), faces + 2);
  EXPECT_EQ(L.mesh.vertexCount(), vertices + 1);
  EXPECT_NEAR(surfaceArea(L.mesh), area, 1e-12 * area);
  ASSERT_EQ(static_cast<int>(L.facePatch.size()), L.mesh.faceCount());
  ASSERT_EQ(static_cast<int>(L.edgePath.size()), L.mesh.edgeCount());
  ASSERT_EQ(static_cast<int>(L.faceCluster.size()), L.mesh.faceCount());
  // The new faces stay in the patches (and clusters) of the faces they were split from.
  for (int f = 0; f < L.mesh.faceCount(); ++f) EXPECT_EQ(L.faceCluster[f], L.facePatch[f] + 10) << "face " << f;
  const LayoutCheck c = validateLayout(L, 2);
  EXPECT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(splitCollinearFaces(L), 0);
  // Real layouts: none left either, and the layout still valid.
  Layout S = sphereLayout(12);
  const int splits = splitCollinearFaces(S);
  EXPECT_GE(splits, 0);
  EXPECT_EQ(collinearFaces(S), 0);
  EXPECT_TRUE(validateLayout(S, 2).status.ok());
}

TEST(Layout, EveryInputFaceTakesThePatchHoldingMostOfIt) {
  // Without splits an input face is its own refined face.
  const Layout H = handMadeLayout();
  EXPECT_EQ(inputFacePatch(H), H.facePatch);
  EXPECT_EQ(inputFaceCluster(H), std::vector<int>(H.mesh.inputFaceCount(), -1)) << "a layout without clusters";
  // A Voronoi layout: paths cut input faces among patches.
  const Layout L = sphereLayout(10);
  ASSERT_EQ(static_cast<int>(L.faceCluster.size()), L.mesh.faceCount());
  const std::vector<int> patch = inputFacePatch(L), cluster = inputFaceCluster(L);
  ASSERT_EQ(static_cast<int>(patch.size()), L.mesh.inputFaceCount());
  ASSERT_EQ(static_cast<int>(cluster.size()), L.mesh.inputFaceCount());
  // Per input face, the area each patch / cluster holds of it.
  std::vector<std::map<int, double>> patchArea(L.mesh.inputFaceCount()), clusterArea(L.mesh.inputFaceCount());
  std::vector<std::set<int>> patchesOf(L.mesh.inputFaceCount());
  for (int f = 0; f < L.mesh.faceCount(); ++f) {
    patchArea[L.mesh.inputFace(f)][L.facePatch[f]] += faceArea(L.mesh, f);
    clusterArea[L.mesh.inputFace(f)][L.faceCluster[f]] += faceArea(L.mesh, f);
    patchesOf[L.mesh.inputFace(f)].insert(L.facePatch[f]);
  }
  auto most = [](const std::map<int, double>& m) {
    double best = -1;
    for (const auto& [l, a] : m) best = std::max(best, a);
    return best;
  };
  std::vector<char> patchOk(patch.size(), 0), clusterOk(patch.size(), 0);
  for (size_t F = 0; F < patch.size(); ++F) {
    patchOk[F] = patchArea[F].count(patch[F]) && patchArea[F].at(patch[F]) >= most(patchArea[F]);
    clusterOk[F] = clusterArea[F].count(cluster[F]) && clusterArea[F].at(cluster[F]) >= most(clusterArea[F]);
  }
  int shared = 0;
  for (size_t F = 0; F < patch.size(); ++F) {
    EXPECT_TRUE(patchOk[F]) << "input face " << F << " is not in the patch holding most of it";
    EXPECT_TRUE(clusterOk[F]) << "input face " << F << " is not in the cluster holding most of it";
    shared += patchesOf[F].size() > 1;
  }
  EXPECT_GT(shared, 0) << "no input face was cut among patches: the test proves nothing";
}

TEST(Layout, ChainsRotationsAndNames) {
  const Layout L = handMadeLayout();
  const std::vector<int>& chain = L.edges[5].vertices;  // 2 -> 4 -> 1
  const double a = (L.mesh.position(4) - L.mesh.position(2)).norm(), b = (L.mesh.position(1) - L.mesh.position(4)).norm();
  EXPECT_NEAR(chainLength(L.mesh, chain), a + b, 1e-15);
  const std::vector<double> t = chainFractions(L.mesh, chain);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_NEAR(t[1], a / (a + b), 1e-15);
  EXPECT_EQ(t[2], 1.0);
  EXPECT_EQ(chainFractions(L.mesh, {3, 3, 3}), (std::vector<double>{0.0, 0.5, 1.0})) << "no length: by index";
  const int out = leavingHalfedge(L.mesh, chain, 2), in = leavingHalfedge(L.mesh, chain, 1);
  EXPECT_EQ(L.mesh.from(out), 2);
  EXPECT_EQ(L.mesh.to(out), 4);
  EXPECT_EQ(L.mesh.from(in), 1);
  EXPECT_EQ(L.mesh.to(in), 4);
  EXPECT_TRUE(rotationAt(L.mesh, L.edgePath, 4).size() == 2u) << "vertex 4 is on one path, twice";
  EXPECT_EQ(anchorLabel({"nose", "tail"}, 1), "'tail'");
  EXPECT_EQ(anchorLabel({"nose"}, 3), "3");
  EXPECT_EQ(anchorLabel({}, 0), "0");
  Layout M = L;
  M.edges.push_back(M.edges[0]);
  M.edges.push_back(M.edges[3]);
  std::swap(M.edges.back().a, M.edges.back().b);  // the same pair the other way round
  M.edges.push_back(M.edges[3]);
  EXPECT_EQ(M.multipleLinkages(), 2);
}
