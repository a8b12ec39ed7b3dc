#pragma once
/// @file layout.h
/// A patch layout (base domain) on a surface: anchors linked by non-crossing paths that cut the
/// surface into triangular patches (Kwok et al. 2012, Sec. 3), and `validateLayout`, which checks
/// every invariant the later stages rely on.

#include <array>
#include <string>
#include <cstdint>
#include <vector>

#include "cbd/refined_mesh.h"
#include "cbd/status.h"

namespace cbd {

/// How a layout edge came to be.
enum class EdgeKind {
  VoronoiCut,     ///< traced across a cut of the anchors' Voronoi diagram (Sec. 5.1)
  Triangulation,  ///< added to triangulate a region that was not a triangle (Sec. 5.1)
  Greedy,         ///< accepted by the greedy shortest-path baseline (Kraevoy & Sheffer 2004)
  Flipped         ///< a Voronoi layout's edge replaced by path flipping (`flipLayoutPaths`)
};

/// How messages name anchor k: by its name in quotes when `names` has one (the names of the
/// anchors in the order the layout builders take them), else by its position k.
std::string anchorLabel(const std::vector<std::string>& names, int k);

/// One edge of the layout: a path between two anchors along edges of the refined mesh.
struct LayoutEdge {
  int a = -1, b = -1;          ///< anchor indices (a != b)
  EdgeKind kind = EdgeKind::VoronoiCut;
  int cut = -1;                ///< index of the Voronoi cut it crosses (VoronoiCut only)
  int eta = 0;                 ///< which of the cuts shared by the anchors' clusters (0-based)
  std::vector<int> vertices;   ///< refined-mesh vertex chain, from anchor a to anchor b
  double length = 0.0;
};

/// One triangular patch: corners and sides in counter-clockwise order (seen from outside).
struct Patch {
  std::array<int, 3> corners{};   ///< anchor indices
  std::array<int, 3> edges{};     ///< edges[k] joins corners[k] -> corners[(k+1)%3]
  std::array<bool, 3> forward{};  ///< edges[k] runs from its a to its b in this direction
  int faces = 0;                  ///< refined-mesh faces inside the patch
};

/// A complete layout on one surface.
struct Layout {
  std::vector<int> anchorVertices;      ///< refined-mesh vertex of each anchor
  std::vector<LayoutEdge> edges;
  std::vector<Patch> patches;
  /// Per anchor, its layout edges in counter-clockwise order around it (seen from outside).
  std::vector<std::vector<int>> rotation;
  RefinedMesh mesh;                     ///< the input surface with every path as an edge chain
  std::vector<int> facePatch;           ///< patch of every refined-mesh face
  std::vector<int> edgePath;            ///< layout edge of every refined-mesh edge, or -1
  std::vector<int> faceCluster;         ///< Voronoi cluster of every refined-mesh face (empty: none)

  int anchorCount() const { return static_cast<int>(anchorVertices.size()); }
  /// Number of anchor pairs linked by more than one edge (multiple linkages, Fig. 3).
  int multipleLinkages() const;
};

/// What `validateLayout` measured.
struct LayoutCheck {
  Status status;                 ///< InternalError naming the first broken invariant
  int eulerCharacteristic = 0;   ///< V - E + F of the layout
};

/// Check a layout: V - E + F equals the surface's Euler characteristic (`expectedEuler`);
/// every patch is a disk bounded by three paths with three distinct anchor corners; every
/// layout edge is a side of exactly two patch sides (once in each direction); paths are simple
/// chains of refined-mesh edges that share no vertex except their end anchors and pass through
/// no other anchor; the rotation system agrees with the patches (consecutive sides at a corner
/// are consecutive in the rotation).
LayoutCheck validateLayout(const Layout& layout, int expectedEuler);

/// How much the paths of two isomorphic layouts disagree in length: the mean over edges of
/// max(r/m, m/r), r the target/source length ratio of an edge and m the median ratio. 1 when
/// every path is scaled alike; a twisted target layout, whose paths detour around anchors,
/// scores far higher.
double lengthDetour(const Layout& source, const Layout& target);

}  // namespace cbd

namespace cbd {

/// One boundary loop of a region of the surface cut along the paths.
struct RegionLoop {
  std::vector<int> halfedges;   ///< path halfedges with the region on their left, in order
  std::vector<int> corners;     ///< anchor indices met along the loop, in order
  std::vector<int> cornerHalfedge;  ///< outgoing loop halfedge at each corner
  std::vector<int> sides;       ///< layout edge from corners[k] to corners[k+1]
};

/// A connected region of faces between paths.
struct Region {
  int faces = 0;
  int eulerCharacteristic = 0;   ///< of the region cut open along its paths
  std::vector<RegionLoop> loops;
  std::vector<int> interiorAnchors;  ///< anchors inside the region, on no path

