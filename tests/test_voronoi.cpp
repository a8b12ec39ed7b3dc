// The approximate Voronoi diagram of the anchors (voronoi.h, Sec. 5.1): clusters that partition
// the faces, each connected around its anchor's one-ring, every face in the cluster of an anchor
// nearest to it by the stated distance; separated anchors; the cuts between clusters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>

#include "cbd/anchor_sampling.h"
#include "cbd/layout.h"
#include "cbd/voronoi.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3 centroid(const RefinedMesh& m, int f) {
  const auto v = m.faceVertices(f);
  return (m.position(v[0]) + m.position(v[1]) + m.position(v[2])) / 3.0;
}

std::vector<int> oneRing(const RefinedMesh& m, int v) {
  std::vector<int> faces;
  const int start = m.outgoing(v);
  int h = start;
  do {
    faces.push_back(m.face(h));
    h = m.rotateCCW(h);
  } while (h != start);
  return faces;
}

/// The header's distance of every face from anchor i alone: its one-ring at the distance from
/// the anchor to their centroids, then centroid-to-centroid steps across edges, never through
/// another anchor's one-ring (those faces are that anchor's from the start).
std::vector<double> distanceFrom(const RefinedMesh& m, const std::vector<int>& anchors, size_t i) {
  std::vector<char> otherSeed(m.faceCount(), 0);
  for (size_t j = 0; j < anchors.size(); ++j)
    if (j != i)
      for (int f : oneRing(m, anchors[j])) otherSeed[f] = 1;
  std::vector<double> d(m.faceCount(), kInf);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  for (int f : oneRing(m, anchors[i])) d[f] = (centroid(m, f) - m.position(anchors[i])).norm(), pq.emplace(d[f], f);
  while (!pq.empty()) {
    const auto [df, f] = pq.top();
    pq.pop();
    if (df > d[f]) continue;
    for (int k = 0, h = m.faceHalfedge(f); k < 3; ++k, h = m.next(h)) {
      const int g = m.face(RefinedMesh::twin(h));
      if (otherSeed[g]) continue;
      const double nd = df + (centroid(m, g) - centroid(m, f)).norm();
      if (nd < d[g]) d[g] = nd, pq.emplace(nd, g);
    }
  }
  return d;
}

/// Clusters partition the faces, each holds its anchor's one-ring and is connected.
void expectPartition(const RefinedMesh& m, const std::vector<int>& anchors, const VoronoiResult& v) {
  ASSERT_TRUE(v.status.ok()) << v.status.message;
  ASSERT_EQ(static_cast<int>(v.faceCluster.size()), m.faceCount());
  ASSERT_EQ(v.clusterSize.size(), anchors.size());
  std::vector<int> size(anchors.size(), 0);
  for (int c : v.faceCluster) {
    ASSERT_TRUE(c >= 0 && c < static_cast<int>(anchors.size()));
    ++size[c];
  }
  EXPECT_EQ(size, v.clusterSize);
  for (size_t i = 0; i < anchors.size(); ++i) {
    const std::vector<int> ring = oneRing(m, anchors[i]);
    for (int f : ring) EXPECT_EQ(v.faceCluster[f], static_cast<int>(i)) << "one-ring of anchor " << i;
    std::vector<char> seen(m.faceCount(), 0);
    std::vector<int> stack{ring[0]};
    seen[ring[0]] = 1;
    int reached = 0;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      ++reached;
      for (int k = 0, h = m.faceHalfedge(f); k < 3; ++k, h = m.next(h)) {
        const int g = m.face(RefinedMesh::twin(h));
        if (!seen[g] && v.faceCluster[g] == static_cast<int>(i)) seen[g] = 1, stack.push_back(g);
      }
    }
    EXPECT_EQ(reached, v.clusterSize[i]) << "cluster " << i << " is not connected";
  }
}

IndexedMesh bumpySphere() {
  IndexedMesh m = fx::icosphere(3);
  for (auto& p : m.positions) p *= 1.0 + 0.2 * std::sin(4 * p.x()) * std::cos(3 * p.z());
  return m;
}

double angleAround(const Vec3& p) { return std::atan2(p.y(), p.x()); }

}  // namespace

