// Relaxation of the cross-map across patch boundaries (map_smoothing.h): nothing moves without
// iterations; anchors stay, images stay on the target, flips only become fewer, the inverse map
// is left alone, and the counts say what was done; the identity stays the identity.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "cbd/anchor_sampling.h"
#include "cbd/map_smoothing.h"
#include "cbd/pipeline.h"
#include "cbd/target_normals.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// A sphere onto a bumpy, stretched, finer sphere with 12 anchors, cross-parameterized without
/// untangling or smoothing: the composed map, distorted, with its layouts and parameterizations.
struct ComposedPair {
  IndexedMesh source = fx::icosphere(3), target;
  std::vector<int> sourceAnchors, targetAnchors;
  CrossParameterizationResult result;
  ComposedPair() {
    const IndexedMesh fine = fx::icosphere(4);
    target = fine;
    for (auto& p : target.positions) p = Vec3(2.5 * p.x(), p.y(), 0.6 * p.z()) * (1.0 + 0.2 * std::sin(6 * p.y()));
    sourceAnchors = farthestPointSampling(source, 12);
    for (int v : sourceAnchors) targetAnchors.push_back(fx::nearestVertex(fine, source.positions[v]));
    CrossParameterizationOptions o;
    o.untangle = false;
    result = crossParameterize(source, sourceAnchors, target, targetAnchors, 2, o);
    EXPECT_TRUE(result.status.ok()) << result.status.message;
  }
  MapSmoothingResult smooth(CrossMap& map, int iterations) const {
    return smoothCrossMap(source, result.layouts.source, result.sourceParam, target, result.layouts.target,
                          result.targetParam, map, MapSmoothingOptions{iterations});
  }
};

/// Flipped (or collapsed) image triangles of M_st, counted the way the header describes.
int flippedTriangles(const IndexedMesh& source, const IndexedMesh& target, const CrossMap& map) {
  const TargetNormals normals(target);
  int n = 0;
  for (const auto& t : source.faces) {
    const Vec3 &a = map.sourceImage[t[0]], &b = map.sourceImage[t[1]], &c = map.sourceImage[t[2]];
    n += (b - a).cross(c - a).squaredNorm() == 0 ||
         normals.flipped(a, b, c, map.sourceToTarget[t[0]], map.sourceToTarget[t[1]], map.sourceToTarget[t[2]]);
  }
  return n;
}

}  // namespace

TEST(MapSmoothing, NoIterationsNoChange) {
  const ComposedPair p;
  CrossMap map = p.result.map;
  const MapSmoothingResult r = p.smooth(map, 0);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.moves, 0);
  EXPECT_EQ(r.rejected, 0);
  EXPECT_EQ(r.flippedBefore, r.flippedAfter);
  EXPECT_EQ(map.sourceImage, p.result.map.sourceImage);
  for (size_t v = 0; v < map.sourceToTarget.size(); ++v) {
    EXPECT_EQ(map.sourceToTarget[v].face, p.result.map.sourceToTarget[v].face);
    EXPECT_EQ(map.sourceToTarget[v].bary, p.result.map.sourceToTarget[v].bary);
  }
}

TEST(MapSmoothing, KeepsAnchorsStaysOnTheTargetAndLeavesTheInverseAlone) {
  const ComposedPair p;
  const int before = flippedTriangles(p.source, p.target, p.result.map);
  CrossMap map = p.result.map;
  const MapSmoothingResult r = p.smooth(map, 10);
  ASSERT_TRUE(r.status.ok());
  EXPECT_GT(r.moves, 0);
  EXPECT_EQ(r.flippedBefore, before);
  EXPECT_EQ(r.flippedAfter, flippedTriangles(p.source, p.target, map));
  EXPECT_LE(r.flippedAfter, r.flippedBefore);
  const double diag = boundingBoxDiagonal(p.target);
  // Anchors exactly where they were (on their target anchors); every other image on the target,
  // inside the face it names.
  for (int a : p.sourceAnchors) EXPECT_EQ(map.sourceImage[a], p.result.map.sourceImage[a]);
  for (size_t k = 0; k < p.sourceAnchors.size(); ++k)
    EXPECT_LT((map.sourceImage[p.sourceAnchors[k]] - p.target.positions[p.targetAnchors[k]]).norm(), 1e-12 * diag);
  int moved = 0;
  for (int v = 0; v < p.source.vertexCount(); ++v) {
    const FacePoint& fp = map.sourceToTarget[v];
    ASSERT_GE(fp.face, 0);
    EXPECT_GE(fp.bary.minCoeff(), -1e-9);
    EXPECT_NEAR(fp.bary.sum(), 1.0, 1e-9);
    EXPECT_LT((fx::pointOn(p.target, fp) - map.sourceImage[v]).norm(), 1e-9 * diag);
    moved += map.sourceImage[v] != p.result.map.sourceImage[v];
  }
  EXPECT_GT(moved, 0);
  EXPECT_LE(moved, r.moves);
  // The inverse map is left as it was.
  EXPECT_EQ(map.targetImage, p.result.map.targetImage);
  for (size_t v = 0; v < map.targetToSource.size(); ++v) {
    EXPECT_EQ(map.targetToSource[v].face, p.result.map.targetToSource[v].face);
    EXPECT_EQ(map.targetToSource[v].bary, p.result.map.targetToSource[v].bary);
  }
}

