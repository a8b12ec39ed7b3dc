#pragma once
/// @file target_layout.h
/// Sec. 5.2 and Procedure 1 of Kwok et al. 2012: the common base domain on the target. The
/// source layout's edges are traced between the corresponding target anchors, in the paper's
/// order: (a) pairs with one source edge whose target clusters share exactly one cut, (b) pairs
/// with one source edge whose target clusters share no cut, (c) multiple linkages, postponed
/// while two of them would leave an anchor in the same sector, and retried. Within that order,
/// a path whose source counterpart runs through the cluster of a third anchor waits until that
/// anchor has a path of its own on the target (`waitForPassedAnchors`): then the cyclic order
/// and region checks at that anchor decide on which side the path passes it. Traced before,
/// it may pass on the other side, and the paths traced later round that anchor keep their
/// cyclic order only by winding round the limb.
///
/// Every path obeys the constraints of Praun et al. 2001 that make the two layouts isomorphic:
/// no crossing (face regions, as on the source); cyclic order (it leaves both anchors inside the
/// sector that the source's rotation system prescribes among the edges embedded so far); no
/// blocking (it stays inside the region of the partial target layout that corresponds to the
/// source region it lies in, and after it is cut in, the regions of the partial layouts on both
/// surfaces have the same boundaries, edge for edge, and the same anchors inside). A path is
/// searched first inside the two anchors' target clusters (fast), then in growing rings of
/// neighbouring clusters (paths stay local, so they do not swirl), then in the whole region.
/// When no pending edge can be traced (on high genus the shortest path may pass a handle on
/// another side than the source's, with the same anchors on each side), a refused edge is traced
/// again with the faces its refused paths ran through closed (`closedCorridorRounds`).
///
/// The same edges can instead be traced in the source's construction order with the source's
/// own queries (`Order::Source`), which reproduces a layout traced onto its own surface; by
/// default it is the fallback when Procedure 1's order gets stuck (`Order`).

#include <string>
#include <vector>

#include "cbd/layout.h"
#include "cbd/progress.h"
#include "cbd/path_tracer.h"
#include "cbd/voronoi.h"

namespace cbd {

/// Options of `buildTargetLayout`.
struct TargetLayoutOptions {
  EdgeNodeOptions edgeNodes;  ///< as on the source
  /// A path whose source path runs through the clusters of other anchors is postponed until
  /// each of those anchors has a path on the target (unless nothing else can be traced). Needs
  /// the source layout's `faceCluster`; without it, or when false, Procedure 1's order alone.
  bool waitForPassedAnchors = true;
  std::vector<std::string> anchorNames;  ///< for messages (`anchorLabel`); empty: by position
  /// The source layout is partial (a stuck source layout: paths, edgePath and rotation, no
  /// patches): trace its paths and stop there, `layout` without patches. Its regions then match
  /// the source's, signature for signature (no blocking), which is what anchor_pairs.h needs.
  bool partial = false;
  /// The last resort before failing, when no pending edge can be traced: an edge whose shortest
  /// path is refused by blocking is traced again with the faces its refused paths ran through
  /// closed (so the next path passes the region's handles on another side), at most this many
  /// times per edge. 0: fail at once. Layouts that complete without it are not changed by it.
  int closedCorridorRounds = 6;
  /// The order the paths are traced in, and with which queries.
  enum class Order {
    Procedure1,  ///< the paper's, as described above
    /// The source's construction order with the source's own queries: a cut path inside the
    /// two anchors' target clusters through one target cut of the pair at a time; then any
    /// path through the target clusters its source path passes, then through those within two
    /// rings of faces of it, then in its region. Each path is then traced into a partial layout whose regions match those its
    /// source path was traced in, so a layout traced onto its own surface is reproduced (where
    /// Procedure 1's order, built for diagrams that differ, may pass a handle on the other
    /// side and get stuck). Where the two Voronoi diagrams differ, a cut path may have no
    /// counterpart cut and fall back to its region.
    Source,
    Procedure1ThenSource,  ///< Procedure 1, and the source's order when Procedure 1 gets stuck
    /// Both, and the layout whose paths keep the lengths of their source paths best
    /// (`lengthDetour`; Procedure 1's on a tie). For surfaces with handles, where Procedure 1's
    /// order may complete a layout whose paths wind round a handle.
    Shorter,
  };
  Order order = Order::Procedure1ThenSource;
};

/// How many candidates `TargetLayoutResult::handleTargetVertices` offers.
constexpr int kHandleCandidates = 8;

/// Result of `buildTargetLayout`.
struct TargetLayoutResult {
  Status status;                  ///< LayoutFailed names the edge and the reason
  Layout layout;                  ///< isomorphic to the source: same edge ids, patch k = source patch k
  CutsResult cuts;                ///< target cuts
  int embeddedInClusters = 0;     ///< paths found inside the two target clusters
  int embeddedInRegion = 0;       ///< paths that needed more: neighbouring clusters, or the whole region
  int postponements = 0;          ///< times an edge was postponed (ambiguous sector, waiting for a passed
                                  ///< anchor, or no valid path yet)
  int waitedForPassedAnchors = 0; ///< edges postponed at least once to wait for an anchor they pass
  int rejectedPaths = 0;          ///< traced paths undone because they blocked (region mismatch)
  int pastClosedCorridors = 0;    ///< paths found only with refused paths' corridors closed
  bool inSourceOrder = false;     ///< traced in the source's order (asked for, or kept over Procedure 1's)
  std::string procedure1Failure;  ///< when Procedure 1's order was tried first and got stuck: where and why
  double procedure1Detour = 0.0;  ///< when Procedure 1's layout completed but the source order's was kept: its detour
  /// LayoutFailed where the source's path runs round a handle of its region and every target
  /// path tried cuts the corresponding region in two: a source input vertex at that handle (on
  /// the shortest loop of a homology basis of the region, by tree-cotree), which the message
  /// names: an anchor pair there lets the layouts pass the handle. -1 otherwise.
  int handleSourceVertex = -1;
  /// With `handleSourceVertex`, candidates for its counterpart, best first (at most
  /// `kHandleCandidates`): in the region of the target's partial layout that matches the source
  /// vertex's region (same boundary paths, anchors and topology), the input vertices placed most
  /// alike relative to its sides. Empty when there are none.
  std::vector<int> handleTargetVertices;
  double voronoiSeconds = 0.0;
  double layoutSeconds = 0.0;
};

/// Trace the source layout on the target surface. `targetAnchors[i]` corresponds to source
/// anchor i. Errors: InvalidArgument (anchor count or indices), LayoutFailed (naming the edge
/// each order tried got stuck at), Cancelled (`progress` said stop; reported per embedded edge;
/// with `Shorter` each order takes half, and the fallback of `Procedure1ThenSource` restarts it).
TargetLayoutResult buildTargetLayout(const Layout& source, const IndexedMesh& target,
                                     const std::vector<int>& targetAnchors, const TargetLayoutOptions& options = {},
                                     const Progress& progress = {});

/// Reorder the patches of `target` (same edge ids as `source`) so that patch k has the corners
/// and sides of source patch k, starting at the same corner; `facePatch` follows.
/// InternalError when a source patch has no counterpart.
Status alignPatches(const Layout& source, Layout& target);

/// Check that two layouts are isomorphic with the identity correspondence: same anchors count,
/// same edges (same anchor pairs), same patches in the same order (same corners, same sides
/// with the same directions), same rotation system up to a cyclic shift. InternalError naming
/// the first difference.
Status checkIsomorphic(const Layout& source, const Layout& target);

}  // namespace cbd
