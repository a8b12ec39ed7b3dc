#include "cbd/anchor_sampling.h"

#include <algorithm>
#include <limits>
#include <queue>

namespace cbd {

std::vector<int> farthestPointSampling(const IndexedMesh& mesh, int count, int seed) {
  const int nv = mesh.vertexCount();
  std::vector<std::vector<int>> nbr(nv);
  for (const auto& f : mesh.faces)
    for (int k = 0; k < 3; ++k) nbr[f[k]].push_back(f[(k + 1) % 3]), nbr[f[k]].push_back(f[(k + 2) % 3]);
  for (auto& n : nbr) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  std::vector<int> out;
  if (nv == 0 || count <= 0) return out;
  if (seed < 0 || seed >= nv || nbr[seed].empty()) {
    seed = 0;
    while (seed < nv && nbr[seed].empty()) ++seed;
    if (seed == nv) return out;
  }
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  int next = seed;
  while (static_cast<int>(out.size()) < count) {
    out.push_back(next);
    // Incremental Dijkstra from the new sample: only distances that shrink are updated.
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
    dist[next] = 0.0;
    pq.emplace(0.0, next);
    while (!pq.empty()) {
      const auto [d, v] = pq.top();
      pq.pop();
      if (d > dist[v]) continue;
      for (int w : nbr[v]) {
        const double nd = d + (mesh.positions[w] - mesh.positions[v]).norm();
        if (nd < dist[w]) dist[w] = nd, pq.emplace(nd, w);
      }
    }
    next = -1;
    for (int v = 0; v < nv; ++v)
      if (!nbr[v].empty() && dist[v] > 0 && (next < 0 || dist[v] > dist[next])) next = v;
    if (next < 0) break;
  }
  return out;
}

}  // namespace cbd