TEST(MapSmoothing, FlipsOnlyBecomeFewerAndRejectedMovesAreCounted) {
  // Every 20th vertex's image folded onto a vertex two rings away (on the target, where that
  // vertex's image is): the map has flipped triangles, and some relaxation moves would add more.
  // Those are rejected: run after run, the flips never grow.
  const ComposedPair p;
  CrossMap map = p.result.map;
  std::vector<std::set<int>> nbr(p.source.vertexCount());
  for (const auto& f : p.source.faces)
    for (int k = 0; k < 3; ++k) nbr[f[k]].insert(f[(k + 1) % 3]);
  const std::set<int> anchors(p.sourceAnchors.begin(), p.sourceAnchors.end());
  for (int v = 0; v < p.source.vertexCount(); v += 20) {
    if (anchors.count(v)) continue;
    const int w = *nbr[v].begin();
    for (int x : nbr[w])
      if (x != v && !nbr[v].count(x)) {
        map.sourceImage[v] = p.result.map.sourceImage[x];
        map.sourceToTarget[v] = p.result.map.sourceToTarget[x];
        break;
      }
  }
  int flips = flippedTriangles(p.source, p.target, map), rejected = 0;
  ASSERT_GT(flips, 10);
  for (int run = 0; run < 8; ++run) {
    const MapSmoothingResult r = p.smooth(map, 1);
    ASSERT_TRUE(r.status.ok());
    EXPECT_EQ(r.flippedBefore, flips) << "run " << run;
    EXPECT_LE(r.flippedAfter, r.flippedBefore) << "run " << run;
    flips = flippedTriangles(p.source, p.target, map);
    EXPECT_EQ(r.flippedAfter, flips) << "run " << run;
    rejected += r.rejected;
  }
  EXPECT_GT(rejected, 0) << "no move was rejected: the rule was not exercised";
  for (int a : p.sourceAnchors) EXPECT_EQ(map.sourceImage[a], p.result.map.sourceImage[a]);
}

TEST(MapSmoothing, TheIdentityStaysTheIdentity) {
  // One layout on both sides: the composed map is the identity, and each vertex's neighbours'
  // images already surround it; the relaxation must not drag vertices across paths or off the
  // surface.
  const IndexedMesh m = fx::icosphere(3);
  SourceLayoutResult s = buildSourceLayout(m, farthestPointSampling(m, 12));
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  splitCollinearFaces(s.layout);
  const PatchParameterization param = parameterizePatches(s.layout);
  ASSERT_TRUE(param.status.ok());
  CrossMap map = composeCrossMap(s.layout, param, s.layout, param);
  ASSERT_TRUE(map.status.ok());
  const MapSmoothingResult r = smoothCrossMap(m, s.layout, param, m, s.layout, param, map, MapSmoothingOptions{10});
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.flippedBefore, 0);
  EXPECT_EQ(r.flippedAfter, 0);
  double worst = 0, edge = 0;
  for (int v = 0; v < m.vertexCount(); ++v) worst = std::max(worst, (map.sourceImage[v] - m.positions[v]).norm());
  for (const auto& t : m.faces) edge = std::max(edge, (m.positions[t[1]] - m.positions[t[0]]).norm());
  RecordProperty("worst_displacement_over_edge", std::to_string(worst / edge));
  EXPECT_LT(worst, 0.05 * edge);
  const DistortionMetrics d = computeDistortion(m, map.sourceImage, m, map.sourceToTarget);
  EXPECT_EQ(d.flipped, 0);
  EXPECT_LT(d.eAng, 1e-3);
}

TEST(MapSmoothing, ThroughThePipelineNeverAddsFlipsKeepsAnchorsAndStaysOnTheTarget) {
  // crossParameterize with smoothing iterations: the result's counts are those of the map it
  // returns and measures.
  const IndexedMesh s = fx::icosphere(3);
  const IndexedMesh tu = fx::icosphere(4);
  IndexedMesh t = tu;
  for (auto& p : t.positions) p = Vec3(2.5 * p.x(), p.y(), 0.6 * p.z()) * (1.0 + 0.2 * std::sin(6 * p.y()));
  const std::vector<int> sa = farthestPointSampling(s, 12);
  std::vector<int> ta;
  for (int v : sa) ta.push_back(fx::nearestVertex(tu, s.positions[v]));
  CrossParameterizationOptions o;
  o.untangle = false;  // the smoothing alone (untangling has its own tests)
  const CrossParameterizationResult plain = crossParameterize(s, sa, t, ta, 2, o);
  ASSERT_TRUE(plain.status.ok()) << plain.status.message;
  o.smoothing.iterations = 10;
  const CrossParameterizationResult smooth = crossParameterize(s, sa, t, ta, 2, o);
  ASSERT_TRUE(smooth.status.ok()) << smooth.status.message;
  EXPECT_GT(smooth.smoothing.moves, 0);
  EXPECT_EQ(smooth.smoothing.flippedBefore, plain.metrics.flipped);
  EXPECT_LE(smooth.metrics.flipped, plain.metrics.flipped);
  EXPECT_EQ(smooth.metrics.flipped, smooth.smoothing.flippedAfter);
  const double diagT = boundingBoxDiagonal(t);
  for (size_t k = 0; k < sa.size(); ++k) EXPECT_LT((smooth.map.sourceImage[sa[k]] - t.positions[ta[k]]).norm(), 1e-12 * diagT);
  for (int v = 0; v < s.vertexCount(); ++v) {
    const FacePoint& fp = smooth.map.sourceToTarget[v];
    ASSERT_GE(fp.face, 0);
    const auto& f = t.faces[fp.face];
    const Vec3 q = fp.bary[0] * t.positions[f[0]] + fp.bary[1] * t.positions[f[1]] + fp.bary[2] * t.positions[f[2]];
    EXPECT_LT((q - smooth.map.sourceImage[v]).norm(), 1e-9 * diagT);
    EXPECT_GE(fp.bary.minCoeff(), -1e-9);
  }
}
