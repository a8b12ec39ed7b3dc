#pragma once
/// @file parameterization.h
/// Stage 4 of the pipeline: every patch of a layout mapped onto one common equilateral
/// triangle. Corners go to corners; each side is parameterized by arc length along its path
/// (so the two patches sharing a path agree on it and nothing cracks); interior vertices by
/// Floater's mean-value coordinates, a convex-combination map that is bijective on a convex
/// domain (Tutte/Floater). One sparse LU factorization per patch, patches in parallel.

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "cbd/layout.h"
#include "cbd/progress.h"

namespace cbd {

using Vec2 = Eigen::Vector2d;

/// Options of `parameterizePatches`.
struct ParameterizationOptions {
  int threads = 0;  ///< worker threads; 0: one per hardware thread
};

/// Result of `parameterizePatches`: where every corner of every refined-mesh face lands in its
/// patch's triangle (a vertex on a path has one position per patch it bounds).
struct PatchParameterization {
  Status status;
  std::vector<std::array<Vec2, 3>> cornerUV;  ///< per face of layout.mesh, per corner (faceVertices order)
  int interiorVertices = 0;                   ///< unknowns solved for, over all patches
};

/// The common domain triangle: corner k of every patch goes to `domainCorner(k)`.
Vec2 domainCorner(int k);

/// Split the faces of a layout whose three corners would land on one side of their patch's
/// triangle (a path running around a single face), so that no face is mapped to a segment.
/// Returns the number of edge splits. Keeps `layout.facePatch` and `layout.edgePath` in sync.
int splitCollinearFaces(Layout& layout);

/// Convex-combination map of a set of refined-mesh faces (a disk) into the plane with Floater's
/// mean-value weights: the corner k of face f is fixed at `uv` where `fixedAt(f, k, uv)` is
/// true (a vertex is free when it is at its first corner met, faces in order, and then at all);
/// the free vertices are solved for. `uv[i]` receives the corners of `faces[i]`, `unknowns`
/// (optional) the free vertex count. Bijective when the fixed corners run around a convex
/// polygon (Tutte/Floater). False: a singular system, or a vertex fixed at one corner and free
/// at another.
bool meanValueMap(const RefinedMesh& mesh, const std::vector<int>& faces,
                  const std::function<bool(int, int, Vec2&)>& fixedAt, std::vector<std::array<Vec2, 3>>& uv,
                  int* unknowns = nullptr);

/// Map every patch of `layout` onto the domain triangle. Pre-condition: `validateLayout` holds
/// and `splitCollinearFaces` was applied. Errors: InternalError (a singular patch system).
PatchParameterization parameterizePatches(const Layout& layout, const ParameterizationOptions& options = {},
                                          const Progress& progress = {});

/// Point location in the patch parameterizations of one layout: which refined-mesh face of
/// patch p holds a point of the domain triangle (a uniform grid per patch).
class PatchLocator {
 public:
  PatchLocator(const Layout& layout, const PatchParameterization& param);
  ~PatchLocator();
  PatchLocator(const PatchLocator&) = delete;
  PatchLocator& operator=(const PatchLocator&) = delete;
  /// The face of patch `patch` holding `uv`, with barycentric coordinates (snapped onto a face
  /// vertex when within 1e-12). False when no face holds it (a bug upstream).
  bool locate(int patch, const Vec2& uv, int& face, Vec3& bary) const;

 private:
  struct Grid;
  std::vector<Grid*> grids_;
};

/// The domain position of a point of refined-mesh face f with barycentric coordinates b.
inline Vec2 uvAt(const PatchParameterization& p, int f, const Vec3& b) {
  return b[0] * p.cornerUV[f][0] + b[1] * p.cornerUV[f][1] + b[2] * p.cornerUV[f][2];
}

/// One point of a surface: a face of a mesh and barycentric coordinates in it.
struct FacePoint {
  int face = -1;
  Vec3 bary = Vec3::Zero();
};

/// The map between the input vertices of two surfaces through their common base domain.
struct CrossMap {
  Status status;
  /// For every vertex of the source input mesh (input order): its image on the target input
  /// mesh (face + barycentric coordinates) and the 3D point. Unreferenced vertices map to
  /// face -1 and keep their position.
  std::vector<FacePoint> sourceToTarget;
  std::vector<Vec3> sourceImage;
  /// The same for every target input vertex, onto the source input mesh.
  std::vector<FacePoint> targetToSource;
  std::vector<Vec3> targetImage;
};

/// Compose the two patch parameterizations: each input vertex of one surface is located in its
/// patch's triangle, then found (grid-indexed 2D point location) in the corresponding patch of
/// the other surface. Anchors map exactly onto anchors; points on a path onto the corresponding
/// path. Pre-condition: `source` and `target` isomorphic with aligned patches.
CrossMap composeCrossMap(const Layout& source, const PatchParameterization& sourceParam,
                         const Layout& target, const PatchParameterization& targetParam);

}  // namespace cbd
