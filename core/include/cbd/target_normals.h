#pragma once
/// @file target_normals.h
/// Which triangles of a mapped mesh face the wrong way: the test behind the metrics' `flipped`
/// count (distortion.h). A triangle whose corners lie on a surface is flipped when its normal
/// points against the surface's normals at its corners.

#include <vector>

#include "cbd/mesh.h"
#include "cbd/parameterization.h"

namespace cbd {

/// Unit normals of the faces of `mesh` (zero for a degenerate face).
std::vector<Vec3> faceNormals(const IndexedMesh& mesh);

/// The surface normals where image points lie. A point inside a face has that face's normal. A
/// point on an edge or at a vertex (a barycentric coordinate below 1e-9) has the normals of every
/// face touching it (the normal cone of a crease or corner), and a triangle is measured against
/// the one closest to its own: so the identity map of a mesh with sharp creases has no flipped
/// triangle, while a triangle folded over a face still is.
class TargetNormals {
 public:
  explicit TargetNormals(const IndexedMesh& target);
  const std::vector<Vec3>& faceNormals() const { return normal_; }
  /// Of the normals at p, the one most aligned with n (zero when p is on no face).
  Vec3 closestAt(const FacePoint& p, const Vec3& n) const;
  /// Whether the image triangle (i0, i1, i2), whose corners lie at p0, p1, p2 on the surface,
  /// is flipped: its normal points against the sum of the surface normals at its corners.
  bool flipped(const Vec3& i0, const Vec3& i1, const Vec3& i2, const FacePoint& p0, const FacePoint& p1,
               const FacePoint& p2) const;

 private:
  const IndexedMesh& mesh_;
  std::vector<Vec3> normal_;
  std::vector<int> starBegin_, star_;  // faces around each vertex (CSR)
};

}  // namespace cbd
