#include "cbd/anchor_pairs.h"

namespace cbd {

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
  const std::vector<int> t = matchingRegionVertices(ds, stuck.stuckVertex, dt, 1);
  if (t.empty()) {
    r.status = Status::error(ErrorCode::LayoutFailed, stuck.status.message +
                                                          " (and the target's region there has no vertex off its paths)");
    return r;
  }
  r.sourceVertex = stuck.stuckVertex;
  r.targetVertex = t[0];
  return r;
}

}  // namespace cbd
