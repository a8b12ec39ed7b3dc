// The path tracing operator of Sec. 4 (path_tracer.h): the adaptive edge-node count, traced paths
// that join their ends over the surface no shorter than the straight line, cut into the mesh as
// chains of edges; anchors and committed paths that later paths never pass through or cross;
// walls of labelled edges, face filters, the sector a path leaves an anchor in, release and recommit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cbd/layout.h"
#include "cbd/path_tracer.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

PathQuery query(int from, int to) {
  PathQuery q;
  q.source = from;
  q.goals.push_back({to, {}, 0});
  return q;
}

/// A traced path joins its source to its goal, its length is the sum of its steps and no shorter
/// than the straight line.
void expectJoins(const PathTracer& t, const TracedPath& p, int from, int to) {
  ASSERT_TRUE(p.found);
  ASSERT_GE(p.nodes.size(), 2u);
  EXPECT_EQ(p.nodes.front(), from);
  EXPECT_EQ(p.nodes.back(), to);
  double length = 0;
  for (size_t i = 1; i < p.nodes.size(); ++i) length += (t.nodePosition(p.nodes[i]) - t.nodePosition(p.nodes[i - 1])).norm();
  EXPECT_NEAR(p.length, length, 1e-12 * length);
  EXPECT_GE(p.length, (t.mesh().position(from) - t.mesh().position(to)).norm() * (1 - 1e-12));
}

/// A committed chain: its steps are mesh edges owned by the path, its vertices on the input
/// surface where their locations say, its length the traced path's.
void expectCommitted(const PathTracer& t, const IndexedMesh& in, const TracedPath& p, int id, const std::vector<int>& chain) {
  const RefinedMesh& m = t.mesh();
  ASSERT_GE(chain.size(), 2u);
  EXPECT_EQ(chain.front(), p.nodes.front());
  EXPECT_EQ(chain.back(), p.nodes.back());
  EXPECT_EQ(chain.size(), p.nodes.size());
  for (size_t k = 0; k + 1 < chain.size(); ++k) {
    const int h = m.findHalfedge(chain[k], chain[k + 1]);
    ASSERT_GE(h, 0) << "step " << k << " is not an edge";
    EXPECT_EQ(t.pathOfEdge(RefinedMesh::edgeOf(h)), id);
    EXPECT_EQ(t.edgeNodeCount(RefinedMesh::edgeOf(h)), 0) << "a path edge keeps edge nodes";
  }
  for (size_t k = 1; k + 1 < chain.size(); ++k) {
    EXPECT_EQ(t.pathCount(chain[k]), 1);
    const SurfacePoint& s = m.location(chain[k]);
    EXPECT_LT((fx::pointOn(in, FacePoint{s.face, s.bary}) - m.position(chain[k])).norm(), 1e-12);
  }
  EXPECT_NEAR(chainLength(m, chain), p.length, 1e-12 * p.length);
}

/// The unit icosphere with six anchors at the axis points, in the order +z, +x, -z, -x, +y, -y.
struct AxisSphere {
  IndexedMesh in = fx::icosphere(3);
  RefinedMesh mesh{in};
  std::vector<int> anchor;
  AxisSphere() {
    for (const Vec3& d : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 0, -1), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)})
      anchor.push_back(fx::nearestVertex(in, d));
  }
};

}  // namespace

