#pragma once
/// @file map_untangle.h
/// Last stage of the cross-map: removing flipped triangles from M_st (the source's triangles
/// at their images on the target).
///
/// The composed map is bijective between the two surfaces (both patch maps are convex-
/// combination maps onto the same triangle), but M_st joins the images of the source's
/// vertices by straight chords. Where a source triangle's image covers target faces whose
/// parameterization Jacobians differ a lot, or straddles a sharp crease of the target, the
/// chord triangle can face the wrong way: a flip (`TargetNormals::flipped`). This stage moves the images
/// of the vertices of such triangles over the target surface (straight walks across target
/// faces, so an image never leaves the surface) to unflip them:
/// 1. local moves of a flipped triangle's vertices (towards averages of the neighbours'
///    images, across opposite edges, on rings of directions) that reduce the vertex's bad
///    triangles without leaving one distorted beyond `maxDistortion` (or, for one that is
///    already, beyond what it is);
/// 2. relaxation of a growing ring around what is left that never adds a bad triangle;
/// 3. whole-region convex-combination relaxation of folds, kept when it helps;
/// 4. for what is still left, Gauss-Seidel minimisation of a smooth energy that stays finite
///    on flipped triangles (conformal + area terms over the regularised signed area of
///    Escobar et al. 2003, "Simultaneous untangling and smoothing of tetrahedral meshes", plus
///    `energyStretchWeight` times the triangle's share of E_L2; areas measured against the
///    region's own scale in the composed map), over each connected region of rings at once,
///    kept when it has fewer bad triangles;
///    then, if flips are left, stages 1-4 once more with looser bounds (`lastResortFactor`),
///    each attempt kept only if E_L2 grows by at most `maxStretchGrowth`;
/// 5. if flips are left, stages 1-4 again from the composed map with the bounds of
///    `retryDistortions`, keeping the best;
/// 6. if flips next to anchors are left, stages 1-4 once more per such anchor from the map
///    kept, a disk round the anchor first laid out anew (`anchorRestartRings`); if flips are
///    still left, stages 1-4 again from the composed map with wider rings (`retryMaxRing`),
///    then, for flips next to anchors, the anchor restarts once more with those wider rings;
/// 7. on the map kept, up to `polishSweeps` sweeps of single-vertex moves over the whole map:
///    of a vertex's candidates (half way to its neighbours' mean-value average, steps along the
///    steepest descent) the one that lowers E_ang x E_L2^`polishStretchWeight` most
///    (`polishProduct`; else that raises neither metric and lowers one) and turns no triangle
///    bad (so the flip count cannot grow); stops when a sweep gains less than `polishTolerance`.
/// When stages 1-6 leave more flips than the composed map had, the composed map is kept.
/// Stages 1-6 run only when the map has flipped triangles; the polish runs on every map, so a
/// composed map that happens to have no flip is polished like one that has. A map without angle
/// distortion but for rounding (the identity) is returned unchanged.
/// Internally a triangle counts as flipped by the stricter `imageFlipped`; what is reported is
/// the metrics' count (`TargetNormals::flipped`). Vertices marked `fixed` (the given anchors) never move.

#include <cstdint>
#include <vector>

#include "cbd/mesh.h"
#include "cbd/parameterization.h"
#include "cbd/progress.h"
#include "cbd/target_normals.h"

