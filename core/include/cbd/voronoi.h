#pragma once
/// @file voronoi.h
/// Sec. 5.1 of Kwok et al. 2012: the approximate Voronoi diagram of the anchors, as a clustering
/// of faces by one multi-source Dijkstra over the face adjacency graph, and its cuts: the
/// maximal contiguous chains of edges along which two clusters touch (a pair of clusters may
/// share several cuts, Observation 2).

#include <string>
#include <vector>

#include "cbd/refined_mesh.h"
#include "cbd/status.h"

namespace cbd {

/// Result of `computeVoronoiClusters`.
struct VoronoiResult {
  Status status;
  std::vector<int> faceCluster;  ///< anchor index of every face
  std::vector<int> clusterSize;  ///< faces per cluster
};

/// Cluster the faces of `mesh` around the anchor vertices: the faces around anchor i (its
/// one-ring) seed cluster i at the distance from the anchor to their centroid; distances grow
/// by centroid-to-centroid steps across edges. Every face joins the cluster of the Dijkstra
/// tree it is reached by, so every cluster is connected and contains its anchor's one-ring.
/// Ties are broken by anchor index, then face index (same input, same output).
/// Pre-condition: the one-rings are disjoint (no edge joins two anchors; see
/// `separateAnchors`). Errors: InvalidArgument when they are not.
VoronoiResult computeVoronoiClusters(const RefinedMesh& mesh, const std::vector<int>& anchorVertices);

/// Split every edge that joins two anchors (at its midpoint), so their one-rings are disjoint.
/// Returns the number of splits.
int separateAnchors(RefinedMesh& mesh, const std::vector<int>& anchorVertices);

/// One cut: where clusters i < j touch along a contiguous chain of edges.
struct Cut {
  int i = -1, j = -1;
  int eta = 0;                  ///< index among the cuts of the pair (i, j), 0-based
  std::vector<int> edges;       ///< mesh edges of the chain
  std::vector<int> endpoints;   ///< Voronoi vertices at its ends (empty for a closed loop)
  double length = 0.0;
};

/// Result of `extractCuts`.
struct CutsResult {
  Status status;
  std::vector<Cut> cuts;        ///< sorted by (i, j, eta)
  std::vector<int> edgeCut;     ///< cut index of every mesh edge, or -1
  /// Number of cuts of each pair, by pair key i * anchorCount + j (i < j).
  int cutsOfPair(int i, int j, int anchorCount) const;
};

struct Layout;

/// The common start of the Voronoi method on one surface: `layout.mesh` becomes the input with
/// edges between anchors split, `layout.anchorVertices` the anchors; then the clusters (per
/// face of layout.mesh) and their cuts. Errors of computeVoronoiClusters.
Status startVoronoiLayout(const IndexedMesh& input, const std::vector<int>& anchors, Layout& layout,
                          std::vector<int>& faceCluster, CutsResult& cuts);

/// Check anchor vertices of a mesh: in range and distinct (InvalidArgument, AnchorsShareVertex).
/// `what` names the surface in messages.
Status checkAnchorVertices(const IndexedMesh& mesh, const std::vector<int>& anchors, const std::string& what);

/// Cuts of a face clustering (maximal chains of same-pair edges joined at shared vertices).
CutsResult extractCuts(const RefinedMesh& mesh, const std::vector<int>& faceCluster, int anchorCount);

}  // namespace cbd
