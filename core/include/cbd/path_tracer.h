#pragma once
/// @file path_tracer.h
/// The path tracing operator of Sec. 4 (Kwok et al. 2012): shortest paths between anchors over
/// mesh vertices plus adaptive edge nodes, `e = max(b, round(b * l / lbar))` per edge, where `l`
/// is the edge length and `lbar` the mean length of the edges incident to its two end vertices
/// (itself included); every pair of nodes on the boundary of a face is joined by an arc across
/// the face (nodes on one edge only to their neighbours along it), weighted by length.
///
/// Committed paths are cut into the `RefinedMesh`: their edge nodes become vertices, so each
/// face a path crossed becomes regions bounded by path edges. Later paths may cross a region
/// between two of its nodes only, never a path edge, never a path vertex: this is the paper's
/// face-region intersection test (Fig. 7), topological and free of numeric predicates. The
/// sub-edges created by a split get their edge nodes recomputed by the same formula.

#include <cstdint>
#include <limits>
#include <vector>

#include "cbd/refined_mesh.h"
#include "cbd/status.h"

namespace cbd {

/// Options of the edge-node graph.
struct EdgeNodeOptions {
  int minEdgeNodes = 3;     ///< b: edge nodes on every edge (1 with adaptive = false is the paper's E1)
  bool adaptive = true;     ///< add nodes on edges longer than their neighbours (b * l / lbar)
  int maxEdgeNodes = 48;    ///< cap per edge, against pathological slivers
};

/// Which faces a search may cross: all (label == nullptr) or those whose label is one of up to
/// two values; with `group`, only those among them whose group g has groupAllowed[g] set.
struct FaceFilter {
  const std::vector<int>* label = nullptr;
  int a = -1, b = -1;
  const std::vector<int>* group = nullptr;
  const std::vector<char>* groupAllowed = nullptr;
  const std::vector<char>* walls = nullptr;  ///< faces marked non-zero are closed (indices past its end are open)
  bool allows(int f) const {
    if (label && (*label)[f] != a && (*label)[f] != b) return false;
    if (walls && f < static_cast<int>(walls->size()) && (*walls)[f]) return false;
    if (!group) return true;
    const int g = (*group)[f];
    return g >= 0 && (*groupAllowed)[g];
  }
};

/// A goal of a search: an anchor vertex, optionally reachable only through some of its faces
/// (a sector between two paths already leaving it).
struct PathGoal {
  int vertex = -1;
  std::vector<int> faces;  ///< empty: any allowed face around the vertex
  int tag = 0;             ///< returned with the path, to tell goals at the same vertex apart
};

/// One shortest-path query.
struct PathQuery {
  int source = -1;                 ///< anchor vertex the path leaves
  std::vector<int> sourceFaces;    ///< empty: any allowed face around the source
  std::vector<PathGoal> goals;     ///< the nearest reachable goal ends the search
  FaceFilter filter;
  std::vector<int> blockedEdgeLabels;  ///< edges with these labels (and their vertices) are walls
  bool distancesOnly = false;  ///< settle every goal and report distances, trace no path
  /// Only paths shorter than this are wanted: the search gives up (not found) once nothing
  /// shorter can be left (the A* key bounds the length of every path through a node).
  double maxLength = std::numeric_limits<double>::infinity();
};

/// A traced path, before it is committed.
struct TracedPath {
  bool found = false;
  int goal = -1;          ///< index into PathQuery::goals
  double length = 0.0;
  /// Nodes from source to goal: a vertex (>= 0) or an edge node, encoded as
  /// -(1 + slot) where slot indexes the edge-node table at the time of the search.
  std::vector<int64_t> nodes;
  std::vector<double> goalDistances;  ///< with PathQuery::distancesOnly: per goal (inf: unreachable)
};

/// Stateful path tracer over a refined mesh: the edge-node graph is kept up to date as paths are
/// committed, together with per-face and per-edge labels that splits inherit.
class PathTracer {
 public:
  PathTracer(RefinedMesh& mesh, const EdgeNodeOptions& options);

  RefinedMesh& mesh() { return mesh_; }
  const RefinedMesh& mesh() const { return mesh_; }

