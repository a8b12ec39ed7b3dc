#include "cbd/target_layout.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace cbd {
namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// How the regions beside a refused target path (`got`) differ from those beside its source
/// path (`want`), both from one region: as the end of "its path ...". Pieces are paired by their
/// boundaries, which the two paths' sectors fix alike.
std::string refusal(const std::vector<RegionSignature>& want, const std::vector<RegionSignature>& got) {
  if (want.size() != got.size())
    return want.size() == 1 ? "would cut its region in two, where the source's path runs round a handle of it"
                            : "would run round a handle of its region, where the source's path cuts it in two";
  bool anchors = false, handles = false;
  for (const RegionSignature& w : want) {
    const auto g = std::find_if(got.begin(), got.end(), [&](const RegionSignature& x) { return x.loops == w.loops; });
    if (g == got.end()) return "would give its regions other boundaries than on the source";
    anchors = anchors || g->inside != w.inside;
    handles = handles || g->euler != w.euler;
  }
  if (anchors) return "would enclose other anchors than on the source";
  if (handles) return "would leave a handle of its region on the other side of it than on the source";
  return "would give its regions other boundaries than on the source";
}

/// The input vertex at a handle of region `region` (its faces labelled so, bounded by the edges
/// with edgePath >= 0): on the shortest loop of a homology basis of the region, by tree-cotree
/// (Eppstein 2003: a spanning tree of the region's faces across free edges, a spanning forest
/// of its vertices over the edges the face tree does not cross; each free edge in neither
/// closes a loop in the face tree), the corner of the loop's faces nearest the loop's mean
/// point that is an input vertex off every path. -1 when the region has no handle (a disk, or
/// loops only parallel to its boundary) or the loop has no such corner.
int handleVertex(const RefinedMesh& m, const std::vector<int>& label, int region, const std::vector<int>& edgePath,
                 const std::vector<int>& anchorOf) {
  const int nf = m.faceCount();
  std::vector<int> parentEdge(nf, -2), depth(nf, 0);  // -2: not reached; -1: the root
  std::vector<int> order;
  for (int f = 0; f < nf && order.empty(); ++f)
    if (label[f] == region) parentEdge[f] = -1, order.push_back(f);
  auto other = [&](int f, int e) { return m.face(2 * e) == f ? m.face(2 * e + 1) : m.face(2 * e); };
  auto freeInside = [&](int e) {
    return edgePath[e] < 0 && label[m.face(2 * e)] == region && label[m.face(2 * e + 1)] == region;
  };
  for (size_t i = 0; i < order.size(); ++i) {
    int h = m.faceHalfedge(order[i]);
    for (int k = 0; k < 3; ++k, h = m.next(h)) {
      const int e = RefinedMesh::edgeOf(h), g = other(order[i], e);
      if (!freeInside(e) || parentEdge[g] != -2) continue;
      parentEdge[g] = e, depth[g] = depth[order[i]] + 1, order.push_back(g);
    }
  }
  std::vector<int> root(m.vertexCount());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  std::vector<char> seen(m.edgeCount(), 0);
  std::vector<int> best;  // the faces of the shortest loop so far
  for (const int f : order) {
    int h = m.faceHalfedge(f);
    for (int k = 0; k < 3; ++k, h = m.next(h)) {
      const int e = RefinedMesh::edgeOf(h);
      if (seen[e]) continue;
      seen[e] = 1;
      const int g = other(f, e);
      if (freeInside(e) && (parentEdge[f] == e || parentEdge[g] == e)) continue;  // in the face tree
      const int a = find(m.from(h)), b = find(m.to(h));
      if (a != b) {
        root[a] = b;
        continue;
      }
      if (!freeInside(e)) continue;
      std::vector<int> loop{f, g};  // up the face tree from f and g to their common ancestor
      int x = f, y = g;
      while (x != y) {
        int& deeper = depth[x] >= depth[y] ? x : y;
        deeper = other(deeper, parentEdge[deeper]);
        loop.push_back(deeper);
      }
      std::sort(loop.begin(), loop.end());  // its faces, each once
      loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
      if (best.empty() || loop.size() < best.size()) best = std::move(loop);
    }
  }
  Vec3 mean = Vec3::Zero();
  for (const int f : best)
    for (const int v : m.faceVertices(f)) mean += m.position(v) / (3.0 * best.size());
  int vertex = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (const int f : best)
    for (const int v : m.faceVertices(f))
      if (m.inputVertex(v) >= 0 && anchorOf[v] < 0 && !onPath(m, edgePath, v) && (m.position(v) - mean).norm() < nearest)
        vertex = v, nearest = (m.position(v) - mean).norm();
  return vertex;
}

