#include "cbd/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

namespace cbd {
namespace {

constexpr int64_t kGoalBase = int64_t(1) << 40;
constexpr int64_t kNone = std::numeric_limits<int64_t>::min();  // no parent
constexpr double kInf = std::numeric_limits<double>::infinity();

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

PathTracer::PathTracer(RefinedMesh& mesh, const EdgeNodeOptions& options) : mesh_(mesh), options_(options) {
  options_.minEdgeNodes = std::max(1, options_.minEdgeNodes);
  options_.maxEdgeNodes = std::max(options_.minEdgeNodes, options_.maxEdgeNodes);
  const int nv = mesh_.vertexCount(), nf = mesh_.faceCount(), ne = mesh_.edgeCount();
  anchor_.assign(nv, 0);
  vertexPaths_.assign(nv, 0);
  faceLabel_.assign(nf, -1);
  edgeLabel_.assign(ne, -1);
  edgePath_.assign(ne, -1);
  edgeNodes_.assign(ne, 0);
  slotBase_.assign(ne, 0);
  for (int e = 0; e < ne; ++e) computeEdgeNodes(e);
  journal_.clear();  // nothing to go back to before the first path
}

void PathTracer::setAnchor(int v, bool isAnchor) { anchor_[v] = isAnchor ? 1 : 0; }

int64_t PathTracer::nodeCount() const {
  int64_t n = mesh_.vertexCount();
  for (int c : edgeNodes_) n += c;
  return n;
}

void PathTracer::growEdges() {
  const size_t ne = mesh_.edgeCount(), nf = mesh_.faceCount(), nv = mesh_.vertexCount();
  edgeLabel_.resize(ne, -1);
  edgePath_.resize(ne, -1);
  edgeNodes_.resize(ne, 0);
  slotBase_.resize(ne, 0);
  faceLabel_.resize(nf, -1);
  anchor_.resize(nv, 0);
  vertexPaths_.resize(nv, 0);
}

void PathTracer::computeEdgeNodes(int e) {
  journal_.push_back({e, edgeNodes_[e], slotBase_[e]});
  if (edgePath_[e] >= 0) {
    edgeNodes_[e] = 0;
    return;
  }
  int n = options_.minEdgeNodes;
  if (options_.adaptive) {
    const double l = mesh_.edgeLength(e);
    double sum = 0.0;
    int count = 0;
    for (int end = 0; end < 2; ++end) {
      const int v = mesh_.to(2 * e + end);
      const int start = mesh_.outgoing(v);
      int h = start;
      do {
        sum += mesh_.edgeLength(RefinedMesh::edgeOf(h));
        ++count;
        h = mesh_.rotateCCW(h);
      } while (h != start);
    }
    sum -= l;  // the edge itself was counted from both ends
    --count;
    const double lbar = sum / count;
    if (lbar > 0) n = std::max(n, static_cast<int>(std::lround(options_.minEdgeNodes * l / lbar)));
  }
  n = std::min(n, options_.maxEdgeNodes);
  edgeNodes_[e] = n;
  slotBase_[e] = static_cast<int>(slotEdge_.size());
  slotEdge_.insert(slotEdge_.end(), n, e);
  const Vec3 &a = mesh_.position(mesh_.from(2 * e)), &b = mesh_.position(mesh_.to(2 * e));
  for (int j = 0; j < n; ++j) {
    const double t = (j + 1.0) / (n + 1.0);
    slotPos_.push_back((1.0 - t) * a + t * b);
  }
}

void PathTracer::onSplit() {
  growEdges();
  const RefinedMesh::SplitRecord& r = mesh_.lastSplit();
  const int e = RefinedMesh::edgeOf(r.halfedge);
  edgeLabel_[r.edgeContinued] = edgeLabel_[e];
  edgeLabel_[r.edgeDiagonalA] = edgeLabel_[r.edgeDiagonalB] = -1;
  edgePath_[r.edgeContinued] = edgePath_[r.edgeDiagonalA] = edgePath_[r.edgeDiagonalB] = -1;
  faceLabel_[r.faceNewA] = faceLabel_[mesh_.face(r.halfedge)];
  faceLabel_[r.faceNewB] = faceLabel_[mesh_.face(RefinedMesh::twin(r.halfedge))];
  for (int x : {e, r.edgeContinued, r.edgeDiagonalA, r.edgeDiagonalB}) computeEdgeNodes(x);
}

const Vec3& PathTracer::nodePosition(int64_t node) const {
  if (node >= 0) return mesh_.position(static_cast<int>(node));
  return slotPos_[static_cast<size_t>(-node - 1)];
}

TracedPath PathTracer::trace(const PathQuery& q) {
  TracedPath result;
  const int nv = mesh_.vertexCount();
  const size_t ns = slotEdge_.size();
  if (distV_.size() < static_cast<size_t>(nv)) {
    distV_.resize(nv), hV_.resize(nv), parentV_.resize(nv), stampV_.resize(nv, 0), blockV_.resize(nv, 0);
    goalV_.resize(nv, 0);
  }
  if (distS_.size() < ns) distS_.resize(ns), hS_.resize(ns), parentS_.resize(ns), stampS_.resize(ns, 0);
  if (blockE_.size() < static_cast<size_t>(mesh_.edgeCount())) blockE_.resize(mesh_.edgeCount(), 0);
  ++stamp_;
  const uint32_t st = stamp_;

  // Walls: edges labelled as blocked and their end vertices.
  if (!q.blockedEdgeLabels.empty()) {
    for (int e = 0; e < mesh_.edgeCount(); ++e) {
      if (edgeLabel_[e] < 0 || !contains(q.blockedEdgeLabels, edgeLabel_[e])) continue;
      blockE_[e] = st;
      blockV_[mesh_.to(2 * e)] = st;
      blockV_[mesh_.to(2 * e + 1)] = st;
    }
  }

  std::vector<double> goalDist(q.goals.size(), kInf);
  std::vector<int64_t> goalParent(q.goals.size(), kNone);
  // Goals by vertex (a vertex may hold several goals, e.g. two sectors of one anchor).
  std::unordered_map<int, std::vector<int>> goalsAt;
  goalsAt.reserve(q.goals.size());
  for (size_t g = 0; g < q.goals.size(); ++g) {
    goalsAt[q.goals[g].vertex].push_back(static_cast<int>(g));
    goalV_[q.goals[g].vertex] = st;
  }

  auto dist = [&](int64_t n) -> double {
    if (n >= 0) return stampV_[n] == st ? distV_[n] : kInf;
    const size_t s = static_cast<size_t>(-n - 1);
    return stampS_[s] == st ? distS_[s] : kInf;
  };
  // A* with the straight-line distance to the nearest goal vertex: a consistent lower bound on
  // the remaining path (arcs are straight segments, and a minimum of consistent bounds is
  // consistent), so the first goal reached is the nearest and its path is shortest. Only when
  // every goal must be settled is it plain Dijkstra. A node's bound is computed once, when the
  // search first reaches it (hV_, hS_), and kept with its distance.
  const bool astar = !q.distancesOnly && !q.goals.empty();
  std::vector<Vec3> goalPos;
  if (astar)
    for (const auto& kv : goalsAt) goalPos.push_back(mesh_.position(kv.first));
  auto heuristic = [&](int64_t n) {
    if (!astar) return 0.0;
    const Vec3& p = nodePosition(n);
    double h = (p - goalPos[0]).norm();
    for (size_t g = 1; g < goalPos.size(); ++g) h = std::min(h, (p - goalPos[g]).norm());
    return h;
  };
  using Item = std::pair<double, int64_t>;  // (distance + heuristic, node)
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  // Vertices and edge nodes keep their scratch in separate arrays, indexed alike.
  auto relax = [&](int64_t from, int64_t to, double d) {
    const bool vertex = to >= 0;
    const size_t i = vertex ? static_cast<size_t>(to) : static_cast<size_t>(-to - 1);
    uint32_t& stamp = vertex ? stampV_[i] : stampS_[i];
    double& dist = vertex ? distV_[i] : distS_[i];
    double& h = vertex ? hV_[i] : hS_[i];
    if (stamp != st) {
      stamp = st, h = heuristic(to);
    } else if (d >= dist) {
      return;
    }
    dist = d;
    (vertex ? parentV_[i] : parentS_[i]) = from;
    pq.push({d + h, to});
  };
  auto bound = [&](int64_t n) { return n >= 0 ? hV_[n] : hS_[static_cast<size_t>(-n - 1)]; };
  // Arrive at a goal vertex through face f (or along an edge with faces f, f2).
  auto arrive = [&](int64_t from, int v, int f, int f2, double d) {
    if (goalV_[v] != st) return;
    const auto it = goalsAt.find(v);
    for (int g : it->second) {
      const PathGoal& goal = q.goals[g];
      if (!goal.faces.empty() && !contains(goal.faces, f) && (f2 < 0 || !contains(goal.faces, f2))) continue;
      if (d < goalDist[g]) {
        goalDist[g] = d, goalParent[g] = from;
        pq.push({d, kGoalBase + static_cast<int64_t>(g)});
      }
    }
  };
  auto vertexUsable = [&](int v) {
    return !anchor_[v] && vertexPaths_[v] == 0 && blockV_[v] != st;
  };
  auto faceOk = [&](int f, bool atSource) {
    if (!q.filter.allows(f)) return false;
    return !atSource || q.sourceFaces.empty() || contains(q.sourceFaces, f);
  };
  // Try node `to` reached from `from` at distance d through face f (f2: second face for
  // along-edge moves, -1 otherwise).
  auto offer = [&](int64_t from, int64_t to, double d, int f, int f2) {
    if (to >= 0) {
      const int v = static_cast<int>(to);
      arrive(from, v, f, f2, d);
      if (!vertexUsable(v)) return;
    } else {
      const int e = slotEdge_[static_cast<size_t>(-to - 1)];
      if (blockE_[e] == st) return;
    }
    relax(from, to, d);
  };

  const Vec3 srcPos = mesh_.position(q.source);
  stampV_[q.source] = st, distV_[q.source] = 0.0, parentV_[q.source] = kNone, hV_[q.source] = heuristic(q.source);
  pq.push({0.0, q.source});
  int reached = -1;
  size_t settledGoals = 0;
  std::vector<char> goalSettled(q.goals.size(), 0);
  while (!pq.empty()) {
    // Plain variables, not structured bindings: lambdas below capture them (C++17).
    const double key = pq.top().first;
    const int64_t u = pq.top().second;
    pq.pop();
    if (key >= q.maxLength) break;  // keys never decrease: nothing shorter is left
    if (u >= kGoalBase) {
      reached = static_cast<int>(u - kGoalBase);
      if (!q.distancesOnly) break;
      if (!goalSettled[reached]) goalSettled[reached] = 1, ++settledGoals;
      if (settledGoals == q.goals.size()) break;
      continue;
    }
    const double d = dist(u);
    if (key > d + bound(u)) continue;  // a stale entry
    const Vec3 pu = u == q.source ? srcPos : nodePosition(u);
    const bool atSource = (u == q.source);
    auto cross = [&](int64_t w, int f) { offer(u, w, d + (nodePosition(w) - pu).norm(), f, -1); };
    // Nodes on edge e (all of them) reached across face f.
    auto crossEdge = [&](int e, int f) {
      const int n = edgeNodes_[e];
      for (int j = 0; j < n; ++j) cross(-1 - static_cast<int64_t>(slotBase_[e] + j), f);
    };
    if (u >= 0) {
      const int v = static_cast<int>(u);
      const int start = mesh_.outgoing(v);
      int h = start;
      do {
        const int e = RefinedMesh::edgeOf(h);
        const int f = mesh_.face(h), ft = mesh_.face(RefinedMesh::twin(h));
        const bool okF = faceOk(f, atSource), okT = faceOk(ft, atSource);
        // Along the edge v -> x: the first node, or x itself.
        if ((okF || okT) && edgePath_[e] < 0) {
          int64_t w;
          if (edgeNodes_[e] == 0) {
            w = mesh_.to(h);
          } else {
            const bool fwd = (h & 1) == 0;  // halfedge 2e runs from(2e) -> to(2e)
            const int j = fwd ? 0 : edgeNodes_[e] - 1;
            w = -1 - static_cast<int64_t>(slotBase_[e] + j);
          }
          offer(u, w, d + (nodePosition(w) - pu).norm(), okF ? f : ft, okF && okT ? ft : -1);
        }
        // Across face f: every node of the opposite edge.
        if (okF) crossEdge(RefinedMesh::edgeOf(mesh_.next(h)), f);
        h = mesh_.rotateCCW(h);
      } while (h != start);
    } else {
      const int s = static_cast<int>(-u - 1);
      const int e = slotEdge_[s];
      const int j = s - slotBase_[e], n = edgeNodes_[e];
      const int f0 = mesh_.face(2 * e), f1 = mesh_.face(2 * e + 1);
      const bool ok0 = faceOk(f0, false), ok1 = faceOk(f1, false);
      if (ok0 || ok1) {
        const int ff = ok0 ? f0 : f1, f2 = ok0 && ok1 ? f1 : -1;
        const int64_t prevNode = j == 0 ? mesh_.from(2 * e) : -1 - static_cast<int64_t>(slotBase_[e] + j - 1);
        const int64_t nextNode = j == n - 1 ? mesh_.to(2 * e) : -1 - static_cast<int64_t>(slotBase_[e] + j + 1);
        offer(u, prevNode, d + (nodePosition(prevNode) - pu).norm(), ff, f2);
        offer(u, nextNode, d + (nodePosition(nextNode) - pu).norm(), ff, f2);
      }
      for (int side = 0; side < 2; ++side) {
        const int h = 2 * e + side;
        const int f = mesh_.face(h);
        if (!faceOk(f, false)) continue;
        const int hn = mesh_.next(h), hp = mesh_.next(hn);
        cross(mesh_.to(hn), f);  // the opposite corner
        crossEdge(RefinedMesh::edgeOf(hn), f);
        crossEdge(RefinedMesh::edgeOf(hp), f);
      }
    }
  }
  if (q.distancesOnly) {
    result.goalDistances = goalDist;
    result.found = settledGoals > 0;
    return result;
  }
  if (reached < 0) return result;

  // Back-track, then shortcut: no two non-consecutive nodes may share a face, so that cutting
  // the path into the mesh turns every step into an edge (see commit).
  std::vector<int64_t> nodes;
  nodes.push_back(q.goals[reached].vertex);
  for (int64_t n = goalParent[reached]; n != kNone;) {
    nodes.push_back(n);
    n = n >= 0 ? parentV_[n] : parentS_[static_cast<size_t>(-n - 1)];
  }
  std::reverse(nodes.begin(), nodes.end());

  auto facesOf = [&](int64_t n, size_t index, std::vector<int>& out) {
    out.clear();
    if (n >= 0) {
      const int v = static_cast<int>(n);
      const int start = mesh_.outgoing(v);
      int h = start;
      do {
        const int f = mesh_.face(h);
        bool ok = q.filter.allows(f);
        if (index == 0 && !q.sourceFaces.empty()) ok = ok && contains(q.sourceFaces, f);
        if (index + 1 == nodes.size() && !q.goals[reached].faces.empty()) ok = ok && contains(q.goals[reached].faces, f);
        if (ok) out.push_back(f);
        h = mesh_.rotateCCW(h);
      } while (h != start);
    } else {
      const int e = slotEdge_[static_cast<size_t>(-n - 1)];
      for (int side = 0; side < 2; ++side)
        if (q.filter.allows(mesh_.face(2 * e + side))) out.push_back(mesh_.face(2 * e + side));
    }
  };
  std::unordered_map<int, size_t> last;
  std::vector<int> fs;
  for (size_t i = 0; i < nodes.size(); ++i) {
    facesOf(nodes[i], i, fs);
    for (int f : fs) last[f] = i;
  }
  std::vector<int64_t> taut;
  for (size_t i = 0; i < nodes.size();) {
    taut.push_back(nodes[i]);
    if (i + 1 == nodes.size()) break;
    facesOf(nodes[i], i, fs);
    size_t j = i + 1;
    for (int f : fs) j = std::max(j, last[f]);
    // Two vertices sharing a face are joined by an edge: never along an existing path edge.
    if (j > i + 1 && nodes[i] >= 0 && nodes[j] >= 0) {
      const int h = mesh_.findHalfedge(static_cast<int>(nodes[i]), static_cast<int>(nodes[j]));
      if (h >= 0 && edgePath_[RefinedMesh::edgeOf(h)] >= 0) j = i + 1;
    }
    i = j;
  }
  result.nodes = std::move(taut);
  result.found = true;
  result.goal = reached;
  for (size_t i = 1; i < result.nodes.size(); ++i)
    result.length += (nodePosition(result.nodes[i]) - nodePosition(result.nodes[i - 1])).norm();
  return result;
}

std::pair<int, int> PathTracer::sectorOf(const TracedPath& path, bool atEnd) const {
  const size_t n = path.nodes.size();
  const int a = static_cast<int>(atEnd ? path.nodes[n - 1] : path.nodes[0]);
  const int64_t next = atEnd ? path.nodes[n - 2] : path.nodes[1];
  // A face around the anchor that the first step lies in (or borders, for a step along an edge).
  auto touches = [&](int f) {
    if (next >= 0) {
      for (int v : mesh_.faceVertices(f))
        if (v == next) return true;
      return false;
    }
    const int e = slotEdge_[static_cast<size_t>(-next - 1)];
    return mesh_.face(2 * e) == f || mesh_.face(2 * e + 1) == f;
  };
  const int start = mesh_.outgoing(a);
  int h = start, leave = -1;
  do {
    if (touches(mesh_.face(h))) leave = h;
    h = mesh_.rotateCCW(h);
  } while (h != start && leave < 0);
  if (leave < 0) return {-1, -1};
  // Counter-clockwise from the face: the first path edge is "after"; clockwise, "before".
  int after = -1, before = -1;
  h = leave;
  for (int guard = 0; guard < 100000; ++guard) {
    h = mesh_.rotateCCW(h);
    if (edgePath_[RefinedMesh::edgeOf(h)] >= 0) { after = edgePath_[RefinedMesh::edgeOf(h)]; break; }
    if (h == leave) break;
  }
  h = leave;
  for (int guard = 0; guard < 100000; ++guard) {
    if (edgePath_[RefinedMesh::edgeOf(h)] >= 0) { before = edgePath_[RefinedMesh::edgeOf(h)]; break; }
    h = mesh_.next(RefinedMesh::twin(h));  // one step clockwise
    if (h == leave) break;
  }
  return {before, after};
}

Status PathTracer::commit(const TracedPath& path, int pathId, std::vector<int>& vertices) {
  vertices.clear();
  if (!path.found || path.nodes.size() < 2 || path.nodes.front() < 0 || path.nodes.back() < 0)
    return Status::error(ErrorCode::InternalError, "commit of a path that does not join two vertices");
  // Where each edge node lies, captured before any split renumbers the edge nodes.
  struct OnEdge {
    int edge;
    double t;
    int a, b;
  };
  std::vector<OnEdge> at(path.nodes.size(), OnEdge{-1, 0.0, -1, -1});
  for (size_t i = 0; i < path.nodes.size(); ++i) {
    const int64_t n = path.nodes[i];
    if (n >= 0) continue;
    const int s = static_cast<int>(-n - 1);
    const int e = slotEdge_[s];
    at[i] = {e, (s - slotBase_[e] + 1.0) / (edgeNodes_[e] + 1.0), mesh_.from(2 * e), mesh_.to(2 * e)};
  }
  // Splits already made on each original edge, as (t, vertex), to find the piece holding t.
  std::unordered_map<int, std::vector<std::pair<double, int>>> splits;
  for (size_t i = 0; i < path.nodes.size(); ++i) {
    if (path.nodes[i] >= 0) {
      vertices.push_back(static_cast<int>(path.nodes[i]));
      continue;
    }
    const OnEdge& o = at[i];
    auto& list = splits[o.edge];
    double tlo = 0.0, thi = 1.0;
    int vlo = o.a, vhi = o.b;
    for (const auto& [t, v] : list) {
      if (t < o.t && t > tlo) tlo = t, vlo = v;
      if (t > o.t && t < thi) thi = t, vhi = v;
    }
    const int h = mesh_.findHalfedge(vlo, vhi);
    if (h < 0) return Status::error(ErrorCode::InternalError, "edge node lost its edge while cutting a path");
    const int m = mesh_.splitEdge(h, (o.t - tlo) / (thi - tlo));
    onSplit();
    list.emplace_back(o.t, m);
    vertices.push_back(m);
  }
  for (size_t i = 1; i + 1 < vertices.size(); ++i) {
    if (vertexPaths_[vertices[i]] != 0 || anchor_[vertices[i]]) {
      vertices.clear();
      return Status::error(ErrorCode::InternalError, "a traced path runs through a vertex already on a path");
    }
  }
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    const int h = mesh_.findHalfedge(vertices[i], vertices[i + 1]);
    if (h < 0 || edgePath_[RefinedMesh::edgeOf(h)] >= 0) {
      vertices.clear();
      return Status::error(ErrorCode::InternalError, "a traced path step is not a free mesh edge after cutting");
    }
  }
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    const int e = RefinedMesh::edgeOf(mesh_.findHalfedge(vertices[i], vertices[i + 1]));
    journal_.push_back({e, edgeNodes_[e], slotBase_[e]});
    edgePath_[e] = pathId;
    edgeNodes_[e] = 0;
  }
  for (int v : vertices) ++vertexPaths_[v];
  return Status::success();
}

