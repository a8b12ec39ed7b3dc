#include "cbd/path_straightening.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "cbd/parameterization.h"

namespace cbd {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// One step of the segment walk: stop at a mesh vertex, or split halfedge `h` at `t`.
struct Event {
  int vertex = -1;
  int halfedge = -1;
  double t = 0.0;
};

/// Straighten layout edge e. Returns false (layout untouched) when it is skipped; sets `error`
/// when the layout was changed and could not be completed.
bool straightenOne(Layout& L, int e, PathStraighteningResult& r, std::string& error) {
  RefinedMesh& m = L.mesh;
  const LayoutEdge& edge = L.edges[e];
  // The patch with e running a -> b counter-clockwise (P1, third corner c) and the one with it
  // running b -> a (P2, third corner d).
  int p1 = -1, k1 = -1, p2 = -1, k2 = -1, sides = 0;
  for (size_t p = 0; p < L.patches.size(); ++p)
    for (int k = 0; k < 3; ++k) {
      if (L.patches[p].edges[k] != e) continue;
      ++sides;
      if (L.patches[p].forward[k]) p1 = static_cast<int>(p), k1 = k;
      else p2 = static_cast<int>(p), k2 = k;
    }
  if (sides != 2 || p1 < 0 || p2 < 0 || p1 == p2) return false;
  const Patch &P1 = L.patches[p1], &P2 = L.patches[p2];
  const int va = L.anchorVertices[edge.a], vb = L.anchorVertices[edge.b];
  const int vc = L.anchorVertices[P1.corners[(k1 + 2) % 3]], vd = L.anchorVertices[P2.corners[(k2 + 2) % 3]];
  // The union, counter-clockwise: a -> d -> b (P2's sides), b -> c -> a (P1's), onto the unit
  // square a (0,0), d (1,0), b (1,1), c (0,1).
  const Vec2 A(0, 0), D(1, 0), B(1, 1), C(0, 1);
  // Per patch: the square position of every vertex on its two other sides.
  std::unordered_map<int, Vec2> onSide[2];
  auto addSide = [&](int which, const Patch& P, int k, const Vec2& from, const Vec2& to) {
    const LayoutEdge& s = L.edges[P.edges[k]];
    const std::vector<double> f = chainFractions(m, s.vertices);
    for (size_t i = 0; i < s.vertices.size(); ++i) {
      const double x = P.forward[k] ? f[i] : 1.0 - f[i];
      onSide[which][s.vertices[i]] = (1.0 - x) * from + x * to;
    }
  };
  addSide(0, P1, (k1 + 1) % 3, B, C);
  addSide(0, P1, (k1 + 2) % 3, C, A);
  addSide(1, P2, (k2 + 1) % 3, A, D);
  addSide(1, P2, (k2 + 2) % 3, D, B);
  std::vector<int> faces;
  for (int f = 0; f < m.faceCount(); ++f)
    if (L.facePatch[f] == p1 || L.facePatch[f] == p2) faces.push_back(f);
  auto fixedAt = [&](int f, int k, Vec2& uv) {
    const int v = m.faceVertices(f)[k];
    if (v == va) return uv = A, true;
    if (v == vb) return uv = B, true;
    const auto& side = onSide[L.facePatch[f] == p1 ? 0 : 1];
    auto it = side.find(v);
    if (it == side.end()) return false;
    uv = it->second;
    return true;
  };
  std::vector<std::array<Vec2, 3>> uv;
  if (!meanValueMap(m, faces, fixedAt, uv)) return false;
  std::unordered_map<int, int> slot;  // face -> index in `faces`
  for (size_t i = 0; i < faces.size(); ++i) slot.emplace(faces[i], static_cast<int>(i));
  auto inQuad = [&](int f) { return L.facePatch[f] == p1 || L.facePatch[f] == p2; };
  auto uvOf = [&](int h) {  // square position of from(h) in face(h)
    const int f = m.face(h);
    const auto v = m.faceVertices(f);
    const int k = v[0] == m.from(h) ? 0 : v[1] == m.from(h) ? 1 : 2;
    return uv[slot.at(f)][k];
  };
  // A vertex the segment may pass through: inside the quadrilateral (on no other path, no
  // anchor but b) and not yet on the new path.
  auto onOtherPath = [&](int v) {
    for (int p : rotationAt(m, L.edgePath, v))
      if (p != e) return true;
    return false;
  };
  std::vector<int> visited;
  auto passable = [&](int v) {
    return v == vb || (std::find(visited.begin(), visited.end(), v) == visited.end() && !onOtherPath(v) &&
                       v != va && v != vc && v != vd);
  };
  // Walk the segment from a to b over the faces of the union.
  constexpr double kSnap = 0.01;
  std::vector<Event> events;
  std::vector<char> crossed(m.edgeCount(), 0);  // a straight segment crosses an edge once
  int cur = va;  // at a vertex (cur >= 0) or entering face(entry) across its edge
  int entry = -1;
  Vec2 origin = A;
  visited.push_back(va);
  const int maxSteps = 4 * static_cast<int>(faces.size()) + 16;
  for (int step = 0; step < maxSteps; ++step) {
    int exitH = -1;
    double exitT = 0;
    if (cur >= 0) {
      // The face around cur whose wedge holds the direction to b.
      const Vec2 dir = B - origin;
      const int start = m.outgoing(cur);
      int h = start;
      do {
        if (slot.count(m.face(h))) {
          const Vec2 u0 = uvOf(h), u1 = uvOf(m.next(h)), u2 = uvOf(m.prev(h));
          if (cross2(u1 - u0, dir) >= 0 && cross2(dir, u2 - u0) >= 0 && cross2(u1 - u0, u2 - u0) > 0) {
            // Exit across the opposite edge u1 -> u2.
            const Vec2 s = u2 - u1;
            const double den = cross2(dir, s);
            if (std::abs(den) > 1e-300) {
              // u0 + x dir = u1 + t s, crossed with dir: t = (u0 - u1) x dir / (s x dir).
              exitH = m.next(h);
              exitT = std::clamp(cross2(u0 - u1, dir) / cross2(s, dir), 0.0, 1.0);
              break;
            }
          }
        }
        h = m.rotateCCW(h);
      } while (h != start);
      if (exitH < 0) return false;
    } else {
      // Entered face(entry) across entry: leave across one of its other two edges.
      const Vec2 dir = B - origin;
      for (int g : {m.next(entry), m.prev(entry)}) {
        const Vec2 u1 = uvOf(g), u2 = uvOf(m.next(g));
        const Vec2 s = u2 - u1;
        const double den = cross2(s, dir);
        if (std::abs(den) <= 1e-300) continue;
        const double t = cross2(origin - u1, dir) / den;
        const double along = std::abs(dir.x()) > std::abs(dir.y()) ? (u1.x() + t * s.x() - origin.x()) / dir.x()
                                                                    : (u1.y() + t * s.y() - origin.y()) / dir.y();
        if (t < -1e-9 || t > 1 + 1e-9 || along <= 1e-12) continue;
        exitH = g, exitT = std::clamp(t, 0.0, 1.0);
        break;
      }
      if (exitH < 0) return false;
    }
    // Snap onto an end of the exit edge when close, if the path may pass there.
    const int v0 = m.from(exitH), v1 = m.to(exitH);
    int snap = -1;
    if (exitT < kSnap && passable(v0)) snap = v0;
    else if (exitT > 1 - kSnap && passable(v1)) snap = v1;
    if (snap >= 0) {
      events.push_back({snap, -1, 0.0});
      visited.push_back(snap);
      if (snap == vb) break;
      cur = snap, entry = -1;
      // Its square position (the same in every face around it: it is inside the union).
      origin = exitT < kSnap ? uvOf(exitH) : uvOf(m.next(exitH));
      continue;
    }
    if (exitT < 1e-6 || exitT > 1 - 1e-6) return false;  // through a vertex it may not use
    if (L.edgePath[RefinedMesh::edgeOf(exitH)] >= 0 && L.edgePath[RefinedMesh::edgeOf(exitH)] != e) return false;
    const int next = RefinedMesh::twin(exitH);
    if (!slot.count(m.face(next)) || crossed[RefinedMesh::edgeOf(exitH)]) return false;
    crossed[RefinedMesh::edgeOf(exitH)] = 1;
    events.push_back({-1, exitH, exitT});
    origin = (1.0 - exitT) * uvOf(exitH) + exitT * uvOf(m.next(exitH));
    cur = -1, entry = next;
  }
  if (events.empty() || events.back().vertex != vb) return false;

  // Cut it in: the old path's edges become plain edges, the crossed edges are split in order.
  const std::vector<int> old = edge.vertices;
  for (size_t k = 1; k < old.size(); ++k) L.edgePath[RefinedMesh::edgeOf(m.findHalfedge(old[k - 1], old[k]))] = -1;
  std::vector<int> chain = {va};
  for (const Event& ev : events) {
    int v = ev.vertex;
    if (v < 0) {
      const int h = ev.halfedge;
      const int pa = L.facePatch[m.face(h)], pb = L.facePatch[m.face(RefinedMesh::twin(h))];
      const int ca = L.faceCluster.empty() ? -1 : L.faceCluster[m.face(h)];
      const int cb = L.faceCluster.empty() ? -1 : L.faceCluster[m.face(RefinedMesh::twin(h))];
      v = m.splitEdge(h, ev.t);
      const auto& rec = m.lastSplit();
      L.edgePath.resize(m.edgeCount(), -1);
      L.facePatch.resize(m.faceCount(), -1);
      L.facePatch[rec.faceNewA] = pa;
      L.facePatch[rec.faceNewB] = pb;
      if (!L.faceCluster.empty()) {
        L.faceCluster.resize(m.faceCount(), -1);
        L.faceCluster[rec.faceNewA] = ca;
        L.faceCluster[rec.faceNewB] = cb;
      }
      ++r.splits;
    }
    if (m.findHalfedge(chain.back(), v) < 0) {
      error = "path " + std::to_string(e) + ": the straightened path is not a chain of mesh edges";
      return false;
    }
    chain.push_back(v);
  }
  // Where the walk went round a vertex (several crossings next to it), take the chord: a path
  // with an edge between two of its non-consecutive vertices would leave faces with all three
  // corners on it, whose split (splitCollinearFaces) gives a vertex with every neighbour on one
  // side of the patch, flat in the parameterization.
  std::vector<int> straight;
  for (size_t i = 0; i < chain.size();) {
    straight.push_back(chain[i]);
    if (i + 1 == chain.size()) break;
    size_t j = chain.size() - 1;
    for (; j > i + 1; --j) {
      const int h = m.findHalfedge(chain[i], chain[j]);
      // A chord inside the quadrilateral (a and b may also be joined by an edge elsewhere).
      if (h >= 0 && L.edgePath[RefinedMesh::edgeOf(h)] < 0 && inQuad(m.face(h)) && inQuad(m.face(RefinedMesh::twin(h))))
        break;
    }
    i = j;
  }
  chain.swap(straight);
  for (size_t k = 1; k < chain.size(); ++k) L.edgePath[RefinedMesh::edgeOf(m.findHalfedge(chain[k - 1], chain[k]))] = e;
  // Faces of the union on P1's side of the new path (flooded from P1's side b -> c) are P1's.
  const LayoutEdge& bc = L.edges[P1.edges[(k1 + 1) % 3]];
  const int seedH = P1.forward[(k1 + 1) % 3] ? m.findHalfedge(bc.vertices[0], bc.vertices[1])
                                               : m.findHalfedge(bc.vertices.back(), bc.vertices[bc.vertices.size() - 2]);
  std::vector<char> inP1(m.faceCount(), 0);
  std::vector<int> stack = {m.face(seedH)};
  inP1[stack[0]] = 1;
  int count1 = 0;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    ++count1;
    if (L.facePatch[f] != p1 && L.facePatch[f] != p2) {
      error = "path " + std::to_string(e) + ": the straightened path leaves its patches open";
      return false;
    }
    for (int k = 0, h = m.faceHalfedge(f); k < 3; ++k, h = m.next(h)) {
      if (L.edgePath[RefinedMesh::edgeOf(h)] >= 0) continue;
      const int g = m.face(RefinedMesh::twin(h));
      if (!inP1[g]) inP1[g] = 1, stack.push_back(g);
    }
  }
  int count2 = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    if (L.facePatch[f] != p1 && L.facePatch[f] != p2) continue;
    L.facePatch[f] = inP1[f] ? p1 : p2;
    count2 += !inP1[f];
  }
  if (count1 == 0 || count2 == 0) {
    error = "path " + std::to_string(e) + ": the straightened path leaves a patch empty";
    return false;
  }
  L.patches[p1].faces = count1;
  L.patches[p2].faces = count2;
  L.edges[e].vertices = std::move(chain);
  L.edges[e].length = chainLength(m, L.edges[e].vertices);
  return true;
}

}  // namespace

PathStraighteningResult straightenPaths(Layout& L, const PathStraighteningOptions& options,
                                        const Progress& progress) {
  PathStraighteningResult r;
  for (const LayoutEdge& e : L.edges) r.lengthBefore += e.length;
  std::vector<char> done(L.edges.size(), 0);
  for (int round = 0; round < options.rounds; ++round)
    for (size_t e = 0; e < L.edges.size(); ++e) {
      if (!progress.report((round + static_cast<double>(e) / L.edges.size()) / options.rounds, "straightening the paths")) {
        r.status = Status::error(ErrorCode::Cancelled, "cancelled while straightening the paths");
        return r;
      }
      std::string error;
      if (straightenOne(L, static_cast<int>(e), r, error)) done[e] = 1;
      if (!error.empty()) {
        r.status = Status::error(ErrorCode::InternalError, "path straightening: " + error);
        return r;
      }
    }
  for (char d : done) (d ? r.straightened : r.skipped) += 1;
  for (const LayoutEdge& e : L.edges) r.lengthAfter += e.length;
  return r;
}

}  // namespace cbd
