#pragma once
/// @file validate_input.h
/// First stage of the pipeline: check that two meshes and their anchors can be processed
/// (closed, manifold, connected, oriented triangle surfaces of the same genus with enough
/// corresponding anchors), and report what was found.

#include <string>
#include <vector>

#include "cbd/anchors.h"
#include "cbd/mesh.h"
#include "cbd/status.h"

namespace cbd {

/// The largest snap tolerance accepted (the whole bounding-box diagonal).
inline constexpr double kMaxSnapTolerance = 1.0;

/// Options of `validateMesh` / `validateInput`.
struct ValidationOptions {
  double degenerateAreaRelative = 1e-14;  ///< a face is degenerate when its area is below this
                                          ///< times the squared bounding-box diagonal
  double snapTolerance = 0.01;            ///< anchors farther from their nearest vertex than
                                          ///< this fraction of the bbox diagonal are errors
};

/// What `validateMesh` found; `status` is the first problem, in the order of the checks.
struct MeshReport {
  Status status;
  std::string name;               ///< the name used in messages ("source", "target", a path)
  int vertices = 0;               ///< referenced vertices
  int faces = 0;
  int edges = 0;
  int unreferencedVertices = 0;   ///< ignored with a warning
  int components = 0;
  int eulerCharacteristic = 0;    ///< V - E + F over referenced vertices
  int genus = -1;                 ///< (2 - chi) / 2 for a closed connected surface, else -1
  double bboxDiagonal = 0.0;
  /// Volume the surface encloses, signed by its faces' orientation: > 0 when they point
  /// outward (counter-clockwise seen from outside), < 0 when inward (set when status is ok).
  double enclosedVolume = 0.0;
  std::vector<std::string> warnings;
};

/// Check one mesh: finite coordinates; no degenerate or duplicate faces; every edge shared by
/// exactly two faces (else OpenBoundary / NonManifoldEdge), traversed in opposite directions
/// (else InconsistentOrientation); one fan of faces around every vertex (NonManifoldVertex);
/// one connected component (MultipleComponents). Unreferenced vertices only warn. Every
/// message names the mesh ("<name> mesh: ...", or "mesh: ..." for an empty name), the count and
/// an example element (0-based indices as in the file).
/// @param[in] hadPolygons from LoadResult: reported as NotTriangles.
MeshReport validateMesh(const IndexedMesh& mesh, const std::string& name, bool hadPolygons = false,
                        const ValidationOptions& options = {});

/// Add the file to the mesh named in `report`'s status message and warnings, for front ends that
/// loaded it from `path`: "source mesh: ..." becomes "source mesh 'cow.off': ...".
void nameMeshFile(MeshReport& report, const std::string& path);

/// Everything `validateInput` checked: both meshes and the matched anchors.
struct InputReport {
  Status status;
  MeshReport source;
  MeshReport target;
  AnchorPairs anchors;  ///< matched and snapped anchors (valid when status is ok)
};

/// The input of the whole pipeline, as given by a caller.
struct InputFiles {
  std::string sourceMesh, targetMesh;
  std::string sourceAnchors, targetAnchors;
};

/// Check a source/target pair with its anchors: both meshes valid, same genus (GenusMismatch),
/// faces outward on both or inward on both (OrientationMismatch, by `enclosedVolume`),
/// anchors matched by name (`matchAnchors`), snapped within tolerance (`snapAnchors`), at least
/// three (TooFewAnchors) and no more than the smaller mesh has vertices (TooManyAnchors).
/// The meshes are not modified.
InputReport validateInput(const IndexedMesh& source, const IndexedMesh& target,
                          const AnchorSet& sourceAnchors, const AnchorSet& targetAnchors,
                          const ValidationOptions& options = {}, bool sourceHadPolygons = false,
                          bool targetHadPolygons = false);

/// Everything loaded and checked from files, for front ends (CLI, plugin scripts, benchmark).
struct LoadedInput {
  InputReport report;
  Mesh sourceMesh, targetMesh;          ///< as loaded (with colours etc.)
  IndexedMesh source, target;           ///< flat copies the algorithm reads
  LoadResult sourceLoad, targetLoad;
};

/// Load both meshes and both anchor files, then `validateInput`. Any file error is returned
/// in `report.status` with the path in the message.
void loadAndValidate(const InputFiles& files, const ValidationOptions& options, LoadedInput& out);

/// One surface (and its anchors) loaded and checked, for commands on a single mesh.
struct LoadedSurface {
  Status status;                       ///< the first problem: file, mesh, anchors
  MeshReport report;                   ///< valid once the mesh loaded
  Mesh mesh;                           ///< as loaded
  IndexedMesh indexed;                 ///< the flat copy the algorithm reads
  LoadResult load;
  std::vector<SnappedAnchor> anchors;  ///< snapped, in file order (empty without an anchor file)
};

/// Load `meshPath` and `validateMesh` it (messages name it "<role> mesh '<path>'"); then, when
/// `anchorsPath` is not empty, read its anchors and snap them (`snapAnchors`), at least
/// `minAnchors` of them (TooFewAnchors, counting the inactive ones left out).
void loadSurface(const std::string& meshPath, const std::string& anchorsPath, const std::string& role,
                 const ValidationOptions& options, LoadedSurface& out, int minAnchors = 3);

}  // namespace cbd