namespace cbd {

/// Options of `untangleCrossMap`.
struct MapUntangleOptions {
  int maxRounds = 40;     ///< rounds of (local moves, relaxation of a ring, of folds) at most
  /// Widest ring (in source edges) around a flip that relaxation may move: wide enough for folds
  /// across a thin limb, narrow enough that the rest of the map stays as composed.
  int maxRing = 10;
  /// A move may not leave a triangle of the vertex with a distortion above this (angle
  /// distortion (s1/s2 + s2/s1)/2 - 1 plus the same of its area ratio to the global one),
  /// unless one was already: trading a flip for a badly stretched triangle is no gain (a
  /// higher bound removes more flips and raises E_L2).
  double maxDistortion = 10.0;
  /// Sweeps over all vertices at the end (the polish) whose moves lower the metrics and add no
  /// flip (0: only the neighbourhoods of flips are touched). Gauss-Seidel converges slowly, so
  /// the cap is generous; `polishTolerance` ends it earlier.
  int polishSweeps = 100;
  /// The polish keeps a move when it lowers E_ang x E_L2^polishStretchWeight (true), or only
  /// when it raises neither metric and lowers one (false). The product lets a move trade a
  /// little of one for more of the other, which badly stretched triangles need.
  bool polishProduct = true;
  double polishStretchWeight = 2.0;
  /// The polish stops early when a sweep lowers that product (else: either metric) by less
  /// than this fraction.
  double polishTolerance = 1e-5;
  /// The order the polish visits the vertices in: 0 by index, else a permutation drawn from this
  /// seed. The polish is a local descent whose end point depends on that order in the third
  /// digit; the benchmark runs several seeds to tell differences between methods from that spread.
  std::uint64_t polishOrderSeed = 0;
  /// Gauss-Seidel sweeps of the smooth untangling energy over the rings of what local moves
  /// left flipped (0: none).
  int energySweeps = 30;
  /// Weight of the triangle's share of E_L2 (image area x |J|^2 / 2, in the region's scale) in
  /// that energy: without it, regions the composed map compresses are spread out over their
  /// neighbours, and E_L2 (which weighs expansion by the image area) grows.
  double energyStretchWeight = 0.3;
  int energyPasses = 4;   ///< repeats of those sweeps (regions taken anew) while flips go down
  /// When flips are left, stages 1-4 once more with `maxDistortion` times this, then times its
  /// square (<= 1: not)...
  double lastResortFactor = 10.0;
  /// ... each such attempt kept only if the map's L2 stretch grows by at most this factor.
  double maxStretchGrowth = 1.05;
  /// When flips survive all that, the whole untangling again from the composed map with each
  /// of these `maxDistortion` bounds in turn, until one leaves no flip; the result with the
  /// fewest flips, then the lowest E_ang x E_L2^polishStretchWeight (the polish's objective), is
  /// kept (the outcome of the greedy local moves depends on the bound in no monotone way).
  /// Empty: one run.
  std::vector<double> retryDistortions = {5.0, 3.0, 7.0};
  /// When flips next to an anchor survive that, the untangling once more from the map kept,
  /// per such anchor and per entry here, with the disk of that many source rings round the
  /// anchor first laid out anew (the source's disk flattened round the anchor's image; vertices
  /// as near another anchor stay, see `relayAnchorDisk`): a star the composed map folds into a
  /// wedge gives way to no local move. Every entry is tried from the same map; the run with the
  /// fewest flips, then the lowest E_ang x E_L2^polishStretchWeight, is kept when it leaves
  /// fewer flips than that map. Empty: none; entries below 1 are skipped.
  std::vector<int> anchorRestartRings = {2, 3, 4};
  /// When flips survive even that, the untangling once more from the composed map with
  /// `maxRing` widened to this (relaxation and energy reach that far round a flip), with
  /// `maxDistortion` and then each of `retryDistortions`, until one leaves no flip; kept by the
  /// same rule (fewer flips, or as few and a lower E_ang x E_L2^polishStretchWeight): for folds
  /// far from every anchor (long thin parts such as fingers) that `maxRing` rings cannot undo.
  /// Not the default `maxRing`, because wider rings everywhere move maps that had no such fold.
  /// After it, flips next to anchors get the anchor restarts once more, untangled with these
  /// rings (a star folded against a bundle of paths leaving the anchor at nearly one angle).
  /// <= maxRing: never.
  int retryMaxRing = 20;
};

/// What `untangleCrossMap` did.
struct MapUntangleResult {
  Status status;
  int flippedBefore = 0;  ///< flipped image triangles before (same test as the metrics)
  int flippedAfter = 0;    ///< flipped image triangles of the map returned
  int degenerateAfter = 0; ///< image triangles of the map returned with (nearly) no area
  int moves = 0;           ///< accepted vertex moves that made the map returned
  int movedVertices = 0;  ///< distinct vertices whose image changed
  int attempts = 0;       ///< runs of the whole untangling (0: there was no flip)
};

/// The untangling's own, stricter test: the image triangle's normal points against the sum of
/// the normals of the target faces its three corners were located in (at a corner on an edge
/// or vertex, one of the faces touching it). Whatever it passes, `TargetNormals::flipped`
/// passes. `targetFaceNormal` holds the unit normal of every target face.
bool imageFlipped(const Vec3& i0, const Vec3& i1, const Vec3& i2, const std::vector<Vec3>& targetFaceNormal,
                  int face0, int face1, int face2);

/// The restart of `anchorRestartRings`: lays the disk of `rings` source rings round `anchor` out
/// anew round the anchor's image (the source's disk flattened into the anchor's tangent plane,
/// scaled to the present mean distance of its neighbours' images, turned to fit the images of the
/// vertices round the disk, put on the target by straight walks from the anchor's image). The
/// disk holds only the vertices nearer (in rings) to `anchor` than to any other fixed vertex:
/// other anchors and their neighbourhoods stay. False (nothing moved) on an index out of range,
/// or a disk holding an unmapped vertex.
bool relayAnchorDisk(const IndexedMesh& source, const IndexedMesh& target, const std::vector<char>& fixed, int anchor,
                     int rings, std::vector<FacePoint>& onTarget, std::vector<Vec3>& image);

/// Move the images of source vertices over `target` until no triangle of M_st is flipped.
/// @param[in] source       the source surface (connectivity of M_st)
/// @param[in] target       the surface the images lie on
/// @param[in] fixed        per source vertex: 1 when its image must not move (anchors)
/// @param[in,out] onTarget per source vertex: its image as a target face + barycentric
///                         coordinates (face -1: unreferenced, ignored)
/// @param[in,out] image    per source vertex: the 3D point of `onTarget`
/// Pre-condition: `target` passed `validateMesh` (closed manifold, no degenerate face).
/// Never fails on valid input; `flippedAfter` > 0 says what could not be untangled. Cancelled
/// when `progress` says stop (the map is then partly moved and must be discarded).
MapUntangleResult untangleCrossMap(const IndexedMesh& source, const IndexedMesh& target,
                                   const std::vector<char>& fixed, std::vector<FacePoint>& onTarget,
                                   std::vector<Vec3>& image, const MapUntangleOptions& options = {},
                                   const Progress& progress = {});

}  // namespace cbd