  /// A disk bounded by three paths with three distinct anchor corners and nothing inside.
  bool isTriangle() const;
};

/// Regions of a surface cut along path edges (edgePath[e] >= 0).
struct RegionMap {
  std::vector<int> faceRegion;
  std::vector<Region> regions;
  std::vector<int> firstFace;  ///< lowest face of every region (analyzeRegions numbers them in this order)

  /// The first region, in the order of `firstFace`, that is not a triangle; -1 when none.
  int firstNonTriangle() const;
};

/// Cut the surface along the path edges and describe every region (boundary loops, corners,
/// sides, interior anchors, Euler characteristic). `anchorOfVertex[v]` is the anchor index of a
/// vertex or -1.
RegionMap analyzeRegions(const RefinedMesh& mesh, const std::vector<int>& edgePath,
                         const std::vector<int>& anchorOfVertex);

/// The faces of the wedge at a loop corner: the region's faces around the corner vertex
/// between the incoming and the outgoing loop halfedge.
std::vector<int> cornerWedge(const RefinedMesh& mesh, const std::vector<int>& edgePath, int outgoingHalfedge);

/// What two partial layouts with the same edge ids must share, region by region: Euler
/// characteristic, anchors inside, and boundary loops as cyclic sequences of (edge, direction).
struct RegionSignature {
  int euler = 0;
  std::vector<int> inside;
  std::vector<std::vector<std::pair<int, int>>> loops;
  bool operator<(const RegionSignature& o) const;
  bool operator==(const RegionSignature& o) const;
};

/// Sorted signatures of all regions of a (partial) layout; `edges[p].a` gives directions.
std::vector<RegionSignature> regionSignatures(const RefinedMesh& mesh, const std::vector<int>& edgePath,
                                              const std::vector<int>& anchorOfVertex,
                                              const std::vector<LayoutEdge>& edges);

/// Scratch marks for flood fills over one refined mesh, stamped so that nothing is cleared
/// between calls: keep one per mesh across many calls (it grows with the mesh).
struct RegionScratch {
  std::vector<uint32_t> vertexMark, halfedgeMark, faceMark;
  uint32_t stamp = 0;
  void fit(const RefinedMesh& mesh);
};

/// Bring `map` up to date after paths were cut into region `region` only, splitting it (a path
/// cut in adds faces to the region it crosses and may divide it): the region's faces and the
/// faces the mesh gained since `map` was made are flooded and described again, exactly as
/// analyzeRegions would from each piece's lowest face; the piece holding the region's first
/// face keeps its id, the others are appended. Every other region is left as it is, so a layout
/// grown path by path floods and describes only the region each path touches (finding its faces
/// is one pass over the face labels).
/// Removing a path merges regions: analyze again instead.
void updateRegion(RegionMap& map, const RefinedMesh& mesh, const std::vector<int>& edgePath,
                  const std::vector<int>& anchorOfVertex, int region, RegionScratch& scratch);

/// The region holding face `f`, flooded from it alone (its faces, breadth first, into
/// `faces`): described as analyzeRegions describes it, except where each loop starts and in
/// what order loops and interior anchors come. Costs the region, not the surface.
Region regionAt(const RefinedMesh& mesh, const std::vector<int>& edgePath, const std::vector<int>& anchorOfVertex,
                int f, RegionScratch& scratch, std::vector<int>& faces);

/// Signatures of only the regions holding the given faces (local flood fills), sorted: after
/// one path is added, comparing these around it on two surfaces is as good as comparing all.
/// With `regionFaces`, also the faces of each of those regions (one list per region).
std::vector<RegionSignature> regionSignaturesAt(const RefinedMesh& mesh, const std::vector<int>& edgePath,
                                                const std::vector<int>& anchorOfVertex,
                                                const std::vector<LayoutEdge>& edges, const std::vector<int>& seedFaces,
                                                RegionScratch& scratch,
                                                std::vector<std::vector<int>>* regionFaces = nullptr);

/// The regions of a partial layout, kept up to date path by path: a region id per face and the
/// signature of every region. Adding a path walks the boundary loops it touches; only when the
/// path may split its region are both sides flooded, in lockstep, until the smaller one is
/// complete (or they meet). So a check costs about the loops' length plus the smaller side,
/// not the whole region, and equals `regionSignaturesAt` beside the path.
class RegionTracker {
 public:
  /// Every region of `mesh` cut along `edgePath`. The tracker keeps the references: `edgePath`
  /// and `anchorOfVertex` may change (and grow with the mesh) between calls as described below.
  RegionTracker(const RefinedMesh& mesh, const std::vector<int>& edgePath, const std::vector<int>& anchorOfVertex,
                const std::vector<LayoutEdge>& edges);

