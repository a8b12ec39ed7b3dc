#include "cbd/source_layout.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <numeric>
#include <set>

namespace cbd {
namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The paths of a layout under construction (ids are stable; removed ones stay as holes).
struct PathSet {
  std::vector<LayoutEdge> edges;
  std::vector<char> alive;

  int add(LayoutEdge e) {
    edges.push_back(std::move(e));
    alive.push_back(1);
    return static_cast<int>(edges.size()) - 1;
  }
};

/// Distinct anchors among the `count` corners from position `from` on, cyclically.
int distinctAnchors(const std::vector<int>& corners, int from, size_t count) {
  std::vector<int> seen;
  for (size_t k = 0; k < count; ++k) seen.push_back(corners[(from + k) % corners.size()]);
  std::sort(seen.begin(), seen.end());
  return static_cast<int>(std::unique(seen.begin(), seen.end()) - seen.begin());
}

/// Whether a region can never be cut into triangles: no anchor inside and at most two distinct
/// anchors on its boundary (an empty 2-gon, a disk whose corners alternate a b a b, a handle
/// between paths of the same two anchors): every path in it would join those two, and every
/// piece would again have only those two for corners.
bool deadRegion(const Region& reg) {
  if (!reg.interiorAnchors.empty()) return false;
  std::vector<int> corners;
  for (const auto& l : reg.loops) corners.insert(corners.end(), l.corners.begin(), l.corners.end());
  return !corners.empty() && distinctAnchors(corners, 0, corners.size()) <= 2;
}

/// Whether the path just cut in along `chain` leaves a dead region on either side.
bool cutsOffDeadPiece(const RefinedMesh& mesh, const std::vector<int>& edgePath, const std::vector<int>& anchorOf,
                      const std::vector<int>& chain, RegionScratch& scratch) {
  if (chain.size() < 2) return false;
  const int h = mesh.findHalfedge(chain[0], chain[1]);
  if (h < 0) return false;
  std::vector<int> faces;
  const int left = mesh.face(h), right = mesh.face(RefinedMesh::twin(h));
  if (deadRegion(regionAt(mesh, edgePath, anchorOf, left, scratch, faces))) return true;
  if (std::find(faces.begin(), faces.end(), right) != faces.end()) return false;  // one piece
  return deadRegion(regionAt(mesh, edgePath, anchorOf, right, scratch, faces));
}

}  // namespace

