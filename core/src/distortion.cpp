#include "cbd/distortion.h"
#include "cbd/target_normals.h"

#include <cmath>

#include <Eigen/Dense>

namespace cbd {
namespace {

/// A triangle in its own plane: edges e1 = p1 - p0, e2 = p2 - p0 in an orthonormal frame.
Eigen::Matrix2d planar(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const Vec3 a = p1 - p0, b = p2 - p0;
  const double la = a.norm();
  const Vec3 x = la > 0 ? Vec3(a / la) : Vec3::UnitX();
  const Vec3 n = a.cross(b);
  const Vec3 y = n.norm() > 0 ? Vec3(n.cross(x).normalized()) : Vec3::UnitY();
  Eigen::Matrix2d m;
  m << la, b.dot(x), 0.0, b.dot(y);
  return m;  // columns: e1, e2
}

double angleAt(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 a = q - p, b = r - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

DistortionMetrics computeDistortion(const IndexedMesh& S, const std::vector<Vec3>& image, const IndexedMesh& T,
                                    const std::vector<FacePoint>& onTarget) {
  DistortionMetrics d;
  const int nf = S.faceCount();
  d.faceStretch.assign(nf, 1.0);
  d.faceAngleShare.assign(nf, 0.0);
  d.faceL2Share.assign(nf, 0.0);
  const TargetNormals targetNormals(T);
  double diag2 = 0;
  {
    Vec3 lo = Vec3::Constant(1e300), hi = -lo;
    for (const Vec3& p : image) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    diag2 = (hi - lo).squaredNorm();
  }
  double sumAs = 0, sumAt = 0, l2t = 0, l2s = 0, ang = 0, angDeg = 0;
  std::vector<double> stretch(nf, 0.0);
  for (int f = 0; f < nf; ++f) {
    const auto& t = S.faces[f];
    const Vec3 &s0 = S.positions[t[0]], &s1 = S.positions[t[1]], &s2 = S.positions[t[2]];
    const Vec3 &i0 = image[t[0]], &i1 = image[t[1]], &i2 = image[t[2]];
    const double As = 0.5 * (s1 - s0).cross(s2 - s0).norm();
    const Vec3 ni = (i1 - i0).cross(i2 - i0);
    const double At = 0.5 * ni.norm();
    if (degenerateImageArea(At, diag2)) {
      ++d.degenerate;
      continue;
    }
    if (targetNormals.flipped(i0, i1, i2, onTarget[t[0]], onTarget[t[1]], onTarget[t[2]])) ++d.flipped;
    // Jacobian from the source triangle to its image, both in their own planes.
    const Eigen::Matrix2d J = planar(i0, i1, i2) * planar(s0, s1, s2).inverse();
    const Eigen::Vector2d sv = Eigen::JacobiSVD<Eigen::Matrix2d>(J).singularValues();
    const double a = sv[0], b = std::max(sv[1], 1e-300);
    sumAs += As, sumAt += At;
    l2t += At * 0.5 * (a * a + b * b);
    l2s += As * 0.5 * (1.0 / (a * a) + 1.0 / (b * b));
    d.faceAngleShare[f] = As * (0.5 * (a / b + b / a) - 1.0);
    d.faceL2Share[f] = At * 0.5 * (a * a + b * b);
    ang += d.faceAngleShare[f];
    const double corner[3] = {angleAt(s0, s1, s2) - angleAt(i0, i1, i2), angleAt(s1, s2, s0) - angleAt(i1, i2, i0),
                              angleAt(s2, s0, s1) - angleAt(i2, i0, i1)};
    angDeg += As * (std::abs(corner[0]) + std::abs(corner[1]) + std::abs(corner[2])) / 3.0 * 180.0 / M_PI;
    stretch[f] = std::sqrt(0.5 * (a * a + b * b));
  }
  if (sumAs <= 0 || sumAt <= 0) {
    d.status = Status::error(ErrorCode::InternalError, "the map has no non-degenerate triangle");
    return d;
  }
  d.eL2 = std::sqrt(l2t / sumAt) * std::sqrt(sumAs / sumAt);
  d.eL2Inverse = std::sqrt(l2s / sumAs) * std::sqrt(sumAt / sumAs);
  d.eAng = ang / sumAs;
  d.eAngDegrees = angDeg / sumAs;
  // Per-face stretch relative to the global scale, so that 1 means "as stretched as average".
  const double scale = std::sqrt(sumAs / sumAt);
  for (int f = 0; f < nf; ++f) {
    if (stretch[f] > 0) d.faceStretch[f] = stretch[f] * scale;
    d.faceAngleShare[f] /= sumAs;
    d.faceL2Share[f] *= sumAs / (sumAt * sumAt);
  }
  return d;
}

}  // namespace cbd