Status PathTracer::recommit(const std::vector<int>& vertices, int pathId) {
  std::vector<int> edges;
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    const int h = mesh_.findHalfedge(vertices[i], vertices[i + 1]);
    if (h < 0 || edgePath_[RefinedMesh::edgeOf(h)] >= 0)
      return Status::error(ErrorCode::InternalError, "a path to restore is no longer a chain of free edges");
    edges.push_back(RefinedMesh::edgeOf(h));
  }
  for (size_t i = 1; i + 1 < vertices.size(); ++i)
    if (vertexPaths_[vertices[i]] != 0) return Status::error(ErrorCode::InternalError, "a path to restore meets another path");
  for (int e : edges) {
    journal_.push_back({e, edgeNodes_[e], slotBase_[e]});
    edgePath_[e] = pathId, edgeNodes_[e] = 0;
  }
  for (int v : vertices) ++vertexPaths_[v];
  return Status::success();
}

void PathTracer::release(const std::vector<int>& vertices, int pathId) {
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    const int h = mesh_.findHalfedge(vertices[i], vertices[i + 1]);
    if (h < 0) continue;
    const int e = RefinedMesh::edgeOf(h);
    if (edgePath_[e] != pathId) continue;
    edgePath_[e] = -1;
    computeEdgeNodes(e);
  }
  for (int v : vertices) --vertexPaths_[v];
}

