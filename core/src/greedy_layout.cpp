#include "cbd/greedy_layout.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

#include "cbd/target_layout.h"
#include "cbd/voronoi.h"

namespace cbd {
namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool cyclicEqual(std::vector<int> a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (size_t s = 0; s < a.size(); ++s) {
    if (a == b) return true;
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  return false;
}

/// One surface of the pair: its refined mesh (inside the result layout) and tracer.
struct Side {
  Layout& layout;
  PathTracer tracer;
  std::vector<int> anchorOf;
  Side(Layout& l, const EdgeNodeOptions& o) : layout(l), tracer(l.mesh, o) {
    for (int v : l.anchorVertices) tracer.setAnchor(v, true);
  }
  const std::vector<int>& anchorMap() {
    anchorOf.assign(layout.mesh.vertexCount(), -1);
    for (int i = 0; i < layout.anchorCount(); ++i) anchorOf[layout.anchorVertices[i]] = i;
    return anchorOf;
  }
  int vertex(int anchor) const { return layout.anchorVertices[anchor]; }
};

/// A way into a region at an anchor: the anchor and the faces of its wedge (all faces around
/// an interior anchor). `key` identifies the corner on both surfaces: its outgoing side.
struct RegionEnd {
  int anchor;
  std::vector<int> faces;
  int loop, pos;
  std::pair<int, int> key;
};

std::vector<RegionEnd> regionEnds(const RefinedMesh& m, const std::vector<int>& edgePath, const Region& reg,
                                  const std::vector<LayoutEdge>& edges) {
  std::vector<RegionEnd> out;
  for (int a : reg.interiorAnchors) out.push_back({a, {}, -1, -1, {-1, a}});
  for (size_t l = 0; l < reg.loops.size(); ++l)
    for (size_t k = 0; k < reg.loops[l].corners.size(); ++k) {
      const int side = reg.loops[l].sides[k];
      const int dir = edges[side].a == reg.loops[l].corners[k] ? 1 : 0;
      out.push_back({reg.loops[l].corners[k], cornerWedge(m, edgePath, reg.loops[l].cornerHalfedge[k]),
                     static_cast<int>(l), static_cast<int>(k), {side, dir}});
    }
  return out;
}

/// Two layouts edited together with shared edge ids (the greedy method's state, and the state
/// path flipping needs on any pair of isomorphic layouts): a tracer per surface, the edges,
/// their chain on either surface, and how often each anchor pair is linked.
struct PairEditor {
  Side& ss;
  Side& st;
  double scale[2];
  std::vector<LayoutEdge> edges;  // shared ids; their chains are in `chains`
  std::vector<std::vector<int>> chains[2];
  std::vector<std::vector<int>> linked;
  RegionScratch scratch[2];
  Status status;

  PairEditor(Side& s, Side& t, int anchors, double scaleS, double scaleT)
      : ss(s), st(t), scale{scaleS, scaleT}, linked(anchors, std::vector<int>(anchors, 0)) {}

  // Both partial layouts agree after a new pair of paths: same rotation at their anchors, same
  // signatures of the regions beside the two chains (the other regions agreed before and are
  // unchanged, as in the Voronoi method's target layout).
  bool consistent(std::initializer_list<int> at, const std::vector<int>& cs, const std::vector<int>& ct) {
    for (int a : at)
      if (!cyclicEqual(rotationAt(ss.layout.mesh, ss.tracer.edgePath(), ss.vertex(a)),
                       rotationAt(st.layout.mesh, st.tracer.edgePath(), st.vertex(a))))
        return false;
    auto around = [](const RefinedMesh& m, const std::vector<int>& chain) {
      std::vector<int> faces;
      for (size_t k = 0; k + 1 < chain.size(); ++k) {
        const int h = m.findHalfedge(chain[k], chain[k + 1]);
        faces.push_back(m.face(h));
        faces.push_back(m.face(RefinedMesh::twin(h)));
      }
      return faces;
    };
    return regionSignaturesAt(ss.layout.mesh, ss.tracer.edgePath(), ss.anchorMap(), edges, around(ss.layout.mesh, cs),
                              scratch[0]) ==
           regionSignaturesAt(st.layout.mesh, st.tracer.edgePath(), st.anchorMap(), edges, around(st.layout.mesh, ct),
                              scratch[1]);
  }

  // Trace on both surfaces and keep the pair of paths if consistent (1); else undo (0);
  // -1 with `status` set on an internal error.
  int tryLink(int id, const PathQuery& qs, const PathQuery& qt, int a, int b) {
    const TracedPath ps = ss.tracer.trace(qs);
    if (!ps.found) return 0;
    const TracedPath pt = st.tracer.trace(qt);
    if (!pt.found) return 0;
    return tryLinkTraced(id, ps, pt, a, b);
  }

  // The same for paths already traced on the current partial layouts.
  int tryLinkTraced(int id, const TracedPath& ps, const TracedPath& pt, int a, int b) {
    // Cyclic order first, before anything is cut into the meshes: the two paths must leave
    // both anchors between the same existing edges.
    if (ss.tracer.sectorOf(ps, false) != st.tracer.sectorOf(pt, false) ||
        ss.tracer.sectorOf(ps, true) != st.tracer.sectorOf(pt, true))
      return 0;
    std::vector<int> cs, ct;
    if (Status s = ss.tracer.commit(ps, id, cs); !s) return status = s, -1;
    if (Status s = st.tracer.commit(pt, id, ct); !s) return status = s, -1;
    edges[id].a = a, edges[id].b = b;
    if (consistent({a, b}, cs, ct)) {
      chains[0][id] = std::move(cs);
      chains[1][id] = std::move(ct);
      edges[id].length = ps.length;
      ++linked[a][b], ++linked[b][a];
      return 1;
    }
    ss.tracer.release(cs, id);
    st.tracer.release(ct, id);
    return 0;
  }

  int newEdge(EdgeKind kind) {
    LayoutEdge e;
    e.kind = kind;
    edges.push_back(e);
    chains[0].emplace_back();
    chains[1].emplace_back();
    return static_cast<int>(edges.size()) - 1;
  }
  void dropLast() {
    edges.pop_back();
    chains[0].pop_back();
    chains[1].pop_back();
  }

  // Path flipping: replace an edge by the other diagonal of its two patches when that is
  // shorter on both surfaces together (lengths over the square root of each surface's area)
  // and both layouts stay consistent; an anchor pair already linked is not linked again. Only
  // the regions beside the edge are flooded, not the whole surfaces. `kind`: what a replaced
  // edge becomes (its own kind stays when nullptr). Returns the edges replaced, -1 with
  // `status` set on an internal error.
  int flipPaths(const EdgeKind* kind) {
    int flips = 0;
    std::vector<int> faces, labels[2];
    Side* sides[2] = {&ss, &st};
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
      const std::vector<int>& ch = chains[0][e];
      const int h = ss.layout.mesh.findHalfedge(ch[0], ch[1]);
      const std::vector<int>& anchorOfS = ss.anchorMap();
      const Region left = regionAt(ss.layout.mesh, ss.tracer.edgePath(), anchorOfS, ss.layout.mesh.face(h), scratch[0], faces);
      const Region right = regionAt(ss.layout.mesh, ss.tracer.edgePath(), anchorOfS,
                                    ss.layout.mesh.face(RefinedMesh::twin(h)), scratch[0], faces);
      auto opposite = [&](const Region& reg) {
        for (int c : reg.loops[0].corners)
          if (c != edges[e].a && c != edges[e].b) return c;
        return -1;
      };
      const int c = opposite(left), d = opposite(right);
      if (c < 0 || d < 0 || c == d || linked[c][d]) continue;
      const double oldCost = edges[e].length / scale[0] + chainLength(st.layout.mesh, chains[1][e]) / scale[1];
      const LayoutEdge old = edges[e];
      const std::vector<int> oldS = chains[0][e], oldT = chains[1][e];
      ss.tracer.release(oldS, e);
      st.tracer.release(oldT, e);
      --linked[old.a][old.b], --linked[old.b][old.a];
      // Trace c-d inside the merged quadrilateral on both surfaces.
      bool ok = false;
      PathQuery q[2];
      for (int s = 0; s < 2; ++s) {
        Side& sd = *sides[s];
        const int hv = sd.layout.mesh.findHalfedge(s == 0 ? oldS[0] : oldT[0], s == 0 ? oldS[1] : oldT[1]);
        const Region reg = regionAt(sd.layout.mesh, sd.tracer.edgePath(), sd.anchorMap(), sd.layout.mesh.face(hv),
                                    scratch[s], faces);
        labels[s].assign(sd.layout.mesh.faceCount(), -1);
        for (int f : faces) labels[s][f] = 0;
        q[s].filter = {&labels[s], 0, 0};
        q[s].source = sd.vertex(c);
        q[s].goals.push_back({sd.vertex(d), {}, 0});
        if (reg.loops.size() == 1)
          for (size_t k = 0; k < reg.loops[0].corners.size(); ++k) {
            const auto wedge = cornerWedge(sd.layout.mesh, sd.tracer.edgePath(), reg.loops[0].cornerHalfedge[k]);
            if (reg.loops[0].corners[k] == c) q[s].sourceFaces = wedge;
            if (reg.loops[0].corners[k] == d) q[s].goals[0].faces = wedge;
          }
      }
      const TracedPath ps = ss.tracer.trace(q[0]), pt = st.tracer.trace(q[1]);
      if (ps.found && pt.found && ps.length / scale[0] + pt.length / scale[1] < oldCost) {
        const int res = tryLinkTraced(e, ps, pt, c, d);
        if (res < 0) return -1;
        ok = res == 1;
      }
      if (ok) {
        if (kind) edges[e].kind = *kind, edges[e].cut = -1, edges[e].eta = 0;
        ++flips;
        continue;
      }
      edges[e] = old;
      if (Status s = ss.tracer.recommit(oldS, e); !s) return status = s, -1;
      if (Status s = st.tracer.recommit(oldT, e); !s) return status = s, -1;
      chains[0][e] = oldS, chains[1][e] = oldT;
      ++linked[old.a][old.b], ++linked[old.b][old.a];
    }
    return flips;
  }

  // Both layouts from the edges, patch k corresponding to patch k.
  Status finish() {
    Side* sides[2] = {&ss, &st};
    for (int s = 0; s < 2; ++s) {
      Layout& L = sides[s]->layout;
      L.edges = edges;
      for (size_t e = 0; e < edges.size(); ++e) {
        L.edges[e].vertices = chains[s][e];
        L.edges[e].length = chainLength(L.mesh, chains[s][e]);
      }
      L.edgePath = sides[s]->tracer.edgePath();
      if (Status st2 = assemblePatches(L); !st2) return st2;
    }
    if (Status s = alignPatches(ss.layout, st.layout); !s) return s;
    return checkIsomorphic(ss.layout, st.layout);
  }
};

}  // namespace

