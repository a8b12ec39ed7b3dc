// The flip test of mapped triangles (target_normals.h): face normals, the normal cone at edges and
// vertices, a consistently oriented image not flipped, a mirrored or folded one flipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cbd/target_normals.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

IndexedMesh bumpySphere() {
  IndexedMesh m = fx::icosphere(2);
  for (auto& p : m.positions) p *= 1.0 + 0.15 * std::sin(5 * p.x()) * std::cos(4 * p.y());
  return m;
}

FacePoint corner(const IndexedMesh& m, int f, int v) {
  const auto& t = m.faces[f];
  return {f, Vec3::Unit(static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin()))};
}

/// The face across the edge from t[k] to t[k+1] of face f, and its corner off that edge.
std::pair<int, int> across(const IndexedMesh& m, int f, int k) {
  const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
  for (int g = 0; g < m.faceCount(); ++g)
    for (int j = 0; j < 3; ++j)
      if (m.faces[g][j] == b && m.faces[g][(j + 1) % 3] == a) return {g, m.faces[g][(j + 2) % 3]};
  return {-1, -1};
}

}  // namespace

TEST(TargetNormals, FaceNormalsAreUnitOutwardAndZeroForADegenerateFace) {
  const IndexedMesh s = bumpySphere();
  const std::vector<Vec3> n = faceNormals(s);
  ASSERT_EQ(static_cast<int>(n.size()), s.faceCount());
  for (int f = 0; f < s.faceCount(); ++f) {
    const auto& t = s.faces[f];
    EXPECT_NEAR(n[f].norm(), 1.0, 1e-12);
    EXPECT_GT(n[f].dot(s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]), 0.0) << "face " << f;
  }
  // The cube's are its sides' axes exactly.
  const IndexedMesh c = fx::cube();
  const std::vector<Vec3> cn = faceNormals(c);
  for (int f = 0; f < c.faceCount(); ++f) {
    const auto& t = c.faces[f];
    const Vec3 centre = (c.positions[t[0]] + c.positions[t[1]] + c.positions[t[2]]) / 3;
    int axis;
    centre.cwiseAbs().maxCoeff(&axis);
    EXPECT_EQ(cn[f], Vec3::Unit(axis) * (centre[axis] > 0 ? 1.0 : -1.0)) << "face " << f;
  }
  IndexedMesh d = fx::tetrahedron();
  d.faces[0] = {0, 1, 1};
  EXPECT_EQ(faceNormals(d)[0], Vec3::Zero());
}

TEST(TargetNormals, AConsistentlyOrientedImageIsNotFlippedItsMirrorIs) {
  // The identity of a bumpy sphere, every corner of every face located at that corner: each
  // triangle as it is is not flipped, the same triangle with two corners swapped is.
  const IndexedMesh m = bumpySphere();
  const TargetNormals tn(m);
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    const FacePoint p0 = corner(m, f, t[0]), p1 = corner(m, f, t[1]), p2 = corner(m, f, t[2]);
    const Vec3 &x0 = m.positions[t[0]], &x1 = m.positions[t[1]], &x2 = m.positions[t[2]];
    EXPECT_FALSE(tn.flipped(x0, x1, x2, p0, p1, p2)) << "face " << f;
    EXPECT_TRUE(tn.flipped(x0, x2, x1, p0, p2, p1)) << "face " << f << " mirrored";
  }
}

TEST(TargetNormals, TheIdentityOfACubeIsNotFlippedWhicheverFaceHoldsEachCorner) {
  // At a corner of the cube three sides meet at right angles: a triangle's corner may be located
  // in any face around it, and the normal cone still holds the triangle's own side's normal.
  const IndexedMesh c = fx::cube();
  const TargetNormals tn(c);
  std::vector<std::vector<int>> star(c.vertexCount());
  for (int f = 0; f < c.faceCount(); ++f)
    for (int v : c.faces[f]) star[v].push_back(f);
  int checked = 0;
  for (const auto& t : c.faces)
    for (int f0 : star[t[0]])
      for (int f1 : star[t[1]])
        for (int f2 : star[t[2]]) {
          EXPECT_FALSE(tn.flipped(c.positions[t[0]], c.positions[t[1]], c.positions[t[2]], corner(c, f0, t[0]),
                                  corner(c, f1, t[1]), corner(c, f2, t[2])));
          ++checked;
        }
  EXPECT_GE(checked, 12 * 27);
}