TEST(PathTracer, EdgeNodesFollowTheAdaptiveFormula) {
  // Few meridians and many rings: long slivers beside short edges; a sphere stretched fourfold:
  // edges of every length ratio.
  IndexedMesh stretched = fx::icosphere(2);
  for (auto& p : stretched.positions) p.x() *= 4;
  for (const IndexedMesh& in : {fx::uvSphere(8, 14), stretched}) {
    RefinedMesh m(in);
    for (const EdgeNodeOptions& o : {EdgeNodeOptions{3, true, 48}, EdgeNodeOptions{1, true, 48}, EdgeNodeOptions{3, true, 4},
                                     EdgeNodeOptions{5, true, 48}, EdgeNodeOptions{2, false, 48}}) {
      const PathTracer t(m, o);
      int64_t nodes = m.vertexCount();
      int above = 0;
      for (int e = 0; e < m.edgeCount(); ++e) {
        double sum = 0;
        int count = 0;
        for (int v : {m.to(2 * e), m.to(2 * e + 1)}) {
          const int start = m.outgoing(v);
          int h = start;
          do {
            if (RefinedMesh::edgeOf(h) != e || v == m.to(2 * e)) sum += m.edgeLength(RefinedMesh::edgeOf(h)), ++count;
            h = m.rotateCCW(h);
          } while (h != start);
        }
        int expected = o.minEdgeNodes;
        if (o.adaptive) expected = std::max(expected, static_cast<int>(std::lround(o.minEdgeNodes * m.edgeLength(e) / (sum / count))));
        expected = std::min(expected, o.maxEdgeNodes);
        EXPECT_EQ(t.edgeNodeCount(e), expected) << "edge " << e << " (b = " << o.minEdgeNodes << ")";
        above += expected > o.minEdgeNodes;
        nodes += t.edgeNodeCount(e);
      }
      EXPECT_EQ(t.nodeCount(), nodes);
      if (o.adaptive && o.minEdgeNodes == 3) {
        EXPECT_GT(above, 0) << "no edge long enough for more than b nodes";
      }
    }
  }
}

TEST(PathTracer, APathJoinsItsEndsOverTheSurfaceAndIsCutInAsEdges) {
  AxisSphere s;
  PathTracer t(s.mesh, EdgeNodeOptions{});
  for (int a : s.anchor) t.setAnchor(a, true);
  const int north = s.anchor[0], east = s.anchor[1];
  const TracedPath p = t.trace(query(north, east));
  expectJoins(t, p, north, east);
  // A quarter of a great circle, to within the edge-node spacing.
  EXPECT_LT(p.length, M_PI / 2 * 1.05);
  std::vector<int> chain;
  ASSERT_TRUE(t.commit(p, 0, chain).ok());
  expectCommitted(t, s.in, p, 0, chain);
  EXPECT_EQ(t.pathCount(north), 1);
  EXPECT_EQ(t.pathCount(east), 1);
  EXPECT_EQ(static_cast<int>(t.edgePath().size()), s.mesh.edgeCount());
  // A second path from the same anchor: anchors count every path ending there.
  const TracedPath q = t.trace(query(north, s.anchor[4]));
  expectJoins(t, q, north, s.anchor[4]);
  std::vector<int> chain2;
  ASSERT_TRUE(t.commit(q, 1, chain2).ok());
  expectCommitted(t, s.in, q, 1, chain2);
  EXPECT_EQ(t.pathCount(north), 2);
  for (size_t k = 1; k + 1 < chain2.size(); ++k)
    EXPECT_EQ(std::count(chain.begin(), chain.end(), chain2[k]), 0) << "the paths share a vertex";
  // Only paths shorter than maxLength are wanted.
  PathQuery bounded = query(east, s.anchor[2]);
  const TracedPath unbounded = t.trace(bounded);
  ASSERT_TRUE(unbounded.found);
  bounded.maxLength = 0.99 * unbounded.length;
  EXPECT_FALSE(t.trace(bounded).found);
  bounded.maxLength = 1.01 * unbounded.length;
  EXPECT_EQ(t.trace(bounded).nodes, unbounded.nodes);
  // A path that was not found cannot be committed.
  std::vector<int> none;
  EXPECT_EQ(t.commit(TracedPath{}, 2, none).code, ErrorCode::InternalError);
}