GreedyLayoutResult buildGreedyLayout(const IndexedMesh& S, const std::vector<int>& sa, const IndexedMesh& T,
                                     const std::vector<int>& ta, const GreedyLayoutOptions& options,
                                     const Progress& progress) {
  GreedyLayoutResult r;
  const char* const stage = "tracing the base domains";
  auto cancelled = [&] {
    r.status = Status::error(ErrorCode::Cancelled, "cancelled while tracing the greedy layouts");
    return r;
  };
  const int na = static_cast<int>(sa.size());
  if (na < 3 || ta.size() != sa.size()) {
    r.status = Status::error(ErrorCode::InvalidArgument, "the greedy layout needs the same number (>= 3) of anchors on both meshes");
    return r;
  }
  for (int i = 0; i < na; ++i)
    if (sa[i] < 0 || sa[i] >= S.vertexCount() || ta[i] < 0 || ta[i] >= T.vertexCount()) {
      r.status = Status::error(ErrorCode::InvalidArgument, "anchor " + std::to_string(i) + " is not a vertex");
      return r;
    }
  auto t0 = std::chrono::steady_clock::now();
  r.source.mesh = RefinedMesh(S);
  r.target.mesh = RefinedMesh(T);
  r.source.anchorVertices = sa;
  r.target.anchorVertices = ta;
  separateAnchors(r.source.mesh, sa);
  separateAnchors(r.target.mesh, ta);
  Side ss(r.source, options.edgeNodes), st(r.target, options.edgeNodes);
  Side* sides[2] = {&ss, &st};

  // Euler characteristic of the surface and the edge count of a complete layout.
  const int chi = closedEulerCharacteristic(S);
  const int targetEdges = 3 * (na - chi);  // E = 3(n - 2 + 2g)
  // The method links a pair of anchors at most once, so a layout has at most n(n-1)/2 edges:
  // with fewer anchors than that allows (Heawood's bound, n >= (7 + sqrt(1 + 48g)) / 2 for
  // genus g >= 1) no trial can succeed; say so at once rather than after the all-pairs searches.
  auto pairs = [](long long n) { return n * (n - 1) / 2; };
  if (targetEdges > pairs(na)) {
    int enough = na;
    while (3LL * (enough - chi) > pairs(enough)) ++enough;
    r.status = Status::error(ErrorCode::LayoutFailed,
                             "greedy layout (Kraevoy & Sheffer): " + std::to_string(na) + " anchors on a surface of genus " +
                                 std::to_string((2 - chi) / 2) + " need " + std::to_string(targetEdges) +
                                 " layout edges, more than the " + std::to_string(pairs(na)) +
                                 " pairs of anchors the method (which never links a pair twice) can link; give at least " +
                                 std::to_string(enough) +
                                 " anchors (Heawood's bound), or use the Voronoi method, which links a pair through "
                                 "several cuts");
    return r;
  }

  // 1. All-pairs shortest paths on both meshes, over the whole surfaces.
  const double scale[2] = {std::sqrt(surfaceArea(S)), std::sqrt(surfaceArea(T))};
  std::vector<std::vector<double>> dist[2];
  for (int s = 0; s < 2; ++s) {
    dist[s].assign(na, std::vector<double>(na, std::numeric_limits<double>::infinity()));
    for (int i = 0; i + 1 < na; ++i) {
      if (!progress.report(0.15 * (s + static_cast<double>(i) / na), "shortest paths between the anchors"))
        return cancelled();
      PathQuery q;
      q.source = sides[s]->vertex(i);
      q.distancesOnly = true;
      for (int j = i + 1; j < na; ++j) q.goals.push_back({sides[s]->vertex(j), {}, j});
      const TracedPath tp = sides[s]->tracer.trace(q);
      for (size_t g = 0; g < q.goals.size(); ++g) dist[s][i][q.goals[g].tag] = tp.goalDistances[g];
    }
  }
  struct Candidate {
    double key;
    int i, j;
    bool operator<(const Candidate& o) const { return std::tie(key, i, j) < std::tie(o.key, o.i, o.j); }
  };
  std::vector<Candidate> queue;
  for (int i = 0; i < na; ++i)
    for (int j = i + 1; j < na; ++j)
      if (std::isfinite(dist[0][i][j]) && std::isfinite(dist[1][i][j]))
        queue.push_back({dist[0][i][j] / scale[0] + dist[1][i][j] / scale[1], i, j});
  std::sort(queue.begin(), queue.end());
  r.candidates = static_cast<int>(queue.size());
  r.candidateSeconds = seconds(t0);
  t0 = std::chrono::steady_clock::now();

  PairEditor ed(ss, st, na, scale[0], scale[1]);
  std::vector<LayoutEdge>& edges = ed.edges;
  auto& linked = ed.linked;
  auto& scratch = ed.scratch;
  auto tryLink = [&](int id, const PathQuery& qs, const PathQuery& qt, int a, int b) {
    const int res = ed.tryLink(id, qs, qt, a, b);
    if (res < 0) r.status = ed.status;
    return res;
  };

  // 2. Trial and error in order of length.
  auto report = [&] { return progress.report(0.3 + 0.6 * edges.size() / std::max(targetEdges, 1), stage); };
  for (const Candidate& c : queue) {
    if (static_cast<int>(edges.size()) >= targetEdges) break;
    if (!report()) return cancelled();
    if (linked[c.i][c.j]) continue;
    ++r.tried;
    const int id = ed.newEdge(EdgeKind::Greedy);
    PathQuery qs, qt;
    qs.source = ss.vertex(c.i), qs.goals.push_back({ss.vertex(c.j), {}, 0});
    qt.source = st.vertex(c.i), qt.goals.push_back({st.vertex(c.j), {}, 0});
    const int res = tryLink(id, qs, qt, c.i, c.j);
    if (res < 0) return r;
    if (res == 0) {
      ed.dropLast();
      ++r.rejected;
      continue;
    }
    ++r.accepted;
  }

  // 3. Complete the regions that are not triangles with paths inside corresponding regions.
  // Both region maps are analysed once, then updated where a path was cut in; regions are
  // taken in the order of their lowest face, as a fresh analysis numbers them.
  RegionMap ms = analyzeRegions(ss.layout.mesh, ss.tracer.edgePath(), ss.anchorMap());
  RegionMap mt = analyzeRegions(st.layout.mesh, st.tracer.edgePath(), st.anchorMap());
  for (int guard = 0;; ++guard) {
    if (!report()) return cancelled();
    const int bad = ms.firstNonTriangle();
    if (bad < 0) break;
    const Region& rs = ms.regions[bad];
    // The corresponding target region: the one with the same corners (anchor + outgoing side).
    std::vector<RegionEnd> es = regionEnds(ss.layout.mesh, ss.tracer.edgePath(), rs, edges);
    std::vector<int> targetOrder(mt.regions.size());
    std::iota(targetOrder.begin(), targetOrder.end(), 0);
    std::sort(targetOrder.begin(), targetOrder.end(), [&](int x, int y) { return mt.firstFace[x] < mt.firstFace[y]; });
    int badT = -1;
    for (size_t o = 0; o < targetOrder.size() && badT < 0; ++o) {
      const int k = targetOrder[o];
      const std::vector<RegionEnd> et = regionEnds(st.layout.mesh, st.tracer.edgePath(), mt.regions[k], edges);
      if (et.size() != es.size() || mt.regions[k].eulerCharacteristic != rs.eulerCharacteristic) continue;
      bool same = true;
      for (const RegionEnd& e : es) {
        bool found = false;
        for (const RegionEnd& f : et) found = found || (f.key == e.key && f.anchor == e.anchor);
        same = same && found;
      }
      if (same) badT = k;
    }
    std::vector<RegionEnd> et =
        badT >= 0 ? regionEnds(st.layout.mesh, st.tracer.edgePath(), mt.regions[badT], edges) : std::vector<RegionEnd>{};
    auto describe = [&] {
      std::string s = "region of " + std::to_string(rs.faces) + " faces with corners";
      for (const auto& l : rs.loops)
        for (int c : l.corners) s += " " + anchorLabel(options.anchorNames, c);
      s += " and " + std::to_string(rs.interiorAnchors.size()) + " anchors inside";
      return s;
    };
    if (badT < 0 || guard > 4 * na + 64) {
      r.status = Status::error(ErrorCode::LayoutFailed,
                               "greedy layout (Kraevoy & Sheffer): the " + describe() +
                                   " has no consistent counterpart on the target; check that the anchors there "
                                   "correspond, add anchors in that region, or use the Voronoi method");
      return r;
    }
    // Candidate links by source length inside the region.
    const bool disk = rs.loops.size() == 1 && rs.eulerCharacteristic == 1;
    std::vector<int>& labelS = ms.faceRegion;
    std::vector<int>& labelT = mt.faceRegion;
    struct Link {
      double length;
      int s, g;
      bool operator<(const Link& o) const { return std::tie(length, s, g) < std::tie(o.length, o.s, o.g); }
    };
    std::vector<Link> links;
    for (size_t si = 0; si < es.size(); ++si) {
      PathQuery q;
      q.source = ss.vertex(es[si].anchor);
      q.sourceFaces = es[si].faces;
      q.filter = {&labelS, bad, bad};
      q.distancesOnly = true;
      for (size_t gi = 0; gi < es.size(); ++gi) {
        const RegionEnd &a = es[si], &b = es[gi];
        if (gi <= si || a.anchor == b.anchor || linked[a.anchor][b.anchor]) continue;
        if (a.loop >= 0 && a.loop == b.loop && disk) {
          const int m = static_cast<int>(rs.loops[a.loop].corners.size());
          const int d = std::abs(a.pos - b.pos);
          if (d == 1 || d == m - 1) continue;
        }
        q.goals.push_back({ss.vertex(b.anchor), b.faces, static_cast<int>(gi)});
      }
      if (q.goals.empty()) continue;
      const TracedPath tp = ss.tracer.trace(q);
      for (size_t g = 0; g < q.goals.size(); ++g)
        if (std::isfinite(tp.goalDistances[g])) links.push_back({tp.goalDistances[g], static_cast<int>(si), q.goals[g].tag});
    }
    std::sort(links.begin(), links.end());
    bool done = false;
    for (const Link& l : links) {
      const RegionEnd &a = es[l.s], &b = es[l.g];
      auto counterpart = [&](const RegionEnd& e) -> const RegionEnd* {
        for (const RegionEnd& f : et)
          if (f.key == e.key && f.anchor == e.anchor) return &f;
        return nullptr;
      };
      const RegionEnd *at = counterpart(a), *bt = counterpart(b);
      if (!at || !bt) continue;
      const int id = ed.newEdge(EdgeKind::Triangulation);
      PathQuery qs, qt;
      qs.source = ss.vertex(a.anchor), qs.sourceFaces = a.faces, qs.filter = {&labelS, bad, bad};
      qs.goals.push_back({ss.vertex(b.anchor), b.faces, 0});
      qt.source = st.vertex(a.anchor), qt.sourceFaces = at->faces, qt.filter = {&labelT, badT, badT};
      qt.goals.push_back({st.vertex(b.anchor), bt->faces, 0});
      const int res = tryLink(id, qs, qt, a.anchor, b.anchor);
      if (res < 0) return r;
      if (res == 1) {
        ++r.completionPaths;
        done = true;
        break;
      }
      ed.dropLast();
      ++r.completionRejected;
      // An attempt cut in and taken out again leaves the faces it split, inside the two
      // regions: label them so, and let the corner wedges hold them.
      if (labelS.size() < static_cast<size_t>(ss.layout.mesh.faceCount()) ||
          labelT.size() < static_cast<size_t>(st.layout.mesh.faceCount())) {
        labelS.resize(ss.layout.mesh.faceCount(), bad);
        labelT.resize(st.layout.mesh.faceCount(), badT);
        es = regionEnds(ss.layout.mesh, ss.tracer.edgePath(), rs, edges);
        et = regionEnds(st.layout.mesh, st.tracer.edgePath(), mt.regions[badT], edges);
      }
    }
    if (!done) {
      r.status = Status::error(ErrorCode::LayoutFailed,
                               "greedy layout (Kraevoy & Sheffer): the " + describe() +
                                   " cannot be triangulated without linking an anchor pair twice (which the "
                                   "method never does); add anchors in that region, or use the Voronoi method, "
                                   "which links a pair through several cuts");
      return r;
    }
    updateRegion(ms, ss.layout.mesh, ss.tracer.edgePath(), ss.anchorMap(), bad, scratch[0]);
    updateRegion(mt, st.layout.mesh, st.tracer.edgePath(), st.anchorMap(), badT, scratch[1]);
  }

  // 4. Path flipping.
  if (!progress.report(0.9, "flipping paths")) return cancelled();
  if (options.flipPaths) {
    r.flips = ed.flipPaths(nullptr);
    if (r.flips < 0) return r.flips = 0, r.status = ed.status, r;
  }

  // 5. Both layouts, patch k corresponding to patch k.
  if (Status s = ed.finish(); !s) return r.status = s, r;
  r.layoutSeconds = seconds(t0);
  return r;
}