TEST(Voronoi, ClustersPartitionTheFacesAndEveryFaceIsNearestToItsAnchor) {
  for (const IndexedMesh& in : {bumpySphere(), fx::torus(2.0, 0.7, 40, 16), fx::holedPlate(2, 3, 10)}) {
    const std::vector<int> anchors = farthestPointSampling(in, 12, 3);
    RefinedMesh m(in);
    separateAnchors(m, anchors);
    const VoronoiResult v = computeVoronoiClusters(m, anchors);
    expectPartition(m, anchors, v);
    // The Voronoi property under the header's distance: no anchor is nearer to a face than the
    // anchor of its cluster.
    std::vector<std::vector<double>> d;
    for (size_t i = 0; i < anchors.size(); ++i) d.push_back(distanceFrom(m, anchors, i));
    int wrong = 0;
    for (int f = 0; f < m.faceCount(); ++f) {
      double nearest = kInf;
      for (const auto& di : d) nearest = std::min(nearest, di[f]);
      const double own = d[v.faceCluster[f]][f];
      if (own > nearest * (1 + 1e-12)) ++wrong;
    }
    EXPECT_EQ(wrong, 0) << "faces in the cluster of an anchor farther than the nearest";
    EXPECT_EQ(computeVoronoiClusters(m, anchors).faceCluster, v.faceCluster) << "not deterministic";
  }
}

TEST(Voronoi, TwoOppositeAnchorsSplitASphereAtItsEquator) {
  // Anchors at the poles of a sphere: a face clearly in the northern hemisphere is the north
  // pole's, and the same in the south (near the equator the graph distance may decide either way).
  const IndexedMesh in = fx::icosphere(3);
  const std::vector<int> anchors = {fx::nearestVertex(in, Vec3(0, 0, 1)), fx::nearestVertex(in, Vec3(0, 0, -1))};
  const RefinedMesh m(in);
  const VoronoiResult v = computeVoronoiClusters(m, anchors);
  expectPartition(m, anchors, v);
  const Vec3 axis = (in.positions[anchors[0]] - in.positions[anchors[1]]).normalized();
  for (int f = 0; f < m.faceCount(); ++f) {
    const double h = centroid(m, f).dot(axis);
    if (std::abs(h) > 0.15) {
      EXPECT_EQ(v.faceCluster[f], h > 0 ? 0 : 1) << "face " << f << " at height " << h;
    }
  }
  EXPECT_NEAR(v.clusterSize[0], v.clusterSize[1], 0.05 * m.faceCount());
}

TEST(Voronoi, SeparateAnchorsSplitsEveryEdgeBetweenTwoAnchors) {
  // Two adjacent anchors share two faces: the clustering refuses them. The three corners of one
  // face: three edges to split. Afterwards no edge joins two anchors and the clusters exist.
  const IndexedMesh in = fx::icosphere(2);
  const auto& f = in.faces[5];
  const int far = fx::nearestVertex(in, -in.positions[f[0]]);
  for (const std::vector<int>& anchors : {std::vector<int>{f[0], f[1], far}, std::vector<int>{f[0], f[1], f[2]}}) {
    RefinedMesh m(in);
    EXPECT_EQ(computeVoronoiClusters(m, anchors).status.code, ErrorCode::InvalidArgument);
    const int edges = m.edgeCount();
    std::set<std::pair<int, int>> between;
    for (int e = 0; e < edges; ++e) {
      const int a = m.to(2 * e), b = m.to(2 * e + 1);
      if (std::count(anchors.begin(), anchors.end(), a) && std::count(anchors.begin(), anchors.end(), b))
        between.insert(std::minmax(a, b));
    }
    const int splits = separateAnchors(m, anchors);
    EXPECT_EQ(splits, static_cast<int>(between.size()));
    for (const auto& [a, b] : between) {
      EXPECT_EQ(m.findHalfedge(a, b), -1);
      // The edge's midpoint is a new vertex joined to both.
      bool midpoint = false;
      for (int w = in.vertexCount(); w < m.vertexCount(); ++w)
        midpoint = midpoint || ((m.position(w) - 0.5 * (in.positions[a] + in.positions[b])).norm() < 1e-15 &&
                                m.findHalfedge(a, w) >= 0 && m.findHalfedge(w, b) >= 0);
      EXPECT_TRUE(midpoint) << a << "-" << b;
    }
    expectPartition(m, anchors, computeVoronoiClusters(m, anchors));
    EXPECT_EQ(separateAnchors(m, anchors), 0);
  }
}