TEST(PathTracer, APathEdgeIsNeverWalkedAlongAgain) {
  // Two adjacent anchors joined by their edge: a second path between them (a multiple linkage)
  // goes round through the faces beside it, never along it.
  const IndexedMesh in = fx::icosphere(2);
  RefinedMesh m(in);
  PathTracer t(m, EdgeNodeOptions{});
  const int a = in.faces[0][0], b = in.faces[0][1];
  t.setAnchor(a, true);
  t.setAnchor(b, true);
  const TracedPath first = t.trace(query(a, b));
  ASSERT_EQ(first.nodes, (std::vector<int64_t>{a, b}));
  std::vector<int> chain;
  ASSERT_TRUE(t.commit(first, 0, chain).ok());
  const TracedPath second = t.trace(query(a, b));
  expectJoins(t, second, a, b);
  EXPECT_GT(second.nodes.size(), 2u);
  EXPECT_GT(second.length, first.length * 1.1);
  std::vector<int> chain2;
  ASSERT_TRUE(t.commit(second, 1, chain2).ok());
  expectCommitted(t, in, second, 1, chain2);
  EXPECT_EQ(t.pathCount(a), 2);
}

TEST(PathTracer, NoPathPassesThroughAnAnchorOtherThanItsEnds) {
  // Along the torus's inner equator (a shortest line there: moving off it lengthens the ring)
  // the path from vertex (0, v = pi) to (3, pi) runs through (1, pi) and (2, pi). Made an anchor,
  // (1, pi) is avoided at some cost in length.
  const int nu = 40, nv = 12;
  const IndexedMesh in = fx::torus(2.0, 0.7, nu, nv);
  auto id = [&](int i, int j) { return i * nv + j; };
  RefinedMesh m(in);
  PathTracer t(m, EdgeNodeOptions{});
  const int a = id(0, nv / 2), b = id(3, nv / 2), blocker = id(1, nv / 2);
  t.setAnchor(a, true);
  t.setAnchor(b, true);
  const TracedPath direct = t.trace(query(a, b));
  expectJoins(t, direct, a, b);
  ASSERT_EQ(std::count(direct.nodes.begin(), direct.nodes.end(), blocker), 1) << "the fixture's path avoids the vertex already";
  t.setAnchor(blocker, true);
  EXPECT_TRUE(t.isAnchor(blocker));
  const TracedPath around = t.trace(query(a, b));
  expectJoins(t, around, a, b);
  EXPECT_EQ(std::count(around.nodes.begin(), around.nodes.end(), blocker), 0);
  EXPECT_GT(around.length, direct.length);
  // ... but it may be a goal.
  const TracedPath to = t.trace(query(a, blocker));
  expectJoins(t, to, a, blocker);
  t.setAnchor(blocker, false);
  EXPECT_FALSE(t.isAnchor(blocker));
  EXPECT_EQ(t.trace(query(a, b)).nodes, direct.nodes);
}