TEST(TargetNormals, ATriangleFoldedOverAnEdgeIsFlipped) {
  // For every face (a, b, c) and each of its edges (a, b): c's image thrown into the face beyond
  // that edge (at its centre), so the triangle turns over the edge.
  const IndexedMesh m = bumpySphere();
  const TargetNormals tn(m);
  for (int f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto& t = m.faces[f];
      const int a = t[k], b = t[(k + 1) % 3];
      const auto [g, d] = across(m, f, k);
      ASSERT_GE(g, 0);
      const FacePoint beyond{g, Vec3::Constant(1.0 / 3)};
      const Vec3 folded = fx::pointOn(m, beyond);
      EXPECT_TRUE(tn.flipped(m.positions[a], m.positions[b], folded, corner(m, f, a), corner(m, f, b), beyond))
          << "face " << f << " folded over its edge " << a << "-" << b;
      // Its mirror image lies flat on the surface: not flipped.
      EXPECT_FALSE(tn.flipped(m.positions[b], m.positions[a], folded, corner(m, g, b), corner(m, g, a), beyond));
    }
}

TEST(TargetNormals, TheNormalConeAtAVertexAndAnEdge) {
  const IndexedMesh c = fx::cube();
  const TargetNormals tn(c);
  // The face of the side z = -1 on the edge from corner 0 = (-1, -1, -1), where the sides
  // x, y, z = -1 meet, to corner 1 = (1, -1, -1).
  int f = -1;
  for (int g = 0; g < c.faceCount() && f < 0; ++g)
    if (tn.faceNormals()[g] == Vec3(0, 0, -1) && std::count(c.faces[g].begin(), c.faces[g].end(), 0) &&
        std::count(c.faces[g].begin(), c.faces[g].end(), 1))
      f = g;
  ASSERT_GE(f, 0);
  const FacePoint atVertex = corner(c, f, 0);
  EXPECT_EQ(tn.closestAt(atVertex, Vec3(-1, 0.1, 0.2)), Vec3(-1, 0, 0));
  EXPECT_EQ(tn.closestAt(atVertex, Vec3(0.1, -1, 0.2)), Vec3(0, -1, 0));
  EXPECT_EQ(tn.closestAt(atVertex, Vec3(0.1, 0.2, -1)), Vec3(0, 0, -1));
  // Inside the face: its own normal, whatever is asked.
  const FacePoint inside{f, Vec3::Constant(1.0 / 3)};
  EXPECT_EQ(tn.closestAt(inside, Vec3(-1, 0, 0)), Vec3(0, 0, -1));
  // On the edge 0-1, where the sides z = -1 and y = -1 meet: the two faces of the edge only,
  // never the side x = -1 that touches its end.
  const auto& t = c.faces[f];
  FacePoint onEdge{f, Vec3::Zero()};
  onEdge.bary[std::find(t.begin(), t.end(), 0) - t.begin()] = 0.5;
  onEdge.bary[std::find(t.begin(), t.end(), 1) - t.begin()] = 0.5;
  EXPECT_EQ(tn.closestAt(onEdge, Vec3(0.1, -1, 0)), Vec3(0, -1, 0));
  // The sides x = -1 and x = +1 touch the edge's ends only: not in its cone.
  EXPECT_EQ(tn.closestAt(onEdge, Vec3(-1, -0.1, -0.2)), Vec3(0, 0, -1));
  EXPECT_EQ(tn.closestAt(onEdge, Vec3(1, -0.1, -0.2)), Vec3(0, 0, -1));
  // A point on no face has no normal.
  EXPECT_EQ(tn.closestAt(FacePoint{}, Vec3(1, 0, 0)), Vec3::Zero());
}
