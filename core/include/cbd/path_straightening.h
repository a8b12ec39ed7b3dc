#pragma once
/// @file path_straightening.h
/// Straightening the paths of a finished layout, the same way for every method: each path is
/// replaced by the diagonal of the quadrilateral formed by its two patches, mapped onto the unit
/// square with Floater's mean-value weights (its four sides by arc length onto the square's
/// sides, the path's own ends at opposite corners). The new path is where the straight segment
/// between those corners runs, cut into the refined mesh by edge splits (a vertex of the mesh is
/// taken where the segment passes within 1 % of an edge's length of it); the patches on its two
/// sides keep their ids, corners and sides, so the layout's combinatorics (and its isomorphism
/// with the other surface's layout) are unchanged.
///
/// Why: a traced path is a shortest path given the paths traced before it, so a path that
/// closes a region often hugs its neighbours and leaves a sliver patch on one surface where the
/// other surface has a fat one (three collinear anchors along a limb are the typical case). The
/// diagonal of the square depends only on the quadrilateral, so corresponding quadrilaterals get
/// corresponding diagonals. Kraevoy & Sheffer 2004 and Praun et al. 2001 straighten their
/// paths in the same spirit (REFERENCES.md: harmonic path smoothing of `jsb/LayoutEmbedding`).

#include "cbd/layout.h"
#include "cbd/progress.h"

namespace cbd {

/// Options of `straightenPaths`.
struct PathStraighteningOptions {
  int rounds = 2;  ///< sweeps over all paths (0: none); a second one settles what the first moved
};

/// What `straightenPaths` did.
struct PathStraighteningResult {
  Status status;          ///< InternalError when a path could not be cut in, or Cancelled (the
                          ///< layout is then partly straightened and must be discarded)
  int straightened = 0;   ///< paths replaced
  int skipped = 0;        ///< paths left as they were (both sides in one patch, or the segment
                          ///< would touch the quadrilateral's boundary)
  int splits = 0;         ///< refined-mesh edges split
  double lengthBefore = 0.0, lengthAfter = 0.0;  ///< summed path lengths
};

/// Straighten every path of a valid layout (see the file comment). Keeps `edges`, `patches`,
/// `rotation`, `facePatch`, `edgePath` and `faceCluster` consistent; `validateLayout` holds
/// afterwards whenever the status is ok. Cancelled when `progress` says stop (reported per path;
/// the layout is then partly straightened and must be discarded, as after an error).
PathStraighteningResult straightenPaths(Layout& layout, const PathStraighteningOptions& options = {},
                                        const Progress& progress = {});

}  // namespace cbd
