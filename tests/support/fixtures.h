#pragma once
// Procedural meshes for the tests: closed surfaces of genus 0, 1, 2 and the broken inputs the
// validator must recognise. All are built from formulas, nothing is read from disk.

#include <functional>
#include <string>
#include <vector>

#include "cbd/mesh.h"
#include "cbd/parameterization.h"

namespace cbd::fixtures {

/// Icosahedron subdivided `levels` times (1-to-4), projected onto the unit sphere.
IndexedMesh icosphere(int levels);

/// Unit latitude-longitude sphere with `lon` meridians and `lat` rings: few meridians and many
/// rings give long slivers beside tiny pole triangles (a badly meshed input, Fig. 12).
IndexedMesh uvSphere(int lon, int lat);

/// Torus with major radius R, minor radius r, `nu` x `nv` quads split into triangles.
IndexedMesh torus(double R, double r, int nu, int nv);

/// Closed surface of genus `holes`: the boundary of a plate of voxels (1 x (2*holes+1) cells
/// in y, 3 in x, one cell thick, each cell `res`^3 sub-voxels) with `holes` square tunnels,
/// smoothed by `smooth` Laplacian steps. genus == holes.
IndexedMesh holedPlate(int holes, int res, int smooth = 10);

/// Closed (capped) cylinder of radius r and height h: genus 0.
IndexedMesh cappedCylinder(double r, double h, int around, int along);

/// Open tube (no caps): has two boundary loops.
IndexedMesh openCylinder(double r, double h, int around, int along);

/// Open cone: apex plus a fan to a circle, one boundary loop.
IndexedMesh openCone(int around);

/// Three triangles sharing one edge (a non-manifold edge).
IndexedMesh nonManifoldFan();

/// Two tetrahedra touching at one vertex: closed, edge-manifold, non-manifold vertex.
IndexedMesh twoTetrahedraAtVertex();

/// Two disjoint tetrahedra.
IndexedMesh twoComponents();

/// The cube [-1, 1]^3, two triangles per side, outward: sharp creases and corners.
IndexedMesh cube();

/// The regular octahedron: vertices +x, -x, +y, -y, +z, -z (in that order), every edge sqrt(2)
/// long to the last bit.
IndexedMesh octahedron();

/// A regular tetrahedron.
IndexedMesh tetrahedron(const Vec3& offset = Vec3::Zero(), double scale = 1.0);

/// The vertex nearest to p (brute force; for tests).
int nearestVertex(const IndexedMesh& mesh, const Vec3& p);

/// Write a mesh as OFF (for CLI tests).
bool writeOff(const std::string& path, const IndexedMesh& mesh);

/// The identity map of a mesh onto itself: every vertex on the first face using it, at its
/// corner (unreferenced vertices on face -1); `image` the positions.
void identityMap(const IndexedMesh& mesh, std::vector<FacePoint>& on, std::vector<Vec3>& image);

/// The point of a mesh a FacePoint names.
Vec3 pointOn(const IndexedMesh& mesh, const FacePoint& p);

/// A smooth warp on the scale of the CGAL meshes (about 1 across): turned by 0.7 about z, scaled
/// by 1.5, bumped by 3 %; a mesh and its warped copy have the known correspondence v -> v.
Vec3 warpedCopyPoint(const Vec3& x);
/// The mesh with every position moved by `warpedCopyPoint`.
IndexedMesh warpedCopy(const IndexedMesh& mesh);

/// A mesh read from a file, or an empty mesh when it is absent or unreadable (the caller skips:
/// scripts/setup.sh unpacks the CGAL meshes).
IndexedMesh readMeshOrEmpty(const std::string& path);

/// Euler characteristic V - E + F over referenced vertices.
int eulerCharacteristic(const IndexedMesh& mesh);

/// An icosphere (3 levels) with `count` farthest-point anchors and a finer one (4 levels) with the
/// anchors at the nearest vertices, then moved by `deform`: a pair with a known correspondence.
struct AnchoredPair {
  IndexedMesh source, target;
  std::vector<int> sourceAnchors, targetAnchors;
};
AnchoredPair anchoredSpheres(int count, const std::function<Vec3(const Vec3&)>& deform);

/// A surface and how many anchors to lay out on it.
struct LayoutCase {
  IndexedMesh mesh;
  int anchors;
};

/// One small layout case per genus 0, 1, 2 (sphere with 14 anchors, torus with 9, double torus
/// with 16), for tests that cut paths into their regions one by one.
std::vector<LayoutCase> genusZeroToTwoLayouts();

}  // namespace cbd::fixtures