/// Candidates for the target vertex of an anchor pair at source vertex `s` (off every path of the
/// source's partial layout, `srcPartial`): in the target's partial layout (`tgtPartial`) the
/// region whose signature is that of the region of `s`, which the blocking rule keeps alike on
/// both surfaces, and in it the vertices placed most alike relative to the region's sides
/// (matchingRegionVertices), best first. Empty when there is no such region or vertex.
std::vector<int> matchingHandleVertices(const Layout& src, const std::vector<int>& srcPartial,
                                        const std::vector<int>& srcAnchorOf, const Layout& tgt,
                                        const std::vector<int>& tgtPartial, int s) {
  Layout a = src, b = tgt;  // copies of both meshes, made once, when the layout is stuck
  a.edgePath = srcPartial;
  b.edgePath = tgtPartial;
  RegionScratch scratch;
  const auto sig = regionSignaturesAt(a.mesh, a.edgePath, srcAnchorOf, a.edges, {a.mesh.face(a.mesh.outgoing(s))}, scratch);
  RegionDistances ds, dt;
  if (sig.size() != 1 || !regionDistances(a, sig[0], ds) || !regionDistances(b, sig[0], dt)) return {};
  return matchingRegionVertices(ds, s, dt, kHandleCandidates);
}

}  // namespace

Status checkIsomorphic(const Layout& s, const Layout& t) {
  auto fail = [](const std::string& what) { return Status::error(ErrorCode::InternalError, "layouts differ: " + what); };
  if (s.anchorCount() != t.anchorCount()) return fail("anchor counts");
  if (s.edges.size() != t.edges.size()) return fail("edge counts " + std::to_string(s.edges.size()) + " and " + std::to_string(t.edges.size()));
  if (s.patches.size() != t.patches.size()) return fail("patch counts");
  for (size_t e = 0; e < s.edges.size(); ++e)
    if (s.edges[e].a != t.edges[e].a || s.edges[e].b != t.edges[e].b) return fail("edge " + std::to_string(e) + " joins other anchors");
  for (size_t p = 0; p < s.patches.size(); ++p)
    if (s.patches[p].corners != t.patches[p].corners || s.patches[p].edges != t.patches[p].edges ||
        s.patches[p].forward != t.patches[p].forward)
      return fail("patch " + std::to_string(p));
  for (int a = 0; a < s.anchorCount(); ++a) {
    const auto& rs = s.rotation[a];
    auto rt = t.rotation[a];
    if (rs.size() != rt.size()) return fail("degree of anchor " + std::to_string(a));
    if (rs.empty()) continue;
    auto it = std::find(rt.begin(), rt.end(), rs[0]);
    if (it == rt.end()) return fail("rotation at anchor " + std::to_string(a));
    std::rotate(rt.begin(), it, rt.end());
    if (rs != rt) return fail("rotation at anchor " + std::to_string(a));
  }
  return Status::success();
}

Status alignPatches(const Layout& src, Layout& L) {
  std::map<std::array<int, 3>, int> byEdges;
  for (size_t p = 0; p < L.patches.size(); ++p) {
    auto key = L.patches[p].edges;
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    byEdges[key] = static_cast<int>(p);
  }
  std::vector<Patch> ordered(src.patches.size());
  std::vector<int> newIndex(L.patches.size(), -1);
  for (size_t p = 0; p < src.patches.size(); ++p) {
    const Patch& sp = src.patches[p];
    auto key = sp.edges;
    const int shift = static_cast<int>(std::min_element(key.begin(), key.end()) - key.begin());
    std::rotate(key.begin(), key.begin() + shift, key.end());
    auto it = byEdges.find(key);
    if (it == byEdges.end()) {
      return Status::error(ErrorCode::InternalError, "source patch " + std::to_string(p) + " has no target counterpart");
    }
    Patch tp = L.patches[it->second];
    // Start at the same corner as the source patch.
    const int start = static_cast<int>(std::find(tp.corners.begin(), tp.corners.end(), sp.corners[0]) - tp.corners.begin());
    std::rotate(tp.corners.begin(), tp.corners.begin() + start % 3, tp.corners.end());
    std::rotate(tp.edges.begin(), tp.edges.begin() + start % 3, tp.edges.end());
    std::rotate(tp.forward.begin(), tp.forward.begin() + start % 3, tp.forward.end());
    ordered[p] = tp;
    newIndex[it->second] = static_cast<int>(p);
  }
  L.patches = std::move(ordered);
  for (int& p : L.facePatch) p = newIndex[p];
  return Status::success();
}

