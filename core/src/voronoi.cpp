#include "cbd/voronoi.h"

#include "cbd/layout.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <tuple>

namespace cbd {

Status startVoronoiLayout(const IndexedMesh& input, const std::vector<int>& anchors, Layout& layout,
                          std::vector<int>& faceCluster, CutsResult& cuts) {
  layout.mesh = RefinedMesh(input);
  layout.anchorVertices = anchors;
  separateAnchors(layout.mesh, anchors);
  VoronoiResult vor = computeVoronoiClusters(layout.mesh, anchors);
  if (!vor.status) return vor.status;
  cuts = extractCuts(layout.mesh, vor.faceCluster, static_cast<int>(anchors.size()));
  faceCluster = std::move(vor.faceCluster);
  return Status::success();
}

Status checkAnchorVertices(const IndexedMesh& mesh, const std::vector<int>& anchors, const std::string& what) {
  std::vector<int> owner(mesh.vertexCount(), -1);
  for (size_t i = 0; i < anchors.size(); ++i) {
    const int v = anchors[i];
    if (v < 0 || v >= mesh.vertexCount())
      return Status::error(ErrorCode::InvalidArgument, what + " anchor " + std::to_string(i) + " is not a vertex");
    if (owner[v] >= 0)
      return Status::error(ErrorCode::AnchorsShareVertex, what + " anchors " + std::to_string(owner[v]) + " and " +
                                                              std::to_string(i) + " are on the same vertex");
    owner[v] = static_cast<int>(i);
  }
  return Status::success();
}

int separateAnchors(RefinedMesh& mesh, const std::vector<int>& anchorVertices) {
  std::vector<char> isAnchor(mesh.vertexCount(), 0);
  for (int v : anchorVertices) isAnchor[v] = 1;
  int splits = 0;
  for (int e = 0; e < mesh.edgeCount(); ++e) {
    const int a = mesh.to(2 * e), b = mesh.to(2 * e + 1);
    if (a < static_cast<int>(isAnchor.size()) && b < static_cast<int>(isAnchor.size()) && isAnchor[a] && isAnchor[b]) {
      mesh.splitEdge(2 * e, 0.5);
      ++splits;
    }
  }
  return splits;
}

VoronoiResult computeVoronoiClusters(const RefinedMesh& mesh, const std::vector<int>& anchors) {
  VoronoiResult r;
  const int nf = mesh.faceCount();
  const int na = static_cast<int>(anchors.size());
  r.faceCluster.assign(nf, -1);
  r.clusterSize.assign(na, 0);
  std::vector<Vec3> centroid(nf);
  for (int f = 0; f < nf; ++f) {
    const auto v = mesh.faceVertices(f);
    centroid[f] = (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2])) / 3.0;
  }
  std::vector<double> dist(nf, std::numeric_limits<double>::infinity());
  std::vector<char> seed(nf, 0), done(nf, 0);
  // Priority: distance, then cluster, then face (deterministic ties).
  using Item = std::tuple<double, int, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  for (int i = 0; i < na; ++i) {
    const int v = anchors[i];
    const int start = mesh.outgoing(v);
    if (start < 0) {
      r.status = Status::error(ErrorCode::InvalidArgument, "anchor " + std::to_string(i) + " is on an isolated vertex");
      return r;
    }
    int h = start;
    do {
      const int f = mesh.face(h);
      if (seed[f]) {
        r.status = Status::error(ErrorCode::InvalidArgument,
                                 "anchors " + std::to_string(r.faceCluster[f]) + " and " + std::to_string(i) +
                                     " share a face; separate them first");
        return r;
      }
      seed[f] = 1;
      r.faceCluster[f] = i;
      dist[f] = (centroid[f] - mesh.position(v)).norm();
      pq.emplace(dist[f], i, f);
      h = mesh.rotateCCW(h);
    } while (h != start);
  }
  while (!pq.empty()) {
    const auto [d, c, f] = pq.top();
    pq.pop();
    if (done[f] || r.faceCluster[f] != c || d > dist[f]) continue;
    done[f] = 1;
    const int h0 = mesh.faceHalfedge(f);
    for (int k = 0, h = h0; k < 3; ++k, h = mesh.next(h)) {
      const int g = mesh.face(RefinedMesh::twin(h));
      if (seed[g] || done[g]) continue;
      const double nd = d + (centroid[g] - centroid[f]).norm();
      if (nd < dist[g] || (nd == dist[g] && c < r.faceCluster[g])) {
        dist[g] = nd;
        r.faceCluster[g] = c;
        pq.emplace(nd, c, g);
      }
    }
  }
  for (int f = 0; f < nf; ++f) {
    if (r.faceCluster[f] < 0) {
      r.status = Status::error(ErrorCode::InternalError, "face " + std::to_string(f) + " was reached by no anchor");
      return r;
    }
    ++r.clusterSize[r.faceCluster[f]];
  }
  return r;
}

