// The half-edge mesh paths are cut into (refined_mesh.h): its connectivity, and edge splits that
// keep the surface (the same area over every input face, the same Euler characteristic, every
// face inside its input face and facing the same way) and every vertex's place on the input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>

#include "cbd/refined_mesh.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

double area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

Vec3 onInput(const IndexedMesh& in, int face, const Vec3& bary) { return fx::pointOn(in, FacePoint{face, bary}); }

/// Every half-edge invariant the header states or the stages rely on.
::testing::AssertionResult connectivityHolds(const RefinedMesh& m) {
  auto fail = [](const std::string& what) { return ::testing::AssertionFailure() << what; };
  if (m.halfedgeCount() != 2 * m.edgeCount()) return fail("halfedges not in pairs");
  if (2 * m.edgeCount() != 3 * m.faceCount()) return fail("not a closed triangle mesh: 2E != 3F");
  for (int h = 0; h < m.halfedgeCount(); ++h) {
    const std::string at = "halfedge " + std::to_string(h) + ": ";
    if (RefinedMesh::twin(RefinedMesh::twin(h)) != h || RefinedMesh::edgeOf(h) != RefinedMesh::edgeOf(h ^ 1))
      return fail(at + "twin");
    if (m.next(m.next(m.next(h))) != h) return fail(at + "face is not a triangle");
    if (m.face(m.next(h)) != m.face(h)) return fail(at + "next leaves the face");
    if (m.to(h) != m.from(m.next(h))) return fail(at + "next does not start where h ends");
    if (m.from(h) != m.to(RefinedMesh::twin(h))) return fail(at + "twin does not run back");
    if (m.face(h) == m.face(RefinedMesh::twin(h))) return fail(at + "both sides in one face");
  }
  for (int f = 0; f < m.faceCount(); ++f)
    if (m.face(m.faceHalfedge(f)) != f) return fail("face " + std::to_string(f) + " has a halfedge of another face");
  // Around every vertex, rotateCCW visits each of its outgoing halfedges once.
  std::vector<int> outgoing(m.vertexCount(), 0);
  for (int h = 0; h < m.halfedgeCount(); ++h) ++outgoing[m.from(h)];
  for (int v = 0; v < m.vertexCount(); ++v) {
    const int start = m.outgoing(v);
    if (start < 0) {
      if (outgoing[v] != 0) return fail("vertex " + std::to_string(v) + " has halfedges but no outgoing one");
      continue;
    }
    int n = 0, h = start;
    do {
      if (m.from(h) != v) return fail("rotation at " + std::to_string(v) + " leaves the vertex");
      h = m.rotateCCW(h);
      if (++n > outgoing[v]) return fail("rotation at " + std::to_string(v) + " does not close");
    } while (h != start);
    if (n != outgoing[v]) return fail("rotation at " + std::to_string(v) + " misses a halfedge");
  }
  return ::testing::AssertionSuccess();
}

