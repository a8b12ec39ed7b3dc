#pragma once
/// @file pipeline.h
/// The whole method as one call, for the CLI, the plugin, the tests and the benchmark alike:
/// validated input -> common base domains (Voronoi method, or the greedy baseline) ->
/// patch parameterizations -> composed cross-map -> distortion. Every intermediate result is
/// returned.

#include <string>
#include <vector>

#include "cbd/anchor_pairs.h"
#include "cbd/distortion.h"
#include "cbd/greedy_layout.h"
#include "cbd/map_optimization.h"
#include "cbd/map_smoothing.h"
#include "cbd/map_untangle.h"
#include "cbd/parameterization.h"
#include "cbd/path_straightening.h"
#include "cbd/source_layout.h"
#include "cbd/target_layout.h"

namespace cbd {

/// How the common base domains are built.
enum class LayoutMethod {
  Voronoi,  ///< Kwok, Zhang & Wang 2012 (this project's method)
  Greedy    ///< Kraevoy & Sheffer 2004, the paper's baseline
};

const char* layoutMethodName(LayoutMethod m);

/// The name of the k-th anchor pair the layouts added (0-based): "added1", "added2", ...
std::string addedAnchorName(int k);

/// The last stage of the cross-map, after the composition.
enum class MapStage {
  Untangle,  ///< remove flipped triangles from M_st and M_ts, then polish (map_untangle.h)
  /// Experimental: M_st optimized in the base domain, injective there, M_ts its inverse
  /// (map_optimization.h); see README for what it does not reach yet.
  Optimize
};

/// Options of `buildLayouts` / `crossParameterize`.
struct CrossParameterizationOptions {
  LayoutMethod method = LayoutMethod::Voronoi;
  EdgeNodeOptions edgeNodes;            ///< b = 3 adaptive; {1, false} is the paper's E1
  ParameterizationOptions parameterization;
  /// Voronoi method: when the target layout's paths detour (`lengthDetour` above this), or it
  /// fails, the layout is also built the other way round — from the target's Voronoi diagram,
  /// traced on the source — and the one with the smaller detour is kept. 0: never.
  double reverseDetour = 2.0;
  /// When the layouts kept detour more than this (`LayoutPair::detour`), `LayoutPair::warnings`
  /// says the anchors may not correspond in shape: corresponding anchors give detours well below
  /// it, anchors swapped left for right above it (test_pipeline checks both on the bundled
  /// pair). 0: never. Also where an anchor pair is added at a handle the target layout got stuck
  /// at: while the layout detours more than this, the pair's other candidate target vertices are
  /// tried (target_layout.h, `handleTargetVertices`); 0: all of them.
  double detourWarning = 1.8;
  /// Voronoi method: where the source layout gets stuck in a region no path can split (a handle
  /// smaller than the anchor spacing; anchor_pairs.h), or the target layout at a handle no target
  /// path passes as the source's does (target_layout.h), add an anchor pair there and build both
  /// layouts again, at most this many times; -1: 4 x genus + 2; 0: never (the layout fails).
  int maxAnchorPairs = -1;
  /// Voronoi method: the greedy baseline's path flipping (`flipLayoutPaths`) applied to its
  /// layouts too, after they are built (the baseline always flips, as the paper grants it).
  bool flipPaths = false;
  /// Greedy method: its path flipping (step 4 of greedy_layout.h; off only to measure what the
  /// flipping does, as `cbd_bench flipping` does).
  bool greedyFlipPaths = true;
  /// Both layouts' paths straightened inside their two patches (path_straightening.h), for either
  /// method alike; 0 rounds: the paths as traced.
  PathStraighteningOptions straightening;
  MapSmoothingOptions smoothing;        ///< 0 iterations: the composed map as it is
  bool untangle = true;                 ///< run `mapStage` (false: the composed map as it is)
  MapStage mapStage = MapStage::Untangle;
  MapUntangleOptions untangling;
  MapOptimizationOptions optimization;
  /// The anchors' names, in the order of the anchor vectors (both sides alike), for the layout
  /// builders' messages; empty: anchors are named by their position.
  std::vector<std::string> anchorNames;
};

/// The accepted values of an integer option: one place for the front ends' ranges and `validate`.
struct IntRange {
  int lo, hi;
  constexpr bool contains(int v) const { return v >= lo && v <= hi; }
};
inline constexpr IntRange kMinEdgeNodesRange{1, 16};        ///< EdgeNodeOptions::minEdgeNodes
inline constexpr IntRange kStraightenRoundsRange{0, 8};     ///< every round splits mesh edges
inline constexpr IntRange kSmoothingIterationsRange{0, 1000};

/// InvalidArgument naming the first option out of its range (edge nodes, straightening rounds,
/// smoothing iterations, the detour thresholds); `buildLayouts` and `crossParameterize` check it
/// first, so every front end gets the same message.
Status validate(const CrossParameterizationOptions& options);

/// Seconds spent in each stage.
struct StageTimes {
  double voronoi = 0.0;          ///< Voronoi clusters on both surfaces (0 for greedy)
  double sourceLayout = 0.0;     ///< greedy: all-pairs paths + trial and error (both surfaces)
  double targetLayout = 0.0;     ///< Voronoi: + path flipping, when on
  double straighten = 0.0;       ///< path straightening on both surfaces
  double parameterization = 0.0; ///< both surfaces' patch maps + composition (+ smoothing)
  double untangle = 0.0;         ///< the map stage: untangling M_st and M_ts, or the optimization
  double distortion = 0.0;
  double total = 0.0;
};

/// Two isomorphic layouts (patch k on the source corresponds to patch k on the target).
struct LayoutPair {
  Status status;
  LayoutMethod method = LayoutMethod::Voronoi;
  Layout source, target;
  SourceLayoutResult sourceStats;   ///< Voronoi method: counters (its layout moved to `source`)
  TargetLayoutResult targetStats;
  GreedyLayoutResult greedyStats;   ///< greedy: counters (its layouts moved out)
  StageTimes times;                 ///< both directions when the reverse was tried
  double detour = 1.0;              ///< lengthDetour(source, target) of the layouts kept, as traced
  bool triedReverse = false;        ///< Voronoi: the layout was also built from the target's diagram
  bool reversed = false;            ///< ... and that one was kept (its statistics are in sourceStats /
                                    ///< targetStats with the roles of the surfaces swapped)
  double reverseDetour = 0.0;       ///< the detour of the layout pair not kept (0: failed)
  int flips = 0;                    ///< Voronoi with `flipPaths`: edges replaced by path flipping
  /// Voronoi: the target is the source itself (same vertices, faces and anchors), so its layout
  /// is the source's rather than one traced again in Procedure 1 order (which, on the same
  /// surface, can take other shortest paths where paths compete for vertices).
  bool sameSurface = false;
  /// Voronoi method: the anchor pairs added (`maxAnchorPairs`), as (source vertex, target
  /// vertex) of the input meshes, in the order added; the layouts' anchors are the given ones
  /// followed by these, named `addedAnchorName(k)`.
  std::vector<std::pair<int, int>> addedAnchors;
  /// What the caller should tell the user (the layouts are valid): a detour above
  /// `detourWarning`.
  std::vector<std::string> warnings;
};

/// Build both layouts with the chosen method and check them (validateLayout on both surfaces,
/// checkIsomorphic). `euler` is the surfaces' Euler characteristic. Cancelled when `progress`
/// says stop.
LayoutPair buildLayouts(const IndexedMesh& source, const std::vector<int>& sourceAnchors, const IndexedMesh& target,
                        const std::vector<int>& targetAnchors, int euler, const CrossParameterizationOptions& options,
                        const Progress& progress = {});

/// Everything `crossParameterize` computed.
struct CrossParameterizationResult {
  Status status;
  LayoutPair layouts;                 ///< straightened, collinear faces split for parameterization
  /// Path straightening of each layout. When either failed or its result did not validate (that
  /// one's status says why), both layouts are kept as traced and `straightenFailed` is set; the
  /// counts are then of the attempt thrown away.
  PathStraighteningResult straightenSource, straightenTarget;
  bool straightenFailed = false;
  PatchParameterization sourceParam, targetParam;
  CrossMap map;
  MapSmoothingResult smoothing;
  MapUntangleResult untangleSource;   ///< M_st (source vertices on the target)
  MapUntangleResult untangleTarget;   ///< M_ts (target vertices on the source)
  MapOptimizationResult optimization; ///< with MapStage::Optimize
  DistortionMetrics metrics;          ///< of M_st against the source
  /// The same of M_st as composed, before untangling: what the base domains and their patch
  /// maps give by themselves (after `smoothing`, when asked for; equal to `metrics` when
  /// untangling is off).
  DistortionMetrics composedMetrics;
  StageTimes times;
};

/// Cross-parameterize two validated surfaces of equal genus with corresponding anchors.
/// `progress` (optional) sees the run's percentage and stage names through every stage; when it
/// says stop the run ends with ErrorCode::Cancelled.
CrossParameterizationResult crossParameterize(const IndexedMesh& source, const std::vector<int>& sourceAnchors,
                                              const IndexedMesh& target, const std::vector<int>& targetAnchors,
                                              int euler, const CrossParameterizationOptions& options = {},
                                              const Progress& progress = {});

}  // namespace cbd