TEST(Voronoi, TwoAnchorsAroundATorusShareTwoClosedCuts) {
  // Anchors on opposite sides of a torus's ring (u = 0 and u = pi): each cluster is half the
  // tube, and the two halves touch along two loops round the tube, near u = pi/2 and u = -pi/2.
  // One pair of clusters, two cuts (Observation 2), each closed: no Voronoi vertex, no endpoints.
  const double R = 2.0, r = 0.6;
  const IndexedMesh in = fx::torus(R, r, 48, 16);
  const std::vector<int> anchors = {fx::nearestVertex(in, Vec3(R + r, 0, 0)), fx::nearestVertex(in, Vec3(-R - r, 0, 0))};
  const RefinedMesh m(in);
  const VoronoiResult v = computeVoronoiClusters(m, anchors);
  expectPartition(m, anchors, v);
  const CutsResult cuts = extractCuts(m, v.faceCluster, 2);
  ASSERT_TRUE(cuts.status.ok());
  ASSERT_EQ(cuts.cuts.size(), 2u);
  EXPECT_EQ(cuts.cutsOfPair(0, 1, 2), 2);
  EXPECT_EQ(cuts.cutsOfPair(1, 0, 2), 2);
  std::set<int> sides;
  for (size_t c = 0; c < cuts.cuts.size(); ++c) {
    const Cut& cut = cuts.cuts[c];
    EXPECT_EQ(cut.i, 0);
    EXPECT_EQ(cut.j, 1);
    EXPECT_EQ(cut.eta, static_cast<int>(c));
    EXPECT_TRUE(cut.endpoints.empty());
    // A loop round the tube: every vertex of it used by two of its edges.
    std::map<int, int> degree;
    double length = 0, mean = 0;
    for (int e : cut.edges) {
      ++degree[m.to(2 * e)], ++degree[m.to(2 * e + 1)];
      length += m.edgeLength(e);
      mean += angleAround(m.position(m.to(2 * e)));
    }
    for (const auto& [vertex, d] : degree) EXPECT_EQ(d, 2) << "vertex " << vertex;
    EXPECT_NEAR(cut.length, length, 1e-12 * length);
    // Round the tube (2 pi r), zig-zagging along mesh edges.
    EXPECT_GT(cut.length, 2 * M_PI * r * 0.95);
    EXPECT_LT(cut.length, 2 * M_PI * r * 1.6);
    mean /= cut.edges.size();
    EXPECT_NEAR(std::abs(mean), M_PI / 2, 0.15);
    sides.insert(mean > 0 ? 1 : -1);
  }
  EXPECT_EQ(sides.size(), 2u) << "both cuts on one side of the ring";
}

