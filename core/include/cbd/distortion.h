#pragma once
/// @file distortion.h
/// How much a cross-parameterization distorts, measured on M_st (the source's triangles at
/// their images on the target) against the source triangles: the L2-stretch of Sander et al.
/// 2001 and the angle distortion used by Kwok et al. 2012 (Sec. 6), plus flipped and
/// degenerate image triangles.

#include <vector>

#include "cbd/mesh.h"
#include "cbd/parameterization.h"

namespace cbd {

/// An image triangle of area `area` is degenerate when the area is at most 1e-12 of `diag2`,
/// the squared diagonal of the images' bounding box: the metrics leave it out and count it,
/// and the untangling and polish use the same test, so what they report is what the metrics count.
inline bool degenerateImageArea(double area, double diag2) { return area <= 1e-12 * diag2; }

/// Result of `computeDistortion`. Every mean is over the source's (non-degenerate) triangles.
struct DistortionMetrics {
  Status status;
  /// L2-stretch normalised so that 1 is optimal: sqrt(sum A_t (s1^2+s2^2)/2 / sum A_t) *
  /// sqrt(sum A_s / sum A_t), s1 >= s2 the singular values of each triangle's Jacobian from
  /// the source triangle to its image, A_s and A_t the source and image areas.
  double eL2 = 0.0;
  double eL2Inverse = 0.0;   ///< the same for the inverse map (image -> source)
  /// Angle distortion: source-area-weighted mean of (s1/s2 + s2/s1)/2 - 1 (0 optimal).
  double eAng = 0.0;
  double eAngDegrees = 0.0;  ///< source-area-weighted mean |corner angle difference|, degrees
  int flipped = 0;           ///< image normal opposite to the target surface normal there
  int degenerate = 0;        ///< image triangles with degenerateImageArea
  std::vector<double> faceStretch;  ///< per source face: sqrt((s1^2+s2^2)/2) scaled so 1 is no stretch
  /// Per source face, its share of the means above: A_s ((s1/s2 + s2/s1)/2 - 1) / sum A_s, which
  /// sum to `eAng`, and A_t (s1^2+s2^2)/2 sum A_s / (sum A_t)^2, which sum to eL2^2 (0 for a
  /// degenerate image): where on the source a map's distortion sits.
  std::vector<double> faceAngleShare, faceL2Share;
};

/// Measure M_st. `image[v]` is the image of source vertex v; `onTarget[v]` its face on the
/// target input mesh (used for the target normal there).
DistortionMetrics computeDistortion(const IndexedMesh& source, const std::vector<Vec3>& image,
                                    const IndexedMesh& target, const std::vector<FacePoint>& onTarget);

}  // namespace cbd
