// Farthest-point sampling of anchors (anchor_sampling.h): distinct referenced vertices, the seed
// first, every next one the farthest along mesh edges from those before it, ties to the lower index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <set>

#include "cbd/anchor_sampling.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// Distance along mesh edges from the nearest of `sources` to every vertex (a plain Dijkstra,
/// written independently of the sampler's incremental one).
std::vector<double> edgeDistance(const IndexedMesh& m, const std::vector<int>& sources) {
  std::vector<std::set<int>> nbr(m.vertexCount());
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) nbr[f[k]].insert(f[(k + 1) % 3]), nbr[f[k]].insert(f[(k + 2) % 3]);
  std::vector<double> d(m.vertexCount(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  for (int s : sources) d[s] = 0, pq.emplace(0.0, s);
  while (!pq.empty()) {
    const auto [dv, v] = pq.top();
    pq.pop();
    if (dv > d[v]) continue;
    for (int w : nbr[v]) {
      const double nd = dv + (m.positions[w] - m.positions[v]).norm();
      if (nd < d[w]) d[w] = nd, pq.emplace(nd, w);
    }
  }
  return d;
}

IndexedMesh bumpySphere() {
  IndexedMesh m = fx::icosphere(2);
  for (auto& p : m.positions) p *= 1.0 + 0.2 * std::sin(4 * p.x()) * std::cos(3 * p.z());
  return m;
}

}  // namespace

TEST(AnchorSampling, DistinctVerticesSeedFirstAsManyAsAsked) {
  const IndexedMesh m = fx::icosphere(3);
  for (int count : {1, 2, 10, 50}) {
    for (int seed : {0, 17, m.vertexCount() - 1}) {
      const std::vector<int> s = farthestPointSampling(m, count, seed);
      ASSERT_EQ(static_cast<int>(s.size()), count) << "seed " << seed;
      EXPECT_EQ(s[0], seed);
      EXPECT_EQ(std::set<int>(s.begin(), s.end()).size(), s.size()) << "a vertex chosen twice";
      for (int v : s) EXPECT_TRUE(v >= 0 && v < m.vertexCount());
    }
  }
  EXPECT_TRUE(farthestPointSampling(m, 0).empty());
  EXPECT_TRUE(farthestPointSampling(IndexedMesh{}, 5).empty());
}

TEST(AnchorSampling, EverySampleIsTheFarthestFromThoseBeforeIt) {
  for (const IndexedMesh& m : {bumpySphere(), fx::torus(2.0, 0.6, 30, 12)}) {
    const std::vector<int> s = farthestPointSampling(m, 24, 5);
    ASSERT_EQ(s.size(), 24u);
    double previous = std::numeric_limits<double>::infinity();
    for (size_t k = 1; k < s.size(); ++k) {
      const std::vector<double> d = edgeDistance(m, std::vector<int>(s.begin(), s.begin() + k));
      const double farthest = *std::max_element(d.begin(), d.end());
      EXPECT_NEAR(d[s[k]], farthest, 1e-12 * farthest) << "sample " << k;
      // The covering radius only shrinks as samples are added.
      EXPECT_LE(farthest, previous * (1 + 1e-12)) << "sample " << k;
      previous = farthest;
    }
    // Spread: no two samples closer than the covering radius of the set minus its last sample.
    const std::vector<double> cover = edgeDistance(m, std::vector<int>(s.begin(), s.end() - 1));
    const double radius = cover[s.back()];
    for (size_t i = 0; i < s.size(); ++i) {
      const std::vector<double> d = edgeDistance(m, {s[i]});
      for (size_t j = i + 1; j < s.size(); ++j) EXPECT_GE(d[s[j]], radius * (1 - 1e-12)) << i << ", " << j;
    }
  }
}

TEST(AnchorSampling, TiesGoToTheLowerIndex) {
  // The octahedron's edges are all sqrt(2) to the last bit: from +z (4) the farthest is -z (5);
  // then +x, -x, +y and -y are all sqrt(2) from the nearest sample, and the lowest index wins
  // each time.
  const std::vector<int> s = farthestPointSampling(fx::octahedron(), 6, 4);
  EXPECT_EQ(s, (std::vector<int>{4, 5, 0, 1, 2, 3}));
}

TEST(AnchorSampling, NeverMoreSamplesThanVertices) {
  const std::vector<int> s = farthestPointSampling(fx::tetrahedron(), 10, 2);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0], 2);
  EXPECT_EQ(std::set<int>(s.begin(), s.end()), (std::set<int>{0, 1, 2, 3}));
}

TEST(AnchorSampling, UnreferencedVerticesAreNeverChosen) {
  // A tetrahedron behind two unreferenced vertices (0 and 5), the first far away: it would be the
  // farthest point of all if it were a candidate.
  const IndexedMesh tet = fx::tetrahedron();
  IndexedMesh m;
  m.positions.push_back(Vec3(100, 100, 100));
  m.positions.insert(m.positions.end(), tet.positions.begin(), tet.positions.end());
  m.positions.push_back(Vec3(-50, 0, 0));
  for (auto f : tet.faces) m.faces.push_back({f[0] + 1, f[1] + 1, f[2] + 1});
  for (int seed : {0, 5, -1, 6, 1000}) {
    const std::vector<int> s = farthestPointSampling(m, 10, seed);
    ASSERT_EQ(s.size(), 4u) << "seed " << seed;
    EXPECT_EQ(s[0], 1) << "seed " << seed << " should be replaced by the first referenced vertex";
    EXPECT_EQ(std::set<int>(s.begin(), s.end()), (std::set<int>{1, 2, 3, 4})) << "seed " << seed;
  }
  EXPECT_EQ(farthestPointSampling(m, 2, 3)[0], 3);  // a referenced seed is kept
}