TEST(PathTracer, ALoopOfPathsCannotBeCrossedUntilReleased) {
  // Paths +z -> +x -> -z -> -x -> +z make a closed loop round the sphere (near the plane y = 0):
  // +y and -y are on opposite sides, and no later path may cross a path edge or vertex.
  AxisSphere s;
  PathTracer t(s.mesh, EdgeNodeOptions{});
  for (int a : s.anchor) t.setAnchor(a, true);
  const int plusY = s.anchor[4], minusY = s.anchor[5];
  const TracedPath before = t.trace(query(plusY, minusY));
  expectJoins(t, before, plusY, minusY);
  std::vector<std::vector<int>> chains(4);
  for (int k = 0; k < 4; ++k) {
    const int from = s.anchor[k], to = s.anchor[(k + 1) % 4];
    const TracedPath p = t.trace(query(from, to));
    expectJoins(t, p, from, to);
    ASSERT_TRUE(t.commit(p, k, chains[k]).ok());
    expectCommitted(t, s.in, p, k, chains[k]);
  }
  EXPECT_FALSE(t.trace(query(plusY, minusY)).found);
  // Within one side paths are still found, and stay on that side.
  const int nearPlusY = fx::nearestVertex(s.in, Vec3(0.5, 0.8, 0.3).normalized());
  const TracedPath side = t.trace(query(plusY, nearPlusY));
  expectJoins(t, side, plusY, nearPlusY);
  for (int64_t n : side.nodes) EXPECT_GT(t.nodePosition(n).y(), 0.0);
  // Of two goals, the reachable one is taken.
  PathQuery both = query(plusY, minusY);
  both.goals.push_back({nearPlusY, {}, 7});
  const TracedPath reached = t.trace(both);
  ASSERT_TRUE(reached.found);
  EXPECT_EQ(reached.goal, 1);
  // Releasing one path opens the loop; recommitting it closes it again.
  t.release(chains[1], 1);
  for (size_t k = 0; k + 1 < chains[1].size(); ++k) {
    const int e = RefinedMesh::edgeOf(s.mesh.findHalfedge(chains[1][k], chains[1][k + 1]));
    EXPECT_EQ(t.pathOfEdge(e), -1);
    EXPECT_GT(t.edgeNodeCount(e), 0);
  }
  for (size_t k = 1; k + 1 < chains[1].size(); ++k) EXPECT_EQ(t.pathCount(chains[1][k]), 0);
  EXPECT_TRUE(t.trace(query(plusY, minusY)).found);
  ASSERT_TRUE(t.recommit(chains[1], 1).ok());
  EXPECT_FALSE(t.trace(query(plusY, minusY)).found);
  EXPECT_EQ(t.recommit(chains[1], 1).code, ErrorCode::InternalError) << "its edges are not free any more";
}

TEST(PathTracer, ARolledBackPathLeavesTheGraphAsItWas) {
  // A committed path, then one refused and rolled back, over and over in one corridor: the
  // mesh and the edge nodes stay as after the first path, and the same query finds the same
  // path every time (release alone keeps the path's vertices: each retry refines the corridor).
  AxisSphere s;
  PathTracer t(s.mesh, EdgeNodeOptions{});
  for (int a : s.anchor) t.setAnchor(a, true);
  std::vector<int> first;
  ASSERT_TRUE(t.commit(t.trace(query(s.anchor[0], s.anchor[1])), 0, first).ok());
  const int vertices = s.mesh.vertexCount(), faces = s.mesh.faceCount();
  const int64_t nodes = t.nodeCount();
  std::vector<int> counts(s.mesh.edgeCount());
  for (int e = 0; e < s.mesh.edgeCount(); ++e) counts[e] = t.edgeNodeCount(e);
  const TracedPath p = t.trace(query(s.anchor[4], s.anchor[2]));
  expectJoins(t, p, s.anchor[4], s.anchor[2]);
  for (int round = 0; round < 10; ++round) {
    const TracedPath again = t.trace(query(s.anchor[4], s.anchor[2]));
    ASSERT_TRUE(again.found);
    EXPECT_EQ(again.nodes, p.nodes) << "round " << round;
    EXPECT_EQ(again.length, p.length);
    const PathTracer::Checkpoint before = t.checkpoint();
    std::vector<int> chain;
    ASSERT_TRUE(t.commit(again, 1, chain).ok());
    expectCommitted(t, s.in, again, 1, chain);
    EXPECT_GT(s.mesh.vertexCount(), vertices);
    t.rollback(chain, 1, before);
    EXPECT_EQ(s.mesh.vertexCount(), vertices);
    EXPECT_EQ(s.mesh.faceCount(), faces);
    EXPECT_EQ(t.nodeCount(), nodes);
  }
  for (int e = 0; e < s.mesh.edgeCount(); ++e) EXPECT_EQ(t.edgeNodeCount(e), counts[e]) << "edge " << e;
  for (int v = 0; v < s.mesh.vertexCount(); ++v)
    EXPECT_EQ(t.pathCount(v), std::count(first.begin(), first.end(), v)) << "vertex " << v;
  // The first path is still a wall; a path committed now is cut in as usual.
  for (size_t k = 0; k + 1 < first.size(); ++k)
    EXPECT_EQ(t.pathOfEdge(RefinedMesh::edgeOf(s.mesh.findHalfedge(first[k], first[k + 1]))), 0);
  std::vector<int> chain;
  ASSERT_TRUE(t.commit(p, 1, chain).ok());
  expectCommitted(t, s.in, p, 1, chain);
}

