#pragma once
/// @file mesh.h
/// The mesh types of cbd: `cbd::Mesh`, a vcglib triangle mesh in double precision used for
/// input/output, and `cbd::IndexedMesh`, the flat index arrays every algorithm stage reads.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <vcg/complex/complex.h>

#include "cbd/status.h"

namespace cbd {

using Vec3 = Eigen::Vector3d;

class MeshVertex;
class MeshEdge;
class MeshFace;
struct MeshUsedTypes
    : public vcg::UsedTypes<vcg::Use<MeshVertex>::AsVertexType, vcg::Use<MeshEdge>::AsEdgeType,
                            vcg::Use<MeshFace>::AsFaceType> {};
class MeshVertex
    : public vcg::Vertex<MeshUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                         vcg::vertex::Color4b, vcg::vertex::Qualityd, vcg::vertex::TexCoord2d,
                         vcg::vertex::VFAdj, vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class MeshEdge : public vcg::Edge<MeshUsedTypes, vcg::edge::VertexRef, vcg::edge::BitFlags> {};
class MeshFace
    : public vcg::Face<MeshUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d,
                       vcg::face::Color4b, vcg::face::Qualityd, vcg::face::FFAdj, vcg::face::VFAdj,
                       vcg::face::BitFlags, vcg::face::Mark> {};

/// A vcglib triangle mesh in double precision with per-vertex normal, colour, quality and
/// texture coordinate, per-face normal, colour and quality, FF/VF adjacency, and edges (used
/// for path polylines).
class Mesh : public vcg::tri::TriMesh<std::vector<MeshVertex>, std::vector<MeshEdge>,
                                      std::vector<MeshFace>> {};

/// Flat, compact view of a triangle mesh: what the algorithm stages read.
struct IndexedMesh {
  std::vector<Vec3> positions;             ///< one per vertex
  std::vector<std::array<int, 3>> faces;   ///< counter-clockwise vertex indices

  int vertexCount() const { return static_cast<int>(positions.size()); }
  int faceCount() const { return static_cast<int>(faces.size()); }
};

/// What `loadMesh` found besides the geometry.
struct LoadResult {
  Status status;
  bool hadPolygons = false;     ///< the file had faces with more than three vertices
  bool hasVertexColor = false;  ///< per-vertex colour was read (e.g. COFF, PLY red/green/blue)
  bool hasVertexQuality = false;
  bool hasVertexTexCoord = false;
  /// What was read but may not be what the file meant (e.g. lines after an OFF file's last
  /// counted face, left unread); the mesh is usable. Each names the file: "'<path>': ...".
  std::vector<std::string> warnings;
};

/// Load PLY, OFF (also COFF with colours), OBJ or STL: PLY and binary STL through vcglib's
/// importers after a full check of the file (vcglib trusts counts and indices), OFF, OBJ and
/// ASCII STL by our own readers (vcglib 2020.09's misread malformed and even some valid files,
/// found by fuzzing). Errors: FileNotFound, UnsupportedFormat, MalformedMesh, EmptyMesh. Polygonal faces are
/// triangulated by the importer and reported in `hadPolygons` (validation turns it into
/// NotTriangles). Unreferenced vertices are kept (indices stay those of the file).
LoadResult loadMesh(const std::string& path, Mesh& mesh);

/// Options of `savePly`.
struct SavePlyOptions {
  bool binary = true;         ///< binary little-endian PLY (false: ASCII)
  bool vertexColor = false;   ///< write per-vertex red/green/blue/alpha
  bool vertexQuality = false; ///< write per-vertex quality
  bool vertexTexCoord = false; ///< write per-vertex texture coordinates (texture_u/texture_v)
  bool faceColor = false;     ///< write per-face red/green/blue/alpha
  bool faceQuality = false;   ///< write per-face quality
  bool edges = false;         ///< write the edge list (for polyline meshes)
};

/// Write a PLY file atomically (a temporary file renamed into place, so a failed run never
/// leaves a partial file behind). Error: OutputError naming the path.
Status savePly(const std::string& path, const Mesh& mesh, const SavePlyOptions& options = {});

/// Flat copy of a vcglib mesh (deleted elements skipped; vertex indices compacted in order).
IndexedMesh toIndexed(const Mesh& mesh);

/// Build a vcglib mesh from index arrays (no adjacency computed).
void fromIndexed(const IndexedMesh& in, Mesh& out);

/// Axis-aligned bounding-box diagonal of the referenced and unreferenced vertices.
double boundingBoxDiagonal(const IndexedMesh& mesh);

/// Sum of the faces' areas.
double surfaceArea(const IndexedMesh& mesh);

/// V - E + F of a closed triangle mesh (every edge on two faces, so E = 3F/2), over the
/// vertices some face uses: 2 - 2 genus for a closed connected surface.
int closedEulerCharacteristic(const IndexedMesh& mesh);

}  // namespace cbd