TEST(Voronoi, EveryEdgeBetweenTwoClustersIsOnACutOfThatPair) {
  const IndexedMesh in = bumpySphere();
  const std::vector<int> anchors = farthestPointSampling(in, 10);
  RefinedMesh m(in);
  separateAnchors(m, anchors);
  const VoronoiResult v = computeVoronoiClusters(m, anchors);
  ASSERT_TRUE(v.status.ok());
  const CutsResult cuts = extractCuts(m, v.faceCluster, 10);
  ASSERT_EQ(static_cast<int>(cuts.edgeCut.size()), m.edgeCount());
  std::vector<int> owned(cuts.cuts.size(), 0);
  for (int e = 0; e < m.edgeCount(); ++e) {
    const int a = v.faceCluster[m.face(2 * e)], b = v.faceCluster[m.face(2 * e + 1)];
    const int c = cuts.edgeCut[e];
    if (a == b) {
      EXPECT_EQ(c, -1) << "edge " << e << " inside cluster " << a;
      continue;
    }
    ASSERT_GE(c, 0) << "edge " << e << " between clusters " << a << " and " << b;
    EXPECT_EQ(std::minmax(a, b), std::minmax(cuts.cuts[c].i, cuts.cuts[c].j));
    EXPECT_TRUE(std::count(cuts.cuts[c].edges.begin(), cuts.cuts[c].edges.end(), e));
    ++owned[c];
  }
  // Sorted by (i, j, eta), eta counting the cuts of each pair from 0; each cut a connected chain
  // of its pair's edges whose ends are the vertices used by one of its edges.
  for (size_t c = 0; c < cuts.cuts.size(); ++c) {
    const Cut& cut = cuts.cuts[c];
    EXPECT_LT(cut.i, cut.j);
    EXPECT_EQ(owned[c], static_cast<int>(cut.edges.size()));
    if (c > 0) {
      const Cut& prev = cuts.cuts[c - 1];
      EXPECT_LT(std::make_tuple(prev.i, prev.j, prev.eta), std::make_tuple(cut.i, cut.j, cut.eta));
      EXPECT_EQ(cut.eta, prev.i == cut.i && prev.j == cut.j ? prev.eta + 1 : 0);
    } else {
      EXPECT_EQ(cut.eta, 0);
    }
    std::map<int, std::vector<int>> at;
    for (int e : cut.edges) at[m.to(2 * e)].push_back(e), at[m.to(2 * e + 1)].push_back(e);
    std::set<int> reached{cut.edges[0]};
    std::vector<int> stack{cut.edges[0]};
    while (!stack.empty()) {
      const int e = stack.back();
      stack.pop_back();
      for (int x : {m.to(2 * e), m.to(2 * e + 1)})
        for (int g : at[x])
          if (reached.insert(g).second) stack.push_back(g);
    }
    EXPECT_EQ(reached.size(), cut.edges.size()) << "cut " << c << " is not one chain";
    std::vector<int> ends;
    for (const auto& [x, es] : at)
      if (es.size() == 1) ends.push_back(x);
    EXPECT_EQ(ends, cut.endpoints);
    // On a sphere with anchors spread out, every cut ends at Voronoi vertices: two ends.
    EXPECT_EQ(cut.endpoints.size(), 2u) << "cut " << c;
  }
  // A sphere's diagram: V - E + F = 2 with the anchors as faces, cuts as edges, their ends as
  // vertices.
  std::set<int> voronoiVertices;
  for (const Cut& cut : cuts.cuts) voronoiVertices.insert(cut.endpoints.begin(), cut.endpoints.end());
  EXPECT_EQ(static_cast<int>(voronoiVertices.size()) - static_cast<int>(cuts.cuts.size()) + 10, 2);
}

TEST(Voronoi, AnchorsAreCheckedAndTheLayoutStartsOnSeparatedAnchors) {
  const IndexedMesh in = fx::icosphere(2);
  EXPECT_TRUE(checkAnchorVertices(in, {0, 5, 9}, "source").ok());
  const Status out = checkAnchorVertices(in, {0, in.vertexCount()}, "source");
  EXPECT_EQ(out.code, ErrorCode::InvalidArgument);
  EXPECT_NE(out.message.find("source"), std::string::npos) << out.message;
  EXPECT_EQ(checkAnchorVertices(in, {0, -1}, "target").code, ErrorCode::InvalidArgument);
  const Status shared = checkAnchorVertices(in, {3, 7, 3}, "target");
  EXPECT_EQ(shared.code, ErrorCode::AnchorsShareVertex);
  EXPECT_NE(shared.message.find("target"), std::string::npos) << shared.message;

  // Two adjacent anchors among them: startVoronoiLayout splits their edge, clusters, cuts.
  const auto& f = in.faces[0];
  std::vector<int> anchors = farthestPointSampling(in, 6, f[0]);
  anchors.push_back(f[1]);
  Layout layout;
  std::vector<int> faceCluster;
  CutsResult cuts;
  ASSERT_TRUE(startVoronoiLayout(in, anchors, layout, faceCluster, cuts).ok());
  EXPECT_EQ(layout.anchorVertices, anchors);
  EXPECT_EQ(layout.mesh.findHalfedge(f[0], f[1]), -1);
  EXPECT_EQ(layout.mesh.vertexCount(), in.vertexCount() + 1);
  EXPECT_EQ(static_cast<int>(faceCluster.size()), layout.mesh.faceCount());
  EXPECT_EQ(static_cast<int>(cuts.edgeCut.size()), layout.mesh.edgeCount());
  expectPartition(layout.mesh, anchors, computeVoronoiClusters(layout.mesh, anchors));
  EXPECT_EQ(computeVoronoiClusters(layout.mesh, anchors).faceCluster, faceCluster);
}
