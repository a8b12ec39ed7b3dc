#pragma once
/// @file greedy_layout.h
/// The baseline of Kwok et al. 2012: common base domains by the greedy shortest-path method of
/// Kraevoy & Sheffer 2004 ("Cross-parameterization and compatible remeshing of 3D models"),
/// as the paper describes it (Sec. 1.1, 2, 6), on the same edge-node graph and data structures
/// as the Voronoi method:
///  1. the shortest path between every pair of anchors on both meshes, over the whole surfaces
///     (one single-source search per anchor and mesh), queued by the sum of the two lengths;
///  2. candidates taken in that order and traced anew over the current partial layouts; one is
///     accepted only if it is valid on both meshes: no crossing (face regions), the same cyclic
///     order at both anchors on both meshes, and no blocking (the regions of both partial
///     layouts keep the same boundaries and the same anchors inside) — trial and error;
///  3. when the queue is exhausted, regions that are not triangles are completed by extra paths
///     inside corresponding regions ("face paths"); a pair of anchors is never linked twice,
///     which is why the method fails where multiple linkages are needed (the paper's Fig. 1);
///  4. post-processing granted for fairness: path flipping (an edge is replaced by the other
///     diagonal of its two patches when that is shorter on both meshes together).

#include <string>
#include <vector>

#include "cbd/layout.h"
#include "cbd/progress.h"
#include "cbd/path_tracer.h"

namespace cbd {

/// Options of `buildGreedyLayout`.
struct GreedyLayoutOptions {
  EdgeNodeOptions edgeNodes;  ///< same graph as the Voronoi method
  bool flipPaths = true;      ///< post-processing: path flipping
  std::vector<std::string> anchorNames;  ///< for messages (`anchorLabel`); empty: by position
};

/// Result of `buildGreedyLayout`: two isomorphic layouts (patch k corresponds to patch k).
struct GreedyLayoutResult {
  Status status;            ///< LayoutFailed names the region that could not be completed
  Layout source, target;
  int candidates = 0;       ///< anchor pairs queued
  int tried = 0;            ///< candidates traced
  int accepted = 0;         ///< candidates that became layout edges
  int rejected = 0;         ///< candidates traced and undone (order, blocking, unreachable)
  int completionPaths = 0;  ///< extra paths added to complete non-triangular regions
  int completionRejected = 0;  ///< completion paths traced and undone (order, blocking)
  int flips = 0;            ///< edges replaced by path flipping
  double candidateSeconds = 0.0;  ///< all-pairs shortest paths on both meshes
  double layoutSeconds = 0.0;     ///< trial and error, completion and flipping
};

/// Build common base domains on a source/target pair with corresponding anchor vertices
/// (validated surfaces of the same genus). Errors: InvalidArgument, LayoutFailed, Cancelled
/// (`progress` said stop; reported per pair searched and per edge linked).
GreedyLayoutResult buildGreedyLayout(const IndexedMesh& source, const std::vector<int>& sourceAnchors,
                                     const IndexedMesh& target, const std::vector<int>& targetAnchors,
                                     const GreedyLayoutOptions& options = {}, const Progress& progress = {});

/// Result of `flipLayoutPaths`.
struct PathFlippingResult {
  Status status;
  int flips = 0;         ///< edges replaced by the other diagonal of their two patches
  double seconds = 0.0;
};

/// The greedy method's path flipping (step 4 above, the same code) as a post-process of any
/// two isomorphic layouts, e.g. the Voronoi method's, so that both methods can be given the
/// post-processing the paper grants the baseline: every edge in turn is replaced by the other
/// diagonal of its two patches when that is shorter on both surfaces together and both layouts
/// stay consistent (cyclic order, regions); a pair of anchors already linked is not linked
/// again. A replaced edge becomes `EdgeKind::Flipped`; patches are assembled anew, patch k
/// still corresponding to patch k. The layouts keep their meshes (paths cut in since stay
/// split). Errors: InvalidArgument when the layouts are not a complete isomorphic pair;
/// InternalError from the layout checks (the layouts are then unusable: their meshes may hold
/// paths their edges do not list).
PathFlippingResult flipLayoutPaths(Layout& source, Layout& target, const EdgeNodeOptions& edgeNodes);

}  // namespace cbd