namespace {

TargetLayoutResult traceTarget(const Layout& src, const IndexedMesh& target, const std::vector<int>& anchors,
                               const TargetLayoutOptions& options, bool sourceOrder, const Progress& progress) {
  TargetLayoutResult r;
  r.inSourceOrder = sourceOrder;
  auto cancelled = [&] {
    r.status = Status::error(ErrorCode::Cancelled, "cancelled while tracing the target layout");
    return r;
  };
  const int na = src.anchorCount();
  if (static_cast<int>(anchors.size()) != na) {
    r.status = Status::error(ErrorCode::InvalidArgument, "the target has " + std::to_string(anchors.size()) +
                                                             " anchors, the source layout " + std::to_string(na));
    return r;
  }
  if (Status st = checkAnchorVertices(target, anchors, "target"); !st) {
    r.status = st;
    return r;
  }
  auto t0 = std::chrono::steady_clock::now();
  Layout& L = r.layout;
  std::vector<int> clusters;
  if (Status st = startVoronoiLayout(target, anchors, L, clusters, r.cuts); !st) {
    r.status = st;
    return r;
  }
  r.voronoiSeconds = seconds(t0);
  if (!progress.report(0.1, "tracing the base domain on the target")) return cancelled();
  t0 = std::chrono::steady_clock::now();
  PathTracer tracer(L.mesh, options.edgeNodes);
  tracer.faceLabel() = std::move(clusters);
  tracer.edgeLabel() = r.cuts.edgeCut;
  for (int v : anchors) tracer.setAnchor(v, true);

  const int ne = static_cast<int>(src.edges.size());
  L.edges.assign(ne, LayoutEdge{});
  for (int e = 0; e < ne; ++e) {
    L.edges[e].a = src.edges[e].a;
    L.edges[e].b = src.edges[e].b;
    L.edges[e].kind = src.edges[e].kind;
  }
  // Source edges per anchor pair, and the target cuts of each pair.
  std::map<std::pair<int, int>, int> sourceLinks;
  for (const LayoutEdge& e : src.edges) ++sourceLinks[std::minmax(e.a, e.b)];
  std::map<std::pair<int, int>, std::vector<int>> targetCutsOf;
  for (int c = 0; c < static_cast<int>(r.cuts.cuts.size()); ++c) targetCutsOf[{r.cuts.cuts[c].i, r.cuts.cuts[c].j}].push_back(c);
  auto group = [&](int e) {
    const auto key = std::minmax(src.edges[e].a, src.edges[e].b);
    if (sourceLinks[key] > 1) return 2;  // (c) multiple linkage
    const auto it = targetCutsOf.find(key);
    const size_t cuts = it == targetCutsOf.end() ? 0 : it->second.size();
    if (cuts == 1) return 0;             // (a)
    if (cuts == 0) return 1;             // (b)
    return 2;                            // one source edge, several target cuts: like (c)
  };
  std::vector<int> pending(ne);
  std::iota(pending.begin(), pending.end(), 0);
  if (!sourceOrder)
    std::stable_sort(pending.begin(), pending.end(), [&](int x, int y) {
      const int gx = group(x), gy = group(y);
      return gx != gy ? gx < gy : src.edges[x].length < src.edges[y].length;
    });

  // The source's partial layout: its refined mesh with only the embedded edges as walls.
  std::vector<int> srcPartial(src.mesh.edgeCount(), -1);
  std::vector<char> embedded(ne, 0);
  std::vector<int> srcAnchorOf(src.mesh.vertexCount(), -1), tgtAnchorOf;
  for (int i = 0; i < na; ++i) srcAnchorOf[src.anchorVertices[i]] = i;
  // Splits only add vertices, and those are never anchors.
  tgtAnchorOf.assign(L.mesh.vertexCount(), -1);
  for (int i = 0; i < na; ++i) tgtAnchorOf[anchors[i]] = i;
  auto refreshTargetAnchorOf = [&] { tgtAnchorOf.resize(L.mesh.vertexCount(), -1); };
  auto setSourceEdge = [&](int e, int value) {
    const auto& chain = src.edges[e].vertices;
    for (size_t k = 0; k + 1 < chain.size(); ++k)
      srcPartial[RefinedMesh::edgeOf(src.mesh.findHalfedge(chain[k], chain[k + 1]))] = value;
  };

  // Sector at anchor `a` for source edge e: the embedded neighbours before and after e in the
  // source rotation, and the target faces between them (counter-clockwise).
  struct Sector {
    int before = -1, after = -1;
    std::vector<int> faces;
  };
  auto facesAround = [&](int v) {
    std::vector<int> faces;
    const int h0 = L.mesh.outgoing(v);
    int h = h0;
    do {
      faces.push_back(L.mesh.face(h));
      h = L.mesh.rotateCCW(h);
    } while (h != h0);
    return faces;
  };
  auto sectorAt = [&](int e, int a, int occurrence) {
    Sector s;
    const auto& rot = src.rotation[a];
    const int n = static_cast<int>(rot.size());
    int pos = -1, seen = 0;
    for (int k = 0; k < n; ++k)
      if (rot[k] == e && seen++ == occurrence) pos = k;
    for (int k = 1; k < n; ++k) {
      const int x = rot[(pos - k + n) % n];
      if (x != e && embedded[x]) { s.before = x; break; }
    }
    for (int k = 1; k < n; ++k) {
      const int x = rot[(pos + k) % n];
      if (x != e && embedded[x]) { s.after = x; break; }
    }
    const RefinedMesh& m = L.mesh;
    const int v = anchors[a];
    if (s.before < 0) {  // nothing embedded at a yet: every face around it
      s.faces = facesAround(v);
      return s;
    }
    const int hb = leavingHalfedge(m, L.edges[s.before].vertices, v);
    const int ha = leavingHalfedge(m, L.edges[s.after].vertices, v);
    int h = hb;
    do {
      s.faces.push_back(m.face(h));
      h = m.rotateCCW(h);
    } while (h != ha);
    return s;
  };
  auto ambiguous = [&](int e) {
    // Another pending edge between the same anchors that would leave `a` in the same sector.
    const LayoutEdge& x = src.edges[e];
    for (int o : pending) {
      if (o == e || embedded[o]) continue;
      const LayoutEdge& y = src.edges[o];
      if (std::minmax(x.a, x.b) != std::minmax(y.a, y.b)) continue;
      const Sector s1 = sectorAt(e, x.a, 0), s2 = sectorAt(o, x.a, 0);
      if (s1.before == s2.before && s1.after == s2.after) return true;
    }
    return false;
  };

  // Target clusters that share a cut.
  std::vector<std::vector<int>> clusterNeighbours(na);
  for (const Cut& c : r.cuts.cuts) {
    clusterNeighbours[c.i].push_back(c.j);
    clusterNeighbours[c.j].push_back(c.i);
  }
  // The regions of both partial layouts, tracked path by path (RegionTracker): no attempt
  // floods its region, and a check walks the loops the new path touches.
  RegionTracker srcRegions(src.mesh, srcPartial, srcAnchorOf, src.edges);
  RegionTracker tgtRegions(L.mesh, tracer.edgePath(), tgtAnchorOf, src.edges);
  std::vector<char> inRing(na, 0);
  std::vector<std::string> reason(ne);  // why each edge was last not traced
  // Per edge, whether its last refused path cut in two a region its source path runs round a
  // handle of.
  std::vector<char> refusedAtHandle(ne, 0);
  // The region of the partial source layout a source edge lies in (beside its first step).
  auto sourceRegionOf = [&](int e) {
    const auto& chain = src.edges[e].vertices;
    return srcRegions.regionOf(src.mesh.face(src.mesh.findHalfedge(chain[0], chain[1])));
  };
  // The anchors whose clusters each source path runs through besides its own two: the faces on
  // both sides of the path, by their source cluster.
  std::vector<std::vector<int>> passedAnchors(ne);
  if ((options.waitForPassedAnchors || sourceOrder) && src.faceCluster.size() == static_cast<size_t>(src.mesh.faceCount())) {
    for (int e = 0; e < ne; ++e) {
      const LayoutEdge& se = src.edges[e];
      std::set<int> passed;
      for (size_t k = 0; k + 1 < se.vertices.size(); ++k) {
        const int h = src.mesh.findHalfedge(se.vertices[k], se.vertices[k + 1]);
        if (h < 0) continue;  // not a layout validateLayout accepts; the tracing reports it
        for (const int f : {src.mesh.face(h), src.mesh.face(RefinedMesh::twin(h))}) {
          if (f < 0) continue;
          const int c = src.faceCluster[f];
          if (c >= 0 && c < na && c != se.a && c != se.b) passed.insert(c);
        }
      }
      passedAnchors[e].assign(passed.begin(), passed.end());
    }
  }
  // With the source's order, the anchors whose clusters lie within two rings of faces of each
  // source path (a superset of those it passes, when they differ).
  std::vector<std::vector<int>> nearAnchors(ne);
  if (sourceOrder && src.faceCluster.size() == static_cast<size_t>(src.mesh.faceCount())) {
    const RefinedMesh& m = src.mesh;
    std::vector<char> seen(m.vertexCount(), 0);
    for (int e = 0; e < ne; ++e) {
      std::vector<int> ring = src.edges[e].vertices, touched = ring;
      for (int v : ring) seen[v] = 1;
      std::set<int> clusters;
      for (int k = 0; k < 2; ++k) {
        std::vector<int> next;
        for (int v : ring) {
          const int h0 = m.outgoing(v);
          int h = h0;
          do {
            const int f = m.face(h);
            const int c = src.faceCluster[f];
            if (c >= 0 && c < na && c != src.edges[e].a && c != src.edges[e].b) clusters.insert(c);
            for (int w : m.faceVertices(f))
              if (!seen[w]) seen[w] = 1, next.push_back(w), touched.push_back(w);
            h = m.rotateCCW(h);
          } while (h != h0);
        }
        ring = std::move(next);
      }
      for (int v : touched) seen[v] = 0;
      if (clusters.size() > passedAnchors[e].size()) nearAnchors[e].assign(clusters.begin(), clusters.end());
    }
  }
  // Last resort before failing (nothing else can be traced): an edge whose shortest path in its
  // region is refused is traced again with the faces its refused paths ran through closed, so
  // that the next path passes the region's handles on another side (another homotopy class
  // between the two sectors). The faces round the two anchors stay open, so the path can
  // still leave through its sectors.
  bool walled = false;
  auto tryEmbed = [&](int e) -> int {  // 1 embedded, 0 not now, -1 internal error (r.status set)
    const LayoutEdge& se = src.edges[e];
    // The regions beside this edge in the partial source layout once it is added: what the
    // target must reproduce beside its path (the other regions already agree). Undone unless
    // the edge is embedded.
    const int srcRegion = sourceRegionOf(e);
    setSourceEdge(e, e);
    const std::vector<RegionSignature> want = srcRegions.add(se.vertices, srcRegion);
    auto notNow = [&] {
      srcRegions.undo();
      setSourceEdge(e, -1);
      return 0;
    };
    // Search rings of target clusters around the two anchors' own: 0 = their two clusters
    // (the paper's local search), k = clusters within k cuts of them, then the whole region.
    std::vector<int> ring(na, -1);
    std::vector<int> frontier{se.a, se.b};
    ring[se.a] = ring[se.b] = 0;
    // A refused attempt is rolled back with its splits, so the sectors hold for every attempt.
    const Sector sa = sectorAt(e, se.a, 0), sb = sectorAt(e, se.b, 0);
    const int region = tgtRegions.regionOf(sa.faces.front());
    if (tgtRegions.regionOf(sb.faces.front()) != region) {
      reason[e] = "its two sectors lie in different regions of the partial target layout";
      return notNow();
    }
    // Commit a traced path and keep it when the regions beside it match the source's: 1. Else
    // undo it: 0, with `got` the regions it made and `corridor` (when asked) the faces it ran
    // through. -1: internal error (r.status set).
    auto keepIfMatching = [&](const TracedPath& tp, std::vector<RegionSignature>& got, std::vector<int>* corridor) -> int {
      std::vector<int> chain;
      const PathTracer::Checkpoint before = tracer.checkpoint();
      if (Status s = tracer.commit(tp, e, chain); !s) {
        r.status = s;
        return -1;
      }
      refreshTargetAnchorOf();
      got = tgtRegions.add(chain, region);
      if (got == want) {
        L.edges[e].vertices = std::move(chain);
        L.edges[e].length = tp.length;
        return 1;
      }
      if (corridor)
        for (size_t i = 0; i + 1 < chain.size(); ++i) {
          const int h = L.mesh.findHalfedge(chain[i], chain[i + 1]);
          if (h < 0) continue;
          corridor->push_back(L.mesh.face(h));
          corridor->push_back(L.mesh.face(RefinedMesh::twin(h)));
        }
      refusedAtHandle[e] = want.size() == 1 && got.size() == 2;
      tracer.rollback(chain, e, before);
      tgtRegions.undo();
      ++r.rejectedPaths;
      return 0;
    };
    auto query = [&] {  // from a's sector to b's
      PathQuery q;
      q.source = anchors[se.a];
      q.sourceFaces = sa.faces;
      q.goals.push_back({anchors[se.b], sb.faces, 0});
      return q;
    };
    // Source order: the source's query first. A cut path inside the two target clusters,
    // through one target cut of its pair at a time (the one of the source's rank first); then
    // any path through the target clusters its source path passes, or near it (two rings of
    // faces, for a source cut too short to have a target counterpart); then the region.
    if (sourceOrder) {
      frontier.clear();
      // Try a path found by the source's query. Kept (1), refused (0), internal error (-1).
      auto tryPath = [&](const TracedPath& tp) {
        std::vector<RegionSignature> got;
        const int k = keepIfMatching(tp, got, nullptr);
        if (k > 0) ++r.embeddedInClusters;
        if (k == 0) reason[e] = "its path in the source's order " + refusal(want, got) + " (blocking)";
        return k;
      };
      // The target cuts of the pair, the one of the source cut's rank first, each crossed
      // alone (the others blocked), as the source crossed its cut.
      if (se.kind == EdgeKind::VoronoiCut) {
        std::vector<int> cand = targetCutsOf[std::minmax(se.a, se.b)];
        std::stable_sort(cand.begin(), cand.end(), [&](int x, int y) {
          return (r.cuts.cuts[x].eta != se.eta) < (r.cuts.cuts[y].eta != se.eta);
        });
        for (const int c : cand) {
          PathQuery q = query();
          q.filter = {&tracer.faceLabel(), se.a, se.b};
          for (const int o : cand)
            if (o != c) q.blockedEdgeLabels.push_back(o);
          const TracedPath tp = tracer.trace(q);
          if (tp.found)
            if (const int k = tryPath(tp); k != 0) return k;
        }
      }
      for (const std::vector<int>* near : {&passedAnchors[e], &nearAnchors[e]}) {
        if (near->empty()) continue;
        for (int c = 0; c < na; ++c) inRing[c] = 0;
        inRing[se.a] = inRing[se.b] = 1;
        for (const int c : *near) inRing[c] = 1;
        PathQuery q = query();
        q.filter.label = &tgtRegions.labels();
        q.filter.a = q.filter.b = region;
        q.filter.group = &tracer.faceLabel(), q.filter.groupAllowed = &inRing;
        const TracedPath tp = tracer.trace(q);
        if (!tp.found) continue;
        if (const int k = tryPath(tp); k != 0) return k;
      }
    }
    std::vector<char> walls;
    int wallRounds = 0;
    for (int attempt = 0;; ++attempt) {
      const bool wholeRegion = frontier.empty();
      for (int c = 0; c < na; ++c) inRing[c] = ring[c] >= 0;
      std::vector<int> next;
      for (int c : frontier)
        for (int d : clusterNeighbours[c])
          if (ring[d] < 0) ring[d] = attempt + 1, next.push_back(d);
      frontier = std::move(next);
      PathQuery q = query();
      q.filter.label = &tgtRegions.labels();
      q.filter.a = q.filter.b = region;
      if (!wholeRegion) q.filter.group = &tracer.faceLabel(), q.filter.groupAllowed = &inRing;
      if (wallRounds > 0) q.filter.walls = &walls;
      TracedPath tp = tracer.trace(q);
      if (!tp.found) {
        if (wallRounds == 0)
          reason[e] = attempt == 0 ? "no path inside the two target clusters" : "no path inside its region";
        if (wholeRegion) break;
        continue;
      }
      std::vector<RegionSignature> got;
      std::vector<int> corridor;  // the faces a refused path ran through, when walls may follow
      const bool wallsNext = walled && wholeRegion && wallRounds < options.closedCorridorRounds;
      const int kept = keepIfMatching(tp, got, wallsNext ? &corridor : nullptr);
      if (kept < 0) return -1;
      if (kept > 0) {
        (attempt == 0 && !sourceOrder ? r.embeddedInClusters : r.embeddedInRegion)++;
        r.pastClosedCorridors += wallRounds > 0;
        return 1;
      }
      reason[e] = (walled ? "every path tried, also with the corridors of the refused ones closed, was refused "
                             "(blocking): the last one "
                           : "its shortest path ") +
                   refusal(want, got) + (walled ? "" : " (blocking)");
      if (!wholeRegion) continue;
      if (corridor.empty()) break;
      // After the rollback the faces the path split are back under their own indices (the
      // split halves beyond the face count are gone).
      walls.resize(L.mesh.faceCount(), 0);
      for (int f : corridor)
        if (f >= 0 && f < L.mesh.faceCount()) walls[f] = 1;
      for (const int a : {anchors[se.a], anchors[se.b]})
        for (int f : facesAround(a)) walls[f] = 0;
      ++wallRounds;
    }
    return notNow();
  };

  auto hasTargetPath = [&](int a) {
    for (const int x : src.rotation[a])
      if (embedded[x]) return true;
    return false;
  };
  auto waitsForPassedAnchor = [&](int e) {
    for (const int c : passedAnchors[e])
      if (!hasTargetPath(c)) return true;
    return false;
  };
  std::vector<char> waited(ne, 0);

  bool force = false;
  while (!pending.empty()) {
    bool advanced = false;
    for (size_t k = 0; k < pending.size();) {
      const int e = pending[k];
      if (!force && !sourceOrder && waitsForPassedAnchor(e)) {
        ++r.postponements;
        if (!waited[e]) waited[e] = 1, ++r.waitedForPassedAnchors;
        ++k;
        continue;
      }
      if (!force && !sourceOrder && ambiguous(e)) {
        ++r.postponements;
        ++k;
        continue;
      }
      // Every attempt reports, embedded or not: a run of refused attempts must stay cancellable.
      if (!progress.report(0.1 + 0.9 * (ne - static_cast<double>(pending.size())) / std::max(ne, 1),
                           "tracing the base domain on the target"))
        return cancelled();
      const int res = tryEmbed(e);
      if (res < 0) return r;
      if (res == 0) {
        ++r.postponements;
        ++k;
        continue;
      }
      embedded[e] = 1;
      setSourceEdge(e, e);
      pending.erase(pending.begin() + static_cast<long>(k));
      if (!progress.report(0.1 + 0.9 * (ne - static_cast<double>(pending.size())) / std::max(ne, 1),
                           "tracing the base domain on the target"))
        return cancelled();
      advanced = true;
      force = walled = false;
    }
    if (!advanced) {
      if (!force || (!walled && options.closedCorridorRounds > 0)) {
        walled = force;
        force = true;
        continue;
      }
      // The message says where this order got stuck; buildTargetLayout frames it.
      const int stuck = pending.front();
      const LayoutEdge& se = src.edges[stuck];
      r.status = Status::error(ErrorCode::LayoutFailed, "edge " + std::to_string(stuck) + " between anchors " +
                                                            anchorLabel(options.anchorNames, se.a) + " and " +
                                                            anchorLabel(options.anchorNames, se.b) + " (" +
                                                            std::to_string(pending.size()) + " edges left): " + reason[stuck]);
      // Where the source's path runs round a handle the target's paths cannot pass, name a
      // vertex at it: an anchor pair there gives the paths a corner at the handle.
      if (refusedAtHandle[stuck]) {
        const int s = handleVertex(src.mesh, srcRegions.labels(), sourceRegionOf(stuck), srcPartial, srcAnchorOf);
        if (s >= 0) {
          const Vec3& x = src.mesh.position(s);
          char where[96];
          std::snprintf(where, sizeof where, "vertex %d (%.6g %.6g %.6g)", s, x.x(), x.y(), x.z());
          r.handleSourceVertex = s;
          r.handleTargetVertices = matchingHandleVertices(src, srcPartial, srcAnchorOf, L, tracer.edgePath(), s);
          r.status.message += "; the source's path runs round a handle there, smaller than the anchor spacing, near source " +
                              std::string(where) + ": an anchor pair there (on both surfaces) gives the paths a corner at it";
        }
      }
      return r;
    }
  }

  L.edgePath = tracer.edgePath();
  L.faceCluster = tracer.faceLabel();
  if (options.partial) {
    r.layoutSeconds = seconds(t0);
    return r;
  }
  if (Status s = assemblePatches(L); !s) {
    r.status = s;
    return r;
  }
  if (Status s = alignPatches(src, L); !s) {
    r.status = s;
    return r;
  }
  if (Status s = checkIsomorphic(src, L); !s) {
    r.status = s;
    return r;
  }
  r.layoutSeconds = seconds(t0);
  return r;
}

}  // namespace

