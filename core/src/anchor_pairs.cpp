#include "cbd/anchor_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cbd {
namespace {

/// The vertex of the target's region whose distances to the region's sides, each over the
/// region's depth, are nearest (least squares) to those of source vertex `s`: the regions are
/// bounded by the same paths, so this places the pair alike relative to them, where the deepest
/// point alone could jump across a handle.
int matchingVertex(const RegionDistances& source, int s, const RegionDistances& target) {
  const auto at = std::find(source.vertices.begin(), source.vertices.end(), s);
  if (at == source.vertices.end() || target.vertices.empty() || source.sides != target.sides) return -1;
  const size_t k = static_cast<size_t>(at - source.vertices.begin());
  const double depthS = source.toBoundary[static_cast<size_t>(source.deepest())];
  const double depthT = target.toBoundary[static_cast<size_t>(target.deepest())];
  int best = -1;
  double bestCost = std::numeric_limits<double>::infinity();
  for (size_t v = 0; v < target.vertices.size(); ++v) {
    double cost = 0;
    for (size_t j = 0; j < source.sides.size(); ++j) {
      const double a = source.toSide[k][j] / depthS, b = target.toSide[v][j] / depthT;
      cost += std::isfinite(a) && std::isfinite(b) ? (a - b) * (a - b) : std::isfinite(a) || std::isfinite(b) ? 1e6 : 0.0;
    }
    if (cost < bestCost) bestCost = cost, best = target.vertices[v];
  }
  return best;
}

}  // namespace

AnchorPairResult placeAnchorPair(const SourceLayoutResult& stuck, const IndexedMesh& target,
                                 const std::vector<int>& targetAnchors, const AnchorPairOptions& options,
                                 const Progress& progress) {
  AnchorPairResult r;
  if (!stuck.stuck) {
    r.status = Status::error(ErrorCode::LayoutFailed, "the source layout is not stuck in a region: " +
                                                          (stuck.status ? std::string("it is complete") : stuck.status.message));
    return r;
  }
  if (stuck.stuckVertex < 0) {
    r.status = Status::error(ErrorCode::LayoutFailed, stuck.status.message + " (and that region has no vertex off its paths)");
    return r;
  }
  TargetLayoutOptions to = options.target;
  to.partial = true;
  const TargetLayoutResult partial = buildTargetLayout(stuck.layout, target, targetAnchors, to, progress);
  if (!partial.status) {
    r.status = partial.status.code == ErrorCode::Cancelled
                   ? partial.status
                   : Status::error(ErrorCode::LayoutFailed, stuck.status.message + "; no anchor could be added there, as the target "
                                                                "cannot follow the source's paths so far: " + partial.status.message);
    return r;
  }
  RegionDistances ds, dt;
  regionDistances(stuck.layout, stuck.stuckRegion, ds);
  regionDistances(partial.layout, stuck.stuckRegion, dt);
  const int t = matchingVertex(ds, stuck.stuckVertex, dt);
  if (t < 0) {
    r.status = Status::error(ErrorCode::LayoutFailed, stuck.status.message +
                                                          " (and the target's region there has no vertex off its paths)");
    return r;
  }
  r.sourceVertex = stuck.stuckVertex;
  r.targetVertex = t;
  return r;
}

}  // namespace cbd