  int regionOf(int f) const { return label_[f]; }
  /// Region id per face (faces added to the mesh since the last call are not in it yet).
  const std::vector<int>& labels() const { return label_; }

  /// The path `chain` (a vertex chain between two anchors) was just cut in inside region
  /// `region`; faces the mesh gained since the last call (splits) lie in that region.
  /// Returns the sorted signatures of the regions beside the path.
  std::vector<RegionSignature> add(const std::vector<int>& chain, int region);
  /// The last added path was removed again: faces from its splits stay in its region, unless
  /// the mesh undid the splits too (PathTracer::rollback).
  void undo();

 private:
  std::vector<std::pair<int, int>> loopFrom(int h, bool& sawTwin, int twinOf) const;
  const RefinedMesh& mesh_;
  const std::vector<int>& edgePath_;
  const std::vector<int>& anchorOf_;
  const std::vector<LayoutEdge>& edges_;
  std::vector<int> label_;
  std::vector<RegionSignature> sig_;
  RegionScratch scratch_;
  std::vector<uint32_t> side_;  // lockstep flood marks: 2 * round + side
  uint32_t round_ = 0;
  struct Undo {
    int region = -1, split = -1;
    RegionSignature before;
    std::vector<int> moved;
  };
  std::vector<Undo> undo_;
};

/// The halfedge by which a path (vertex chain) leaves its end vertex v.
int leavingHalfedge(const RefinedMesh& mesh, const std::vector<int>& chain, int v);

/// Whether vertex v lies on a path: an edge round it has edgePath >= 0.
bool onPath(const RefinedMesh& mesh, const std::vector<int>& edgePath, int v);

/// Length of a vertex chain of `mesh` (sum of its segments).
double chainLength(const RefinedMesh& mesh, const std::vector<int>& chain);

/// Arc-length fraction of every vertex of a chain from its first vertex (0 ... 1; evenly
/// spaced by index when the chain has no length).
std::vector<double> chainFractions(const RefinedMesh& mesh, const std::vector<int>& chain);

/// Layout edges leaving vertex v, counter-clockwise (path ids of the path edges around it).
std::vector<int> rotationAt(const RefinedMesh& mesh, const std::vector<int>& edgePath, int v);

/// The patch of every face of the input mesh the layout was built on: the patch holding the
/// largest part of it (faces crossed by a path are split among patches in `layout.mesh`).
std::vector<int> inputFacePatch(const Layout& layout);

/// The Voronoi cluster of every input face, the same way (all -1 when the layout has none).
std::vector<int> inputFaceCluster(const Layout& layout);

/// Distances inside one region of a layout (its paths so far; patches not needed), along mesh
/// edges inside the region, from each input vertex of the region off its boundary: to the
/// boundary (its paths and anchors) and to each path bounding it.
struct RegionDistances {
  std::vector<int> sides;                   ///< the layout edges on the region's boundary, each once
  std::vector<int> vertices;                ///< input vertices inside the region, off its boundary
  std::vector<double> toBoundary;           ///< per vertex
  std::vector<std::vector<double>> toSide;  ///< per vertex, per side (infinite: not reachable)
  /// Index into `vertices` of the one farthest from the boundary; -1 when there is none.
  int deepest() const;
};

/// The distances in the region of `layout` whose signature is `region`; false when no region has
/// that signature.
bool regionDistances(const Layout& layout, const RegionSignature& region, RegionDistances& out);

/// The vertices of the `target` region whose distances to the region's sides, each over the
/// region's depth, are nearest (least squares) to those of input vertex `s` of the `source`
/// region, at most `count`, best first: two regions bounded by the same paths, so this places a
/// point alike relative to them, where the deepest point alone could jump across a handle. The
/// distances cannot tell the two sides of a thin part apart, hence the runners-up. Empty when `s`
/// is not in `source`, the target region has no vertex off its boundary, or the sides differ.
std::vector<int> matchingRegionVertices(const RegionDistances& source, int s, const RegionDistances& target,
                                        int count);

/// Assemble `layout.patches`, `layout.rotation` and `layout.facePatch` from the paths cut into
/// `layout.mesh` (`layout.edgePath` set). InternalError if a region is not a triangle.
Status assemblePatches(Layout& layout);

}  // namespace cbd
