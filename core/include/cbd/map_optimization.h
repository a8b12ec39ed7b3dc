#pragma once
/// @file map_optimization.h
/// Experimental last stage of the cross-map (`MapStage::Optimize`; the default is the untangling
/// of map_untangle.h): M_st optimized in the common base domain D (base_domain.h), after Schmidt,
/// Campen, Born & Kobbelt 2019, "Distortion-minimizing injective maps between surfaces".
///
/// Variables: the point of D of every vertex of the source layout's refined mesh (the source with
/// every path cut in) but the anchors, which stay at D's corners. The composed map is injective in
/// D (each patch is a convex-combination map onto its triangle: Floater), so no untangling is
/// needed, and every step keeps every face's area in D positive.
/// Energy: per face, its area share times the symmetric Dirichlet energy of its map onto its image
/// on the target (both surfaces scaled to one area), plus `conformalWeight` times the conformal
/// energy (s1/s2 + s2/s1)/2. The image is the triangle through its corners' images; its area ratio
/// enters as the geometric mean of the chord's and the one the target's parameterization predicts
/// from the face's area in D, so the energy grows without bound as a face degenerates in D or on
/// the target.
/// Solver: projected Newton (a positive semi-definite model per face, one sparse Cholesky
/// factorization per iteration); the line search starts at 0.9 of the largest step before a face's
/// area in D reaches zero (Smith & Schaefer 2015) and halves until the energy falls enough. Where
/// the energy has a kink (a vertex on an edge of the target's parameterization) and Newton's
/// direction climbs, those vertices sit the step out; failing that, a diagonally scaled gradient
/// step. Vertices move across patch sides by walks in D.
///
/// Contract:
/// - status Ok: every face has positive area in D at every iteration and the areas sum to D's: M_st
///   is a bijection of the source onto the target through D (`injective`);
/// - M_ts is its exact inverse: every target vertex's point of D located among the source's faces;
/// - it stops when a Newton iteration lowers the energy by less than `tolerance` of itself, when
///   no step lowers it at all, or after `maxIterations` (`stop` says which); `converged` only when
///   that last Newton step was not cut short by the injectivity bound (`boundedSteps` counts the
///   iterations that were: a descent whose every step is cut stalls, see docs/algorithm.md);
/// - it does not keep the image triangles of M_st from facing away from the target (the
///   metrics' `flipped`): see README's known limitations;
/// - errors: Cancelled (the progress callback said stop), InternalError (a broken invariant).

#include <array>
#include <vector>

#include "cbd/base_domain.h"
#include "cbd/mesh.h"
#include "cbd/progress.h"

namespace cbd {

/// Options of `optimizeCrossMap`.
struct MapOptimizationOptions {
  /// Weight of the conformal energy beside the symmetric Dirichlet energy (0: none): trades
  /// stretch (E_L2) for angles (E_ang).
  double conformalWeight = 0.0;
  /// Stop when a Newton iteration lowers the energy by less than this fraction of it.
  double tolerance = 1e-4;
  int maxIterations = 200;  ///< Newton iterations at most (a safety net: `converged` says which ended it)
  int threads = 0;          ///< worker threads for the per-face terms; 0: one per hardware thread
};

/// Why `optimizeCrossMap` stopped.
enum class MapOptimizationStop {
  Tolerance,      ///< a Newton iteration lowered the energy by less than `tolerance` of itself
  NoDescent,      ///< no step (Newton's, with kinks held, or a scaled gradient) lowered it at all
  MaxIterations,  ///< `maxIterations` reached
};

/// What `optimizeCrossMap` did and found.
struct MapOptimizationResult {
  Status status;
  int iterations = 0;  ///< Newton iterations
  MapOptimizationStop stop = MapOptimizationStop::MaxIterations;
  /// Iterations whose step the injectivity bound cut short of the full step (Newton's 1, or the
  /// gradient's): while it holds every step, the descent loses Newton's fast local convergence.
  int boundedSteps = 0;
  /// Stopped on `tolerance` after a step the bound left whole: a minimum, not a stall.
  bool converged = false;
  double energyBefore = 0.0;  ///< of the composed map
  double energyAfter = 0.0;
  bool injective = false;     ///< every face positive in D and the areas summing to D's
  /// Per vertex of the source layout's refined mesh its point of D, and per face its corners'
  /// chart maps: with them, `TrianglesInDomain` locates any point of D on the source.
  std::vector<DomainPoint> sourcePoints;
  std::vector<std::array<ChartMap, 3>> sourceCharts;
};

/// Optimize M_st in D and derive M_ts from it.
/// @param[in] source, target        the input surfaces (validated)
/// @param[in] sourceInD, targetInD  the two surfaces mapped onto D by their layouts (isomorphic,
///                                  aligned patches) and patch parameterizations
/// @param[in] domain                D, built from either layout
/// @return M_st and M_ts: sourceToTarget / sourceImage for every source input vertex,
///         targetToSource / targetImage for every target input vertex; `result` says how.
CrossMap optimizeCrossMap(const IndexedMesh& source, const IndexedMesh& target, const SurfaceInDomain& sourceInD,
                          const SurfaceInDomain& targetInD, const BaseDomain& domain,
                          const MapOptimizationOptions& options, MapOptimizationResult& result,
                          const Progress& progress = {});

}  // namespace cbd