/// Every vertex where its location says, every face inside its input face (its corners'
/// barycentric coordinates in it in [0, 1]) and facing the same way, each input face's area
/// the sum of its pieces'.
::testing::AssertionResult surfaceKept(const RefinedMesh& m, const IndexedMesh& in) {
  const double tol = 1e-12 * boundingBoxDiagonal(in);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const SurfacePoint& p = m.location(v);
    if (p.face < 0 || p.face >= in.faceCount()) return ::testing::AssertionFailure() << "vertex " << v << " on no face";
    if (p.bary.minCoeff() < -1e-12 || std::abs(p.bary.sum() - 1) > 1e-12)
      return ::testing::AssertionFailure() << "vertex " << v << ": barycentric " << p.bary.transpose();
    if ((onInput(in, p.face, p.bary) - m.position(v)).norm() > tol)
      return ::testing::AssertionFailure() << "vertex " << v << " is not where its location says";
  }
  // An edge is on an input edge exactly when both its ends are on that edge of an input face
  // beside it (a barycentric coordinate zero at both).
  for (int e = 0; e < m.edgeCount(); ++e) {
    const int F = m.inputFace(m.face(2 * e));
    const Vec3 b0 = m.baryIn(m.to(2 * e), F), b1 = m.baryIn(m.to(2 * e + 1), F);
    bool along = false;
    for (int k = 0; k < 3; ++k) along = along || (std::abs(b0[k]) < 1e-12 && std::abs(b1[k]) < 1e-12);
    if (along != m.onInputEdge(e))
      return ::testing::AssertionFailure() << "edge " << e << (along ? " lies on" : " does not lie on")
                                           << " an input edge, onInputEdge says otherwise";
  }
  std::vector<double> pieces(in.faceCount(), 0.0);
  for (int f = 0; f < m.faceCount(); ++f) {
    const int F = m.inputFace(f);
    const auto c = m.faceVertices(f);
    for (int v : c) {
      const Vec3 b = m.baryIn(v, F);
      if (b.minCoeff() < -1e-12 || std::abs(b.sum() - 1) > 1e-12 || (onInput(in, F, b) - m.position(v)).norm() > tol)
        return ::testing::AssertionFailure() << "corner " << v << " of face " << f << " is not on its input face " << F;
    }
    const auto& t = in.faces[F];
    const Vec3 n = (m.position(c[1]) - m.position(c[0])).cross(m.position(c[2]) - m.position(c[0]));
    const Vec3 N = (in.positions[t[1]] - in.positions[t[0]]).cross(in.positions[t[2]] - in.positions[t[0]]);
    if (n.dot(N) <= 0 || n.cross(N).norm() > 1e-9 * n.norm() * N.norm())
      return ::testing::AssertionFailure() << "face " << f << " does not lie in its input face " << F << " facing its way";
    pieces[F] += area(m.position(c[0]), m.position(c[1]), m.position(c[2]));
  }
  for (int F = 0; F < in.faceCount(); ++F) {
    const auto& t = in.faces[F];
    const double whole = area(in.positions[t[0]], in.positions[t[1]], in.positions[t[2]]);
    if (std::abs(pieces[F] - whole) > 1e-12 * whole)
      return ::testing::AssertionFailure() << "input face " << F << ": pieces " << pieces[F] << ", whole " << whole;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

TEST(RefinedMesh, IsTheHalfedgeFormOfTheInput) {
  for (const IndexedMesh& in : {fx::icosphere(1), fx::torus(2.0, 0.7, 12, 8)}) {
    const RefinedMesh m(in);
    EXPECT_EQ(m.vertexCount(), in.vertexCount());
    EXPECT_EQ(m.faceCount(), in.faceCount());
    EXPECT_EQ(m.edgeCount(), 3 * in.faceCount() / 2);
    EXPECT_EQ(m.inputVertexCount(), in.vertexCount());
    EXPECT_EQ(m.inputFaceCount(), in.faceCount());
    EXPECT_TRUE(connectivityHolds(m));
    EXPECT_TRUE(surfaceKept(m, in));
    for (int f = 0; f < in.faceCount(); ++f) {
      EXPECT_EQ(m.faceVertices(f), in.faces[f]) << "face " << f;
      EXPECT_EQ(m.inputFace(f), f);
      for (int k = 0; k < 3; ++k) {
        const int a = in.faces[f][k], b = in.faces[f][(k + 1) % 3];
        const int h = m.findHalfedge(a, b);
        ASSERT_GE(h, 0);
        EXPECT_EQ(m.from(h), a);
        EXPECT_EQ(m.to(h), b);
        EXPECT_EQ(m.face(h), f);
        EXPECT_TRUE(m.onInputEdge(RefinedMesh::edgeOf(h)));
      }
    }
    for (int v = 0; v < in.vertexCount(); ++v) {
      EXPECT_EQ(m.inputVertex(v), v);
      EXPECT_EQ(m.position(v), in.positions[v]);
      EXPECT_EQ(m.findHalfedge(v, v), -1);
    }
    EXPECT_NEAR(surfaceArea(m), surfaceArea(in), 1e-12 * surfaceArea(in));
  }
}

TEST(RefinedMesh, RotateCCWTurnsCounterClockwiseSeenFromOutside) {
  const IndexedMesh in = fx::icosphere(2);
  const RefinedMesh m(in);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const int start = m.outgoing(v);
    int h = start;
    do {
      const int g = m.rotateCCW(h);
      const Vec3 a = m.position(m.to(h)) - m.position(v), b = m.position(m.to(g)) - m.position(v);
      EXPECT_GT(a.cross(b).dot(m.position(v)), 0.0) << "at vertex " << v;
      h = g;
    } while (h != start);
  }
}

