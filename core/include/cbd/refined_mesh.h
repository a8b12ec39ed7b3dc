#pragma once
/// @file refined_mesh.h
/// A closed, oriented triangle mesh in half-edge form that paths are cut into: every path of a
/// layout becomes a chain of mesh edges by splitting the edges it crosses (Sec. 4, Fig. 7 of
/// Kwok et al. 2012). Splitting an edge splits its two faces by joining the new vertex to the
/// opposite corners, so a path through a face leaves that face as regions whose sub-edges are
/// edges of the mesh again: later paths may cross them, never the path edges. Intersection
/// tests are therefore topological, with no floating-point predicate.
///
/// Every vertex remembers where it lies on the input surface (face + barycentric coordinates),
/// every face which input face it is part of.

#include <array>
#include <vector>

#include "cbd/mesh.h"

namespace cbd {

/// A point on the input surface: a face of the input mesh and barycentric coordinates in it.
struct SurfacePoint {
  int face = -1;
  Vec3 bary = Vec3::Zero();
};

/// Half-edge triangle mesh with edge splits. Halfedges come in pairs: twin(h) == h ^ 1, and the
/// edge of h is h / 2.
class RefinedMesh {
 public:
  RefinedMesh() = default;
  /// Build from a validated closed, manifold, oriented mesh (see validateMesh). Unreferenced
  /// vertices are kept as isolated vertices (out == -1).
  explicit RefinedMesh(const IndexedMesh& mesh);

  int vertexCount() const { return static_cast<int>(pos_.size()); }
  int faceCount() const { return static_cast<int>(faceHe_.size()); }
  int halfedgeCount() const { return static_cast<int>(to_.size()); }
  int edgeCount() const { return halfedgeCount() / 2; }
  int inputVertexCount() const { return inputVertices_; }
  int inputFaceCount() const { return inputFaces_; }

  // Connectivity.
  int to(int h) const { return to_[h]; }
  int from(int h) const { return to_[h ^ 1]; }
  int next(int h) const { return next_[h]; }
  int prev(int h) const { return next_[next_[h]]; }
  static int twin(int h) { return h ^ 1; }
  static int edgeOf(int h) { return h >> 1; }
  int face(int h) const { return face_[h]; }
  int faceHalfedge(int f) const { return faceHe_[f]; }
  int outgoing(int v) const { return out_[v]; }
  /// The next outgoing halfedge counter-clockwise around from(h) (seen from outside).
  int rotateCCW(int h) const { return twin(prev(h)); }
  /// The halfedge from a to b, or -1.
  int findHalfedge(int a, int b) const;
  /// Corners of face f in counter-clockwise order.
  std::array<int, 3> faceVertices(int f) const;

  // Geometry and provenance.
  const Vec3& position(int v) const { return pos_[v]; }
  double edgeLength(int e) const { return (pos_[to_[2 * e]] - pos_[to_[2 * e + 1]]).norm(); }
  /// The input vertex v was (or -1 for a vertex inserted by a split).
  int inputVertex(int v) const { return v < inputVertices_ ? v : -1; }
  const SurfacePoint& location(int v) const { return loc_[v]; }
  int inputFace(int f) const { return inputFace_[f]; }
  /// True when edge e lies on an edge of the input mesh (not a diagonal inside an input face).
  bool onInputEdge(int e) const { return onInputEdge_[e] != 0; }

  /// Split the edge of h at parameter t in (0, 1) measured from from(h). Returns the new vertex.
  /// Afterwards h runs from from(h) to the new vertex; the two faces of the edge are split by
  /// joining the new vertex to their opposite corners. Called observers keep attributes in sync.
  int splitEdge(int h, double t);

  /// Observer of splits, to keep per-edge / per-face attributes of the owning stage in sync.
  struct SplitRecord {
    int halfedge;        ///< the split halfedge (now ending at `vertex`)
    int vertex;          ///< the new vertex
    int edgeContinued;   ///< new edge continuing the split edge (vertex -> old to(h))
    int edgeDiagonalA;   ///< new edge in the face of h
    int edgeDiagonalB;   ///< new edge in the face of twin(h)
    int faceNewA;        ///< new face split off the face of h
    int faceNewB;        ///< new face split off the face of twin(h)
  };
  const SplitRecord& lastSplit() const { return last_; }
  /// Splits made so far (the count `undoSplits` returns to).
  int splitCount() const { return static_cast<int>(history_.size()); }
  /// Undo the splits made after the first `count`, latest first: the mesh is then exactly as it
  /// was after `count` splits, indices included (a path refused after it was cut in leaves
  /// nothing behind).
  void undoSplits(int count);

  /// Barycentric coordinates of vertex v in input face f (v must lie on the closure of f).
  Vec3 baryIn(int v, int f) const;

  /// Flat copy (vertices in index order; input vertices keep their indices).
  IndexedMesh toIndexed() const;

 private:
  std::vector<Vec3> pos_;
  std::vector<SurfacePoint> loc_;
  std::vector<int> out_;
  std::vector<int> to_, next_, face_;
  std::vector<int> faceHe_, inputFace_;
  std::vector<char> onInputEdge_;
  std::vector<std::array<int, 3>> inputFaceVerts_;
  int inputVertices_ = 0, inputFaces_ = 0;
  SplitRecord last_{};
  /// Per split, what it overwrote that its record cannot tell: the two old faces' halfedges and
  /// the far end's outgoing halfedge.
  struct SplitUndo {
    SplitRecord record;
    int faceHalfedgeA, faceHalfedgeB, farOutgoing;
  };
  std::vector<SplitUndo> history_;
};

/// Sum of the faces' areas (the input mesh's area up to rounding: splits keep faces planar).
double surfaceArea(const RefinedMesh& mesh);

}  // namespace cbd