TargetLayoutResult buildTargetLayout(const Layout& src, const IndexedMesh& target, const std::vector<int>& anchors,
                                     const TargetLayoutOptions& options, const Progress& progress) {
  using Order = TargetLayoutOptions::Order;
  const std::string advice = "; check that these anchors correspond, or add anchors nearby";
  // Shorter traces both orders: each reports half the progress. A fallback restarts it.
  const bool halves = options.order == Order::Shorter;
  auto run = [&](bool sourceOrder) {
    const auto t0 = std::chrono::steady_clock::now();
    const Progress part = !halves ? progress : sourceOrder ? progress.part(0.5, 1.0) : progress.part(0.0, 0.5);
    TargetLayoutResult x = traceTarget(src, target, anchors, options, sourceOrder, part);
    x.layoutSeconds = seconds(t0) - x.voronoiSeconds;
    return x;
  };
  const bool p1First = options.order != Order::Source;
  TargetLayoutResult first = run(!p1First);
  const bool both = options.order == Order::Procedure1ThenSource || options.order == Order::Shorter;
  const bool tryOther = both && (first.status.code == ErrorCode::LayoutFailed ||
                                 (first.status.ok() && options.order == Order::Shorter));
  if (!tryOther) {
    if (first.status.code == ErrorCode::LayoutFailed)
      first.status.message = std::string("the target layout cannot be completed") +
                             (p1First ? "" : " in the source's order") + ": " + first.status.message + advice;
    return first;
  }
  TargetLayoutResult second = run(true);
  if (second.status.code == ErrorCode::Cancelled) return second;
  second.voronoiSeconds += first.voronoiSeconds;
  second.layoutSeconds += first.layoutSeconds;
  if (!first.status) {
    second.procedure1Failure = first.status.message;
    if (second.status.code == ErrorCode::LayoutFailed && second.handleSourceVertex < 0) {
      second.handleSourceVertex = first.handleSourceVertex;
      second.handleTargetVertices = first.handleTargetVertices;
    }
    if (second.status.code == ErrorCode::LayoutFailed)
      second.status.message = "the target layout cannot be completed, neither in Procedure 1's order (" +
                              first.status.message + ") nor in the source's (" + second.status.message + ")" + advice;
    return second;
  }
  // Both complete (Shorter): the one whose paths keep their source paths' lengths best.
  const double d1 = lengthDetour(src, first.layout);
  if (!second.status || d1 <= lengthDetour(src, second.layout)) {
    first.voronoiSeconds = second.voronoiSeconds;
    first.layoutSeconds = second.layoutSeconds;
    return first;
  }
  second.procedure1Detour = d1;
  return second;
}

}  // namespace cbd