  /// Vertices that paths may not pass through (anchors), except as source or goal.
  void setAnchor(int v, bool isAnchor);
  bool isAnchor(int v) const { return anchor_[v] != 0; }

  /// Per-face labels (e.g. Voronoi cluster) inherited by the faces a split creates.
  std::vector<int>& faceLabel() { return faceLabel_; }
  /// Per-edge labels (e.g. cut index) inherited by the continuation of a split edge; the
  /// diagonals a split creates get -1.
  std::vector<int>& edgeLabel() { return edgeLabel_; }

  /// Layout edge owning a mesh edge, or -1 for a free edge.
  int pathOfEdge(int e) const { return edgePath_[e]; }
  const std::vector<int>& edgePath() const { return edgePath_; }
  /// Number of paths through a vertex (anchors count every path ending there).
  int pathCount(int v) const { return vertexPaths_[v]; }

  /// Shortest path for a query (Dijkstra over the edge-node graph).
  TracedPath trace(const PathQuery& query);

  /// Cut a traced path into the mesh as layout edge `pathId`. Returns the vertex chain.
  /// InternalError if the mesh does not contain the expected edges afterwards (a bug).
  Status commit(const TracedPath& path, int pathId, std::vector<int>& vertices);

  /// Mark an existing vertex chain (whose edges are free) as layout edge `pathId` again, e.g.
  /// to restore a path undone by `release`. InternalError when a step is not a free edge.
  Status recommit(const std::vector<int>& vertices, int pathId);

  /// Undo a committed path (its vertices stay in the mesh; its edges become free again).
  void release(const std::vector<int>& vertices, int pathId);
  /// The state `rollback` returns to.
  struct Checkpoint {
    int splits = 0;
    size_t nodeSlots = 0, journal = 0;
  };
  Checkpoint checkpoint() const { return {mesh_.splitCount(), slotEdge_.size(), journal_.size()}; }
  /// Undo path `pathId`, committed as `vertices` since `checkpoint` and the only change since:
  /// its edges freed and its splits undone, so the mesh, the edge nodes and the labels are
  /// exactly as at the checkpoint. A path refused after it was cut in then leaves no finer
  /// mesh behind (`release` keeps its vertices, and retrying in one corridor refines it
  /// without end).
  void rollback(const std::vector<int>& vertices, int pathId, const Checkpoint& checkpoint);

  /// The committed paths a traced (not yet committed) path would lie between where it leaves
  /// its first (`atEnd` false) or last node, an anchor: (the path edge before it, the one after
  /// it) counter-clockwise, -1 when none leaves that anchor. Lets a caller check cyclic order
  /// before cutting a path into the mesh.
  std::pair<int, int> sectorOf(const TracedPath& path, bool atEnd) const;

  /// Edge nodes currently on edge e (0 on path edges).
  int edgeNodeCount(int e) const { return edgeNodes_[e]; }
  /// Total nodes (vertices + edge nodes) of the current graph.
  int64_t nodeCount() const;
  /// Position of a node as encoded in TracedPath::nodes.
  const Vec3& nodePosition(int64_t node) const;

 private:
  void growEdges();
  void computeEdgeNodes(int e);
  void onSplit();
  template <class F> void forEachNodeOfFace(int f, int64_t except, F&& fn) const;

  RefinedMesh& mesh_;
  EdgeNodeOptions options_;
  std::vector<char> anchor_;
  std::vector<int> vertexPaths_;
  std::vector<int> faceLabel_, edgeLabel_, edgePath_;
  std::vector<int> edgeNodes_, slotBase_;
  std::vector<int> slotEdge_;
  std::vector<Vec3> slotPos_;  ///< position of every edge node, fixed when it is created
  /// Every change to the edge nodes of an edge: (edge, old node count, old first slot).
  struct NodeChange {
    int edge, nodes, base;
  };
  std::vector<NodeChange> journal_;
  // Dijkstra scratch (stamped so nothing is cleared between searches).
  std::vector<double> distV_, distS_, hV_, hS_;  // distance, A* bound
  std::vector<int64_t> parentV_, parentS_;
  std::vector<uint32_t> stampV_, stampS_, blockV_, blockE_, goalV_;
  uint32_t stamp_ = 0;
};

}  // namespace cbd