void PathTracer::rollback(const std::vector<int>& vertices, int pathId, const Checkpoint& cp) {
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    const int h = mesh_.findHalfedge(vertices[i], vertices[i + 1]);
    if (h >= 0 && edgePath_[RefinedMesh::edgeOf(h)] == pathId) edgePath_[RefinedMesh::edgeOf(h)] = -1;
  }
  for (int v : vertices) --vertexPaths_[v];
  // Latest first, so an edge changed twice ends with its oldest value; entries of edges the
  // splits created go with them.
  for (size_t k = journal_.size(); k-- > cp.journal;) {
    const NodeChange& c = journal_[k];
    if (c.edge < static_cast<int>(edgeNodes_.size())) edgeNodes_[c.edge] = c.nodes, slotBase_[c.edge] = c.base;
  }
  journal_.resize(cp.journal);
  mesh_.undoSplits(cp.splits);
  const size_t ne = mesh_.edgeCount(), nf = mesh_.faceCount(), nv = mesh_.vertexCount();
  edgeLabel_.resize(ne), edgePath_.resize(ne), edgeNodes_.resize(ne), slotBase_.resize(ne);
  faceLabel_.resize(nf);
  anchor_.resize(nv), vertexPaths_.resize(nv);
  slotEdge_.resize(cp.nodeSlots), slotPos_.resize(cp.nodeSlots);
}

}  // namespace cbd