TEST(PathTracer, LabelledEdgesAreWallsAndFiltersKeepToTheirFaces) {
  // A latitude-longitude sphere: the equator ring of edges labelled 7 separates the poles when
  // walls of label 7 are asked for, not otherwise.
  const int lon = 12, lat = 10;
  const IndexedMesh in = fx::uvSphere(lon, lat);
  auto id = [&](int i, int j) { return 1 + (i - 1) * lon + (j % lon); };
  const int north = 0, south = in.vertexCount() - 1;
  RefinedMesh m(in);
  PathTracer t(m, EdgeNodeOptions{});
  for (int j = 0; j < lon; ++j) {
    const int h = m.findHalfedge(id(lat / 2, j), id(lat / 2, j + 1));
    ASSERT_GE(h, 0);
    t.edgeLabel()[RefinedMesh::edgeOf(h)] = 7;
  }
  PathQuery q = query(north, south);
  expectJoins(t, t.trace(q), north, south);
  q.blockedEdgeLabels = {8};
  EXPECT_TRUE(t.trace(q).found);
  q.blockedEdgeLabels = {8, 7};
  EXPECT_FALSE(t.trace(q).found);
  // Faces labelled by hemisphere: a search allowed on the north's faces reaches the north only.
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto v = m.faceVertices(f);
    t.faceLabel()[f] = (m.position(v[0]) + m.position(v[1]) + m.position(v[2])).z() > 0 ? 0 : 1;
  }
  PathQuery north0 = query(north, south);
  north0.filter.label = &t.faceLabel();
  north0.filter.a = 0;
  EXPECT_FALSE(t.trace(north0).found);
  const int ring = id(lat / 2 - 1, 3);  // above the equator
  north0.goals = {{ring, {}, 0}};
  const TracedPath p = t.trace(north0);
  expectJoins(t, p, north, ring);
  for (int64_t n : p.nodes) EXPECT_GE(t.nodePosition(n).z(), -1e-12);
  north0.filter.b = 1;  // both labels allowed
  north0.goals = {{south, {}, 0}};
  EXPECT_TRUE(t.trace(north0).found);
}

TEST(PathTracer, APathLeavesAnAnchorInTheSectorBetweenThePathsAroundIt) {
  // From +z, committed paths to +x (0) and -x (1). Seen from outside (from above), +y lies
  // counter-clockwise after +x and before -x, -y after -x and before +x.
  AxisSphere s;
  PathTracer t(s.mesh, EdgeNodeOptions{});
  for (int a : s.anchor) t.setAnchor(a, true);
  const int north = s.anchor[0];
  for (int k : {0, 1}) {
    const TracedPath p = t.trace(query(north, s.anchor[k == 0 ? 1 : 3]));
    std::vector<int> chain;
    ASSERT_TRUE(t.commit(p, k, chain).ok());
  }
  const TracedPath toPlusY = t.trace(query(north, s.anchor[4]));
  ASSERT_TRUE(toPlusY.found);
  EXPECT_EQ(t.sectorOf(toPlusY, false), std::make_pair(0, 1));
  const TracedPath toMinusY = t.trace(query(north, s.anchor[5]));
  ASSERT_TRUE(toMinusY.found);
  EXPECT_EQ(t.sectorOf(toMinusY, false), std::make_pair(1, 0));
  // At the far end: -y has no path yet.
  EXPECT_EQ(t.sectorOf(toMinusY, true), std::make_pair(-1, -1));
}