TEST(RefinedMesh, ASplitMakesWhatItsRecordSays) {
  const IndexedMesh in = fx::icosphere(1);
  RefinedMesh m(in);
  const int h = m.findHalfedge(in.faces[0][0], in.faces[0][1]);
  const int a = m.from(h), b = m.to(h), c = m.to(m.next(h)), d = m.to(m.next(RefinedMesh::twin(h)));
  const int faces = m.faceCount(), edges = m.edgeCount(), vertices = m.vertexCount();
  const double t = 0.3;
  const int v = m.splitEdge(h, t);
  EXPECT_EQ(v, vertices);
  EXPECT_EQ(m.vertexCount(), vertices + 1);
  EXPECT_EQ(m.edgeCount(), edges + 3);
  EXPECT_EQ(m.faceCount(), faces + 2);
  EXPECT_EQ(m.inputVertex(v), -1);
  EXPECT_LT((m.position(v) - ((1 - t) * in.positions[a] + t * in.positions[b])).norm(), 1e-15);
  // h keeps running from a, now to the new vertex.
  EXPECT_EQ(m.from(h), a);
  EXPECT_EQ(m.to(h), v);
  const RefinedMesh::SplitRecord& r = m.lastSplit();
  EXPECT_EQ(r.halfedge, h);
  EXPECT_EQ(r.vertex, v);
  auto joins = [&](int e, int x, int y) {
    return std::minmax(m.to(2 * e), m.to(2 * e + 1)) == std::minmax(x, y);
  };
  EXPECT_TRUE(joins(r.edgeContinued, v, b));
  EXPECT_TRUE(joins(r.edgeDiagonalA, v, c));
  EXPECT_TRUE(joins(r.edgeDiagonalB, v, d));
  EXPECT_EQ(std::minmax(r.faceNewA, r.faceNewB), std::minmax(faces, faces + 1));
  // The split edge goes on along the input edge; the diagonals lie inside input faces.
  EXPECT_TRUE(m.onInputEdge(RefinedMesh::edgeOf(h)));
  EXPECT_TRUE(m.onInputEdge(r.edgeContinued));
  EXPECT_FALSE(m.onInputEdge(r.edgeDiagonalA));
  EXPECT_FALSE(m.onInputEdge(r.edgeDiagonalB));
  // On the input edge a-b at t: one coordinate 0, the others 1 - t and t.
  const SurfacePoint& p = m.location(v);
  const auto& F = in.faces[p.face];
  const int ka = static_cast<int>(std::find(F.begin(), F.end(), a) - F.begin());
  const int kb = static_cast<int>(std::find(F.begin(), F.end(), b) - F.begin());
  ASSERT_LT(ka, 3);
  ASSERT_LT(kb, 3);
  EXPECT_NEAR(p.bary[ka], 1 - t, 1e-15);
  EXPECT_NEAR(p.bary[kb], t, 1e-15);
  EXPECT_TRUE(connectivityHolds(m));
  EXPECT_TRUE(surfaceKept(m, in));
  // A diagonal split puts a vertex inside an input face: every coordinate positive.
  const int diagonal = r.edgeDiagonalA;
  const int w = m.splitEdge(2 * diagonal, 0.5);
  EXPECT_GT(m.location(w).bary.minCoeff(), 0.1);
  EXPECT_FALSE(m.onInputEdge(diagonal));
  EXPECT_FALSE(m.onInputEdge(m.lastSplit().edgeContinued)) << "a diagonal goes on as a diagonal";
  EXPECT_TRUE(surfaceKept(m, in));
}

TEST(RefinedMesh, ManySplitsKeepTheSurfaceItsAreaAndItsEulerCharacteristic) {
  std::mt19937 rng(11);
  for (const IndexedMesh& in : {fx::icosphere(2), fx::torus(2.0, 0.7, 16, 10), fx::holedPlate(2, 2, 5)}) {
    const MeshReport before = validateMesh(in, "input");
    ASSERT_TRUE(before.status.ok()) << before.status.message;
    RefinedMesh m(in);
    const int chi = m.vertexCount() - m.edgeCount() + m.faceCount();
    EXPECT_EQ(chi, 2 - 2 * before.genus);
    for (int i = 0; i < 300; ++i) {
      const int h = std::uniform_int_distribution<int>(0, m.halfedgeCount() - 1)(rng);
      const double t = std::uniform_real_distribution<double>(0.1, 0.9)(rng);
      const int v = m.splitEdge(h, t);
      ASSERT_EQ(m.to(h), v);
      ASSERT_EQ(m.vertexCount() - m.edgeCount() + m.faceCount(), chi) << "after split " << i;
      if (i % 100 == 99) {
        ASSERT_TRUE(connectivityHolds(m)) << "after split " << i;
        ASSERT_TRUE(surfaceKept(m, in)) << "after split " << i;
      }
    }
    EXPECT_NEAR(surfaceArea(m), surfaceArea(in), 1e-12 * surfaceArea(in));
    // Its flat copy is a valid closed surface of the same genus, the input vertices in place.
    const IndexedMesh out = m.toIndexed();
    const MeshReport after = validateMesh(out, "refined");
    EXPECT_TRUE(after.status.ok()) << after.status.message;
    EXPECT_EQ(after.genus, before.genus);
    EXPECT_EQ(fx::eulerCharacteristic(out), chi);
    for (int v = 0; v < in.vertexCount(); ++v) EXPECT_EQ(out.positions[v], in.positions[v]);
  }
}

