#pragma once
/// @file source_layout.h
/// Sec. 5.1 of Kwok et al. 2012: the base domain on the source model. Voronoi clusters of the
/// anchors, one path across every cut (restricted to the two clusters, through that cut only,
/// so anchor pairs whose clusters share several cuts get multiple linkages), then the regions
/// that are not triangles are triangulated by paths searched inside them.

#include <string>
#include <vector>

#include "cbd/layout.h"
#include "cbd/path_tracer.h"
#include "cbd/progress.h"
#include "cbd/voronoi.h"

namespace cbd {

/// Options of `buildSourceLayout`.
struct SourceLayoutOptions {
  EdgeNodeOptions edgeNodes;        ///< b = 3 adaptive (the paper's C); b = 1 fixed is E1
  /// Cap on the paths added to triangulate the regions the cut paths leave; -1: 4 * anchors + 64.
  /// A finished layout has 3 (anchors - 2 + 2 genus) paths, so when the cut paths leave more
  /// than this to add, the layout fails (LayoutFailed, with those counts) before any search.
  int maxTriangulationPaths = -1;
  std::vector<std::string> anchorNames;  ///< for messages (`anchorLabel`); empty: by position
};

/// Result of `buildSourceLayout`: the layout and every intermediate stage.
struct SourceLayoutResult {
  Status status;                 ///< LayoutFailed names the region and the reason
  Layout layout;
  CutsResult cuts;               ///< on the mesh before the paths were cut in
  int cutPaths = 0;              ///< paths traced across cuts
  int cutPathsFailed = 0;        ///< cuts no path could cross (left to the triangulation)
  int triangulationPaths = 0;    ///< paths added to triangulate regions
  int removedPaths = 0;          ///< paths removed because they bounded an empty 2-gon
  /// Triangulation paths taken back as soon as they were traced, because they left a piece no
  /// path can triangulate (two anchors for corners, none inside; not counted in
  /// `triangulationPaths`).
  int rejectedPaths = 0;
  double voronoiSeconds = 0.0;
  double layoutSeconds = 0.0;    ///< cuts, paths and triangulation
  /// LayoutFailed because no path can split a region (a handle smaller than the anchor spacing,
  /// typically): `layout` then holds the paths traced so far (edges, edgePath, faceCluster and
  /// rotation; no patches), `stuckRegion` is that region's signature in it, and `stuckVertex`
  /// the input vertex deepest inside it (`RegionDistances::deepest`), where an added anchor lets the
  /// layout go on (anchor_pairs.h); -1 when the region has none off its boundary.
  bool stuck = false;
  RegionSignature stuckRegion;
  int stuckVertex = -1;
};

/// Build the base domain on a validated closed surface with anchors at the given vertices
/// (distinct, at least 3). Errors: InvalidArgument (bad anchor indices), LayoutFailed, Cancelled
/// (`progress` said stop; reported per path, as the share of the 3 (anchors - chi) paths).
SourceLayoutResult buildSourceLayout(const IndexedMesh& mesh, const std::vector<int>& anchorVertices,
                                     const SourceLayoutOptions& options = {}, const Progress& progress = {});

}  // namespace cbd
