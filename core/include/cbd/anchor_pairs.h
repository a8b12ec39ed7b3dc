#pragma once
/// @file anchor_pairs.h
/// Anchor pairs added where the Voronoi method's source layout gets stuck: a region no path can
/// split, such as a handle smaller than the anchor spacing, whose region has three corners, no
/// anchor inside, and no path that keeps every piece triangulable (source_layout.h). Schreiner et
/// al. 2004 add Steiner vertices to their base domains the same way.
///
/// Contract of `placeAnchorPair`, given a stuck source layout (`SourceLayoutResult::stuck`):
/// - on the source, the pair's vertex is the input vertex deepest inside the stuck region;
/// - on the target, it is the input vertex deepest inside the corresponding region of the partial
///   target layout: the source's paths so far traced by Procedure 1 (target_layout.h), whose
///   regions match the source's signature for signature (same boundary paths, corners, anchors
///   inside and Euler characteristic). So the two vertices lie in regions of the same topology,
///   and the layouts rebuilt with the pair added stay isomorphic by the same rules as before.
/// The caller adds the pair to both anchor lists and builds both layouts again (pipeline.h),
/// and reports it: an added pair is an anchor the user did not give.
/// Errors: LayoutFailed (the source layout is not stuck, the target's paths cannot be traced, or
/// a region has no input vertex off its boundary), Cancelled.

#include <string>
#include <vector>

#include "cbd/progress.h"
#include "cbd/source_layout.h"
#include "cbd/target_layout.h"

namespace cbd {

/// Options of `placeAnchorPair`.
struct AnchorPairOptions {
  /// How the partial target layout is traced (`partial` is set by `placeAnchorPair`).
  TargetLayoutOptions target;
};

/// The pair `placeAnchorPair` chose: input vertex indices of the two surfaces.
struct AnchorPairResult {
  Status status;
  int sourceVertex = -1;
  int targetVertex = -1;
};

/// Where to add an anchor pair so that a stuck source layout can go on; `targetAnchors[i]`
/// corresponds to the stuck layout's anchor i.
AnchorPairResult placeAnchorPair(const SourceLayoutResult& stuck, const IndexedMesh& target,
                                 const std::vector<int>& targetAnchors, const AnchorPairOptions& options = {},
                                 const Progress& progress = {});

}  // namespace cbd