TEST(RefinedMesh, UndoingSplitsGivesBackTheMeshAsItWasIndicesIncluded) {
  // Everything a split touches, compared entry by entry: every halfedge's ends, next and face,
  // every face's halfedge and input face, every vertex's position, place and outgoing halfedge.
  auto same = [](const RefinedMesh& a, const RefinedMesh& b) {
    if (a.vertexCount() != b.vertexCount() || a.halfedgeCount() != b.halfedgeCount() || a.faceCount() != b.faceCount())
      return false;
    for (int h = 0; h < a.halfedgeCount(); ++h)
      if (a.to(h) != b.to(h) || a.next(h) != b.next(h) || a.face(h) != b.face(h)) return false;
    for (int e = 0; e < a.edgeCount(); ++e)
      if (a.onInputEdge(e) != b.onInputEdge(e)) return false;
    for (int f = 0; f < a.faceCount(); ++f)
      if (a.faceHalfedge(f) != b.faceHalfedge(f) || a.inputFace(f) != b.inputFace(f)) return false;
    for (int v = 0; v < a.vertexCount(); ++v)
      if (a.position(v) != b.position(v) || a.outgoing(v) != b.outgoing(v) || a.location(v).face != b.location(v).face ||
          a.location(v).bary != b.location(v).bary)
        return false;
    return true;
  };
  std::mt19937 rng(5);
  for (const IndexedMesh& in : {fx::icosphere(2), fx::torus(2.0, 0.7, 16, 10)}) {
    RefinedMesh m(in);
    auto splitSome = [&](int n) {
      for (int i = 0; i < n; ++i)
        m.splitEdge(std::uniform_int_distribution<int>(0, m.halfedgeCount() - 1)(rng),
                    std::uniform_real_distribution<double>(0.1, 0.9)(rng));
    };
    splitSome(40);
    const RefinedMesh after40 = m;
    EXPECT_EQ(m.splitCount(), 40);
    splitSome(60);
    EXPECT_FALSE(same(m, after40));
    m.undoSplits(40);
    EXPECT_EQ(m.splitCount(), 40);
    EXPECT_TRUE(same(m, after40)) << "back to 40 splits";
    EXPECT_TRUE(connectivityHolds(m));
    EXPECT_TRUE(surfaceKept(m, in));
    EXPECT_EQ(m.lastSplit().vertex, after40.lastSplit().vertex);
    // Splitting again from there works as on a mesh that never had the undone splits.
    splitSome(30);
    EXPECT_TRUE(connectivityHolds(m));
    EXPECT_TRUE(surfaceKept(m, in));
    m.undoSplits(0);
    EXPECT_TRUE(same(m, RefinedMesh(in))) << "back to the input";
  }
}

TEST(RefinedMesh, UnreferencedVerticesStayIsolated) {
  IndexedMesh in = fx::tetrahedron();
  in.positions.push_back(Vec3(7, 7, 7));  // vertex 4, on no face
  RefinedMesh m(in);
  EXPECT_EQ(m.vertexCount(), 5);
  EXPECT_EQ(m.outgoing(4), -1);
  EXPECT_EQ(m.inputVertex(4), 4);
  EXPECT_EQ(m.findHalfedge(4, 0), -1);
  EXPECT_TRUE(connectivityHolds(m));
  m.splitEdge(0, 0.5);
  const IndexedMesh out = m.toIndexed();
  EXPECT_EQ(out.positions[4], Vec3(7, 7, 7));
  EXPECT_EQ(out.vertexCount(), 6);
  EXPECT_EQ(out.faceCount(), 6);
}