SourceLayoutResult buildSourceLayout(const IndexedMesh& input, const std::vector<int>& anchors,
                                     const SourceLayoutOptions& options, const Progress& progress) {
  SourceLayoutResult r;
  const char* const stage = "tracing the base domain";
  auto cancelled = [&] {
    r.status = Status::error(ErrorCode::Cancelled, "cancelled while tracing the source layout");
    return r;
  };
  const int na = static_cast<int>(anchors.size());
  if (na < 3) {
    r.status = Status::error(ErrorCode::TooFewAnchors, "a layout needs at least 3 anchors");
    return r;
  }
  if (Status st = checkAnchorVertices(input, anchors, "source"); !st) {
    r.status = st;
    return r;
  }
  auto t0 = std::chrono::steady_clock::now();
  Layout& L = r.layout;
  std::vector<int> clusters;
  if (Status st = startVoronoiLayout(input, anchors, L, clusters, r.cuts); !st) {
    r.status = st;
    return r;
  }
  r.voronoiSeconds = seconds(t0);
  // A finished base domain is a triangulation of the surface with the anchors for vertices
  // (multiple linkages allowed, no loops): V - E + F = chi and 3F = 2E, so it has exactly
  // 3 (anchors - chi) paths; progress is the share of them traced.
  const int chi = closedEulerCharacteristic(input);
  const int needed = 3 * (na - chi);
  auto report = [&](int traced) {
    return progress.report(0.1 + 0.9 * traced / std::max(needed, 1), stage);
  };
  if (!report(0)) return cancelled();
  t0 = std::chrono::steady_clock::now();
  PathTracer tracer(L.mesh, options.edgeNodes);
  tracer.faceLabel() = std::move(clusters);
  tracer.edgeLabel() = r.cuts.edgeCut;
  for (int v : anchors) tracer.setAnchor(v, true);
  PathSet paths;

  // 1. One path across every cut, longest cuts (strongest Delaunay adjacencies) first.
  std::vector<int> order(r.cuts.cuts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return r.cuts.cuts[a].length > r.cuts.cuts[b].length; });
  for (int c : order) {
    if (!report(r.cutPaths)) return cancelled();
    const Cut& cut = r.cuts.cuts[c];
    PathQuery q;
    q.source = anchors[cut.i];
    q.goals.push_back({anchors[cut.j], {}, 0});
    q.filter = {&tracer.faceLabel(), cut.i, cut.j};
    for (int o = 0; o < static_cast<int>(r.cuts.cuts.size()); ++o)
      if (o != c && r.cuts.cuts[o].i == cut.i && r.cuts.cuts[o].j == cut.j) q.blockedEdgeLabels.push_back(o);
    TracedPath tp = tracer.trace(q);
    if (!tp.found) {
      ++r.cutPathsFailed;
      continue;
    }
    LayoutEdge e;
    e.a = cut.i, e.b = cut.j, e.kind = EdgeKind::VoronoiCut, e.cut = c, e.eta = cut.eta, e.length = tp.length;
    const int id = paths.add(e);
    Status s = tracer.commit(tp, id, paths.edges[id].vertices);
    if (!s) {
      r.status = s;
      return r;
    }
    ++r.cutPaths;
  }

  // 2. Triangulate every region that is not a triangle, with paths searched inside it.
  const int maxExtra = options.maxTriangulationPaths >= 0 ? options.maxTriangulationPaths : 4 * na + 64;
  // Every path the triangulation adds counts against `maxExtra`, even one later dropped with an
  // empty 2-gon, so when the cut paths leave more than that to add, the layout cannot be
  // finished: say so now instead of searching until the cap is hit (on a surface of high genus
  // with few anchors that search takes back link after link for a long time while the refined
  // mesh grows).
  {
    if (needed - r.cutPaths > maxExtra) {
      const int genus = (2 - chi) / 2;
      r.status = Status::error(
          ErrorCode::LayoutFailed,
          "the source layout cannot be completed: a base domain with " + std::to_string(na) + " anchors on a genus-" +
              std::to_string(genus) + " surface has 3 x (anchors - 2 + 2 x genus) = " + std::to_string(needed) +
              " paths; the Voronoi cuts gave " + std::to_string(r.cutPaths) + ", and at most " +
              std::to_string(maxExtra) + " more may triangulate the rest" +
              (options.maxTriangulationPaths >= 0 ? std::string() : std::string(" (4 x anchors + 64)")) + "; add anchors");
      r.layoutSeconds = seconds(t0);
      return r;
    }
  }
  std::vector<int> anchorOf;
  auto refreshAnchorOf = [&] {
    anchorOf.assign(L.mesh.vertexCount(), -1);
    for (int i = 0; i < na; ++i) anchorOf[anchors[i]] = i;
  };
  // The surviving paths into the layout, numbered in order.
  auto compact = [&] {
    std::vector<int> newId(paths.edges.size(), -1);
    for (size_t p = 0; p < paths.edges.size(); ++p)
      if (paths.alive[p]) {
        newId[p] = static_cast<int>(L.edges.size());
        L.edges.push_back(std::move(paths.edges[p]));
      }
    L.edgePath = tracer.edgePath();
    for (int& p : L.edgePath)
      if (p >= 0) p = newId[p];
    L.faceCluster = tracer.faceLabel();
  };
  // The regions, analysed once and then updated where each path was cut in; regions are taken
  // in the order of their lowest face, as a fresh analysis would number them.
  RegionMap rm;
  RegionScratch scratch;
  // Links taken back in the region being triangulated (pairs of `endKey`s, both orders).
  std::set<std::pair<int, int>> triedLinks;
  bool analyzed = false;
  int bad = -1;
  for (int iteration = 0;; ++iteration) {
    if (!report(r.cutPaths - r.removedPaths + r.triangulationPaths)) return cancelled();
    refreshAnchorOf();
    if (!analyzed)
      rm = analyzeRegions(L.mesh, tracer.edgePath(), anchorOf), analyzed = true;
    else
      updateRegion(rm, L.mesh, tracer.edgePath(), anchorOf, bad, scratch);
    bad = rm.firstNonTriangle();
    if (bad < 0) break;
    const Region& reg = rm.regions[bad];
    auto describe = [&] {
      std::string s = "region " + std::to_string(bad) + " (" + std::to_string(reg.faces) + " faces, " +
                      std::to_string(reg.loops.size()) + " boundary loops, corners";
      for (const auto& l : reg.loops)
        for (int c : l.corners) s += " " + anchorLabel(options.anchorNames, c);
      s += ", " + std::to_string(reg.interiorAnchors.size()) + " anchors inside)";
      return s;
    };
    // Stuck in region `bad`: keep the partial layout and where an anchor would help.
    auto stuck = [&] {
      const int seed = rm.firstFace[bad];
      compact();
      L.rotation.assign(na, {});
      for (int i = 0; i < na; ++i) L.rotation[i] = rotationAt(L.mesh, L.edgePath, L.anchorVertices[i]);
      refreshAnchorOf();
      const auto sig = regionSignaturesAt(L.mesh, L.edgePath, anchorOf, L.edges, {seed}, scratch);
      r.stuck = true;
      r.stuckRegion = sig.front();
      RegionDistances d;
      if (regionDistances(L, r.stuckRegion, d) && d.deepest() >= 0) r.stuckVertex = d.vertices[d.deepest()];
      r.layoutSeconds = seconds(t0);
      return r;
    };
    if (r.triangulationPaths >= maxExtra) {
      r.status = Status::error(ErrorCode::LayoutFailed,
                               "the source layout could not be triangulated after " + std::to_string(maxExtra) +
                                   " extra paths; " + describe() + " remains; add anchors there");
      return stuck();
    }
    // An empty 2-gon: two paths between the same anchors enclose nothing; drop one of them.
    if (reg.loops.size() == 1 && reg.eulerCharacteristic == 1 && reg.interiorAnchors.empty() &&
        reg.loops[0].corners.size() == 2) {
      const int p0 = reg.loops[0].sides[0], p1 = reg.loops[0].sides[1];
      const int drop = paths.edges[p0].length >= paths.edges[p1].length ? p0 : p1;
      tracer.release(paths.edges[drop].vertices, drop);
      paths.alive[drop] = 0;
      ++r.removedPaths;
      analyzed = false;  // two regions merged
      triedLinks.clear();
      continue;
    }
    // Candidate links: (source anchor + wedge) -> goals (anchor + wedge).
    struct End {
      int anchor;
      std::vector<int> faces;
      int loop, pos;  // loop/position on the boundary, or -1 for an interior anchor
    };
    std::vector<End> ends;
    for (int a : reg.interiorAnchors) ends.push_back({a, {}, -1, -1});
    for (size_t l = 0; l < reg.loops.size(); ++l)
      for (size_t k = 0; k < reg.loops[l].corners.size(); ++k)
        ends.push_back({reg.loops[l].corners[k], cornerWedge(L.mesh, tracer.edgePath(), reg.loops[l].cornerHalfedge[k]),
                        static_cast<int>(l), static_cast<int>(k)});
    const bool disk = reg.loops.size() == 1 && reg.eulerCharacteristic == 1;
    auto linkable = [&](const End& s, const End& g, bool strict) {
      if (s.anchor == g.anchor) return false;
      if (s.loop < 0 || g.loop < 0) return true;           // an interior anchor joins anything
      if (s.loop != g.loop) return true;                   // joining two loops
      const int m = static_cast<int>(reg.loops[s.loop].corners.size());
      const int d = std::abs(s.pos - g.pos);
      const bool adjacent = d == 1 || d == m - 1;
      if (adjacent && (disk || strict)) return false;
      // A diagonal of a disk must not cut off a polygon whose corners alternate between two
      // anchors (a b a b ...): that one would have no diagonal left. (Two such diagonals are
      // all that 4 farthest-point anchors on a double torus left, and the layout failed.)
      if (disk) {
        const auto& corners = reg.loops[s.loop].corners;
        auto dead = [&](int from, int to) {
          const int n = (to - from + m) % m + 1;
          return n >= 4 && distinctAnchors(corners, from, n) == 2;
        };
        return !dead(s.pos, g.pos) && !dead(g.pos, s.pos);
      }
      return true;                                         // a region with a handle
    };
    // An end's identity across the re-analyses of this region: its outgoing loop halfedge (a
    // path edge, never split), or the anchor for an interior one.
    auto endKey = [&](const End& x) {
      return x.loop >= 0 ? reg.loops[x.loop].cornerHalfedge[x.pos] : -1 - x.anchor;
    };
    TracedPath best;
    int bestSource = -1;
    for (int pass = 0; pass < 2 && !best.found; ++pass) {
      const bool strict = pass == 0;
      if (!strict && disk) break;
      for (size_t si = 0; si < ends.size(); ++si) {
        const End& s = ends[si];
        // Interior anchors first: they must be linked before anything else.
        if (!reg.interiorAnchors.empty() && s.loop >= 0) continue;
        PathQuery q;
        q.source = anchors[s.anchor];
        q.sourceFaces = s.faces;
        q.filter = {&rm.faceRegion, bad, bad};
        for (size_t gi = 0; gi < ends.size(); ++gi)
          if (gi != si && linkable(s, ends[gi], strict) && !triedLinks.count({endKey(s), endKey(ends[gi])}))
            q.goals.push_back({anchors[ends[gi].anchor], ends[gi].faces, static_cast<int>(gi)});
        if (q.goals.empty()) continue;
        // Only a shorter link can win. The margin leaves ties (a link and its reverse, equal up
        // to rounding) to the comparison below, as without the bound.
        if (best.found) q.maxLength = best.length * (1.0 + 1e-9);
        TracedPath tp = tracer.trace(q);
        if (tp.found && (!best.found || tp.length < best.length)) {
          best = tp;
          best.goal = q.goals[tp.goal].tag;
          bestSource = static_cast<int>(si);
        }
      }
    }
    if (!best.found) {
      r.status = Status::error(ErrorCode::LayoutFailed,
                               "the source layout cannot be completed: no path can split " + describe() +
                                   "; add anchors there");
      return stuck();
    }
    LayoutEdge e;
    e.a = ends[bestSource].anchor, e.b = ends[best.goal].anchor, e.kind = EdgeKind::Triangulation;
    e.length = best.length;
    const int id = paths.add(e);
    Status s = tracer.commit(best, id, paths.edges[id].vertices);
    if (!s) {
      r.status = s;
      return r;
    }
    // A link that leaves a piece no path can ever make a triangle (an empty 2-gon, whose removal
    // would only undo the link, or any region with only two anchors for corners and none inside)
    // is taken back and not tried again in this region: in a region with a handle, the shortest
    // link between two of its corners can run along a side, and re-tracing it forever would grow
    // the refined mesh without bound.
    refreshAnchorOf();
    if (cutsOffDeadPiece(L.mesh, tracer.edgePath(), anchorOf, paths.edges[id].vertices, scratch)) {
      tracer.release(paths.edges[id].vertices, id);
      paths.alive[id] = 0;
      ++r.rejectedPaths;
      triedLinks.insert({endKey(ends[bestSource]), endKey(ends[best.goal])});
      triedLinks.insert({endKey(ends[best.goal]), endKey(ends[bestSource])});
      continue;  // the same region again (with the faces the link's splits added)
    }
    triedLinks.clear();
    ++r.triangulationPaths;
  }

  // 3. Compact the surviving paths into the layout.
  compact();
  if (Status s = assemblePatches(L); !s) {
    r.status = s;
    return r;
  }
  r.layoutSeconds = seconds(t0);
  return r;
}

}  // namespace cbd