int CutsResult::cutsOfPair(int i, int j, int) const {
  if (i > j) std::swap(i, j);
  int n = 0;
  for (const Cut& c : cuts) n += (c.i == i && c.j == j);
  return n;
}

CutsResult extractCuts(const RefinedMesh& mesh, const std::vector<int>& faceCluster, int anchorCount) {
  CutsResult r;
  const int ne = mesh.edgeCount();
  r.edgeCut.assign(ne, -1);
  // Union-find over cut edges of the same pair that share a vertex.
  std::vector<int> parent(ne);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto pairOf = [&](int e) -> long long {
    int a = faceCluster[mesh.face(2 * e)], b = faceCluster[mesh.face(2 * e + 1)];
    if (a == b) return -1;
    if (a > b) std::swap(a, b);
    return static_cast<long long>(a) * anchorCount + b;
  };
  std::vector<long long> pair(ne);
  for (int e = 0; e < ne; ++e) pair[e] = pairOf(e);
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    const int start = mesh.outgoing(v);
    if (start < 0) continue;
    // Cut edges around v with the same pair belong to one chain.
    std::map<long long, int> firstOfPair;
    int h = start;
    do {
      const int e = RefinedMesh::edgeOf(h);
      if (pair[e] >= 0) {
        auto [it, inserted] = firstOfPair.emplace(pair[e], e);
        if (!inserted) {
          const int a = find(it->second), b = find(e);
          if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
      }
      h = mesh.rotateCCW(h);
    } while (h != start);
  }
  std::map<std::pair<long long, int>, int> chainOf;  // (pair, root) -> cut
  std::vector<std::pair<long long, int>> order;
  for (int e = 0; e < ne; ++e)
    if (pair[e] >= 0 && find(e) == e) order.emplace_back(pair[e], e);
  std::sort(order.begin(), order.end());
  for (const auto& [p, root] : order) {
    Cut c;
    c.i = static_cast<int>(p / anchorCount);
    c.j = static_cast<int>(p % anchorCount);
    c.eta = r.cuts.empty() || r.cuts.back().i != c.i || r.cuts.back().j != c.j ? 0 : r.cuts.back().eta + 1;
    chainOf[{p, root}] = static_cast<int>(r.cuts.size());
    r.cuts.push_back(c);
  }
  for (int e = 0; e < ne; ++e) {
    if (pair[e] < 0) continue;
    const int c = chainOf[{pair[e], find(e)}];
    r.edgeCut[e] = c;
    r.cuts[c].edges.push_back(e);
    r.cuts[c].length += mesh.edgeLength(e);
  }
  // End points: vertices used by exactly one edge of the chain.
  for (Cut& c : r.cuts) {
    std::map<int, int> degree;
    for (int e : c.edges) ++degree[mesh.to(2 * e)], ++degree[mesh.to(2 * e + 1)];
    for (const auto& [v, d] : degree)
      if (d == 1) c.endpoints.push_back(v);
  }
  return r;
}

}  // namespace cbd