PathFlippingResult flipLayoutPaths(Layout& source, Layout& target, const EdgeNodeOptions& edgeNodes) {
  PathFlippingResult r;
  const auto t0 = std::chrono::steady_clock::now();
  const int na = source.anchorCount();
  if (na != target.anchorCount() || source.edges.size() != target.edges.size() || source.edges.empty() ||
      source.edgePath.size() != static_cast<size_t>(source.mesh.edgeCount()) ||
      target.edgePath.size() != static_cast<size_t>(target.mesh.edgeCount())) {
    r.status = Status::error(ErrorCode::InvalidArgument,
                             "path flipping needs two complete layouts with the same anchors and edges");
    return r;
  }
  if (Status s = checkIsomorphic(source, target); !s) return r.status = s, r;
  Layout* layouts[2] = {&source, &target};
  // Each surface's tracer holds its layout's paths again; the Voronoi clusters, when the layout
  // has them, are the faces' labels, so that faces split by a new path keep their cluster.
  Side ss(source, edgeNodes), st(target, edgeNodes);
  Side* sides[2] = {&ss, &st};
  PairEditor ed(ss, st, na, std::sqrt(surfaceArea(source.mesh)), std::sqrt(surfaceArea(target.mesh)));
  ed.edges = source.edges;
  for (int s = 0; s < 2; ++s) {
    const Layout& L = *layouts[s];
    for (size_t e = 0; e < L.edges.size(); ++e) {
      ed.chains[s].push_back(L.edges[e].vertices);
      if (Status st2 = sides[s]->tracer.recommit(L.edges[e].vertices, static_cast<int>(e)); !st2) return r.status = st2, r;
    }
    if (L.faceCluster.size() == static_cast<size_t>(L.mesh.faceCount())) sides[s]->tracer.faceLabel() = L.faceCluster;
  }
  for (const LayoutEdge& e : source.edges) ++ed.linked[e.a][e.b], ++ed.linked[e.b][e.a];
  const EdgeKind flipped = EdgeKind::Flipped;
  r.flips = ed.flipPaths(&flipped);
  if (r.flips < 0) return r.flips = 0, r.status = ed.status, r;
  for (int s = 0; s < 2; ++s)
    if (!layouts[s]->faceCluster.empty()) layouts[s]->faceCluster = sides[s]->tracer.faceLabel();
  if (Status s = ed.finish(); !s) return r.status = s, r;
  r.seconds = seconds(t0);
  return r;
}

}  // namespace cbd
