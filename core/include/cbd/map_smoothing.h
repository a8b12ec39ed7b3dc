#pragma once
/// @file map_smoothing.h
/// Optional relaxation of the cross-map across patch boundaries (in the spirit of Kraevoy &
/// Sheffer 2004's smoothing): every source vertex that is not an anchor is moved, in the chart
/// of its patch (unfolded across the path it lies on when it lies on one), towards the
/// source-weighted average of its neighbours' images on the target, projected back onto the
/// target through the target's patch parameterization. A move is rejected when it would raise
/// the number of the vertex's triangles in M_st that face against the target (a collapsed
/// triangle counts as one), or leave the chart: so flipped triangles can only become fewer (a
/// move may trade one of the vertex's flips for another). The metrics, which count collapsed
/// triangles as degenerate rather than flipped, are measured after this stage.

#include "cbd/layout.h"
#include "cbd/parameterization.h"

namespace cbd {

/// Options of `smoothCrossMap`.
struct MapSmoothingOptions {
  int iterations = 0;  ///< Gauss-Seidel sweeps over the source vertices
};

/// What `smoothCrossMap` did.
struct MapSmoothingResult {
  Status status;
  int moves = 0;          ///< accepted vertex moves
  int rejected = 0;       ///< moves undone (flip or outside the chart)
  int flippedBefore = 0;  ///< flipped M_st triangles before
  int flippedAfter = 0;
};

/// Relax `map.sourceToTarget` / `map.sourceImage` (M_st). The inverse map is left as it was.
MapSmoothingResult smoothCrossMap(const IndexedMesh& source, const Layout& sourceLayout,
                                  const PatchParameterization& sourceParam, const IndexedMesh& target,
                                  const Layout& targetLayout, const PatchParameterization& targetParam, CrossMap& map,
                                  const MapSmoothingOptions& options);

}  // namespace cbd
