#include "cbd/layout.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <map>
#include <set>
#include <cstdint>
#include <tuple>

namespace cbd {

std::string anchorLabel(const std::vector<std::string>& names, int k) {
  if (k >= 0 && k < static_cast<int>(names.size())) return "'" + names[k] + "'";
  return std::to_string(k);
}

int Layout::multipleLinkages() const {
  std::map<std::pair<int, int>, int> count;
  for (const LayoutEdge& e : edges) ++count[std::minmax(e.a, e.b)];
  int n = 0;
  for (const auto& [k, c] : count) n += (c > 1);
  return n;
}

bool Region::isTriangle() const {
  if (loops.size() != 1 || eulerCharacteristic != 1 || !interiorAnchors.empty()) return false;
  const auto& c = loops[0].corners;
  return c.size() == 3 && c[0] != c[1] && c[1] != c[2] && c[0] != c[2];
}

namespace {
int nextBoundary(const RefinedMesh& m, const std::vector<int>& edgePath, int h) {
  int g = m.next(h);
  while (edgePath[RefinedMesh::edgeOf(g)] < 0) g = m.next(RefinedMesh::twin(g));
  return g;
}
}  // namespace

std::vector<int> cornerWedge(const RefinedMesh& m, const std::vector<int>& edgePath, int out) {
  // Rotate clockwise from the outgoing loop halfedge until the previous path halfedge.
  std::vector<int> faces;
  int g = out;
  for (;;) {
    faces.push_back(m.face(g));
    const int in = m.prev(g);  // ends at the corner, in the same face
    if (edgePath[RefinedMesh::edgeOf(in)] >= 0) break;
    g = RefinedMesh::twin(in);
    if (g == out) break;  // no path on this side (interior vertex)
  }
  return faces;
}

bool onPath(const RefinedMesh& m, const std::vector<int>& edgePath, int v) {
  const int start = m.outgoing(v);
  int h = start;
  do {
    if (edgePath[RefinedMesh::edgeOf(h)] >= 0) return true;
    h = m.rotateCCW(h);
  } while (h != start);
  return false;
}

namespace {

/// Everything about one region, given its faces: Euler characteristic of the region cut open
/// along its paths (V - E + F, one wedge corner per boundary halfedge), boundary loops with
/// their anchor corners and sides, anchors inside.
///
/// With `flood`, `faces` holds only the first face on entry: the flood fill that finds the rest
/// (across edges on no path) runs in the same pass and appends them, breadth first, so loops and
/// interior anchors come out in another order than from the same faces given in another order
/// (the signature does not depend on it).
Region describeRegion(const RefinedMesh& m, const std::vector<int>& edgePath, const std::vector<int>& anchorOf,
                      std::vector<int>& faces, RegionScratch& sc, bool flood = false) {
  sc.fit(m);
  Region reg;
  long long V = 0, E = 0;
  std::vector<int> boundary;
  if (flood) sc.faceMark[faces[0]] = sc.stamp;
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0, h = m.faceHalfedge(faces[i]); k < 3; ++k, h = m.next(h)) {
      if (edgePath[RefinedMesh::edgeOf(h)] >= 0) {
        boundary.push_back(h);
        ++E, ++V;
      } else {
        const int t = RefinedMesh::twin(h);
        if (h < t) ++E;  // an interior edge: both its halfedges are in the region, count it once
        if (flood && sc.faceMark[m.face(t)] != sc.stamp) sc.faceMark[m.face(t)] = sc.stamp, faces.push_back(m.face(t));
      }
      const int v = m.from(h);
      if (sc.vertexMark[v] == sc.stamp) continue;
      sc.vertexMark[v] = sc.stamp;
      if (onPath(m, edgePath, v)) continue;
      ++V;
      if (v < static_cast<int>(anchorOf.size()) && anchorOf[v] >= 0) reg.interiorAnchors.push_back(anchorOf[v]);
    }
  reg.faces = static_cast<int>(faces.size());
  reg.eulerCharacteristic = static_cast<int>(V - E + reg.faces);
  for (int h0 : boundary) {
    if (sc.halfedgeMark[h0] == sc.stamp) continue;
    RegionLoop loop;
    int h = h0;
    do {
      sc.halfedgeMark[h] = sc.stamp;
      loop.halfedges.push_back(h);
      h = nextBoundary(m, edgePath, h);
    } while (h != h0 && sc.halfedgeMark[h] != sc.stamp);
    for (int x : loop.halfedges) {
      const int v = m.from(x);
      if (v < static_cast<int>(anchorOf.size()) && anchorOf[v] >= 0) {
        loop.corners.push_back(anchorOf[v]);
        loop.cornerHalfedge.push_back(x);
        loop.sides.push_back(edgePath[RefinedMesh::edgeOf(x)]);
      }
    }
    reg.loops.push_back(std::move(loop));
  }
  return reg;
}

RegionSignature signatureOf(const Region& r, const std::vector<LayoutEdge>& edges) {
  RegionSignature s;
  s.euler = r.eulerCharacteristic;
  s.inside = r.interiorAnchors;
  std::sort(s.inside.begin(), s.inside.end());
  for (const RegionLoop& l : r.loops) {
    std::vector<std::pair<int, int>> ls;
    for (size_t k = 0; k < l.sides.size(); ++k) ls.emplace_back(l.sides[k], edges[l.sides[k]].a == l.corners[k] ? 1 : 0);
    std::rotate(ls.begin(), std::min_element(ls.begin(), ls.end()), ls.end());
    s.loops.push_back(ls);
  }
  std::sort(s.loops.begin(), s.loops.end());
  return s;
}

}  // namespace

void RegionScratch::fit(const RefinedMesh& m) {
  vertexMark.resize(m.vertexCount(), 0);
  halfedgeMark.resize(m.halfedgeCount(), 0);
  faceMark.resize(m.faceCount(), 0);
  ++stamp;
}

namespace {
/// Faces reachable from f0 across edges on no path, depth first, each labelled `id` in
/// `faceRegion` (which must hold -1 for them) and appended to `faces` in the order reached.
void floodFaces(const RefinedMesh& m, const std::vector<int>& edgePath, int f0, int id, std::vector<int>& faceRegion,
                std::vector<int>& faces, std::vector<int>& stack) {
  faces.assign(1, f0);
  faceRegion[f0] = id;
  stack.assign(1, f0);
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0, h = m.faceHalfedge(f); k < 3; ++k, h = m.next(h)) {
      if (edgePath[RefinedMesh::edgeOf(h)] >= 0) continue;
      const int g = m.face(RefinedMesh::twin(h));
      if (faceRegion[g] < 0) faceRegion[g] = id, faces.push_back(g), stack.push_back(g);
    }
  }
}
}  // namespace

int RegionMap::firstNonTriangle() const {
  int best = -1;
  for (size_t i = 0; i < regions.size(); ++i)
    if (!regions[i].isTriangle() && (best < 0 || firstFace[i] < firstFace[best])) best = static_cast<int>(i);
  return best;
}

RegionMap analyzeRegions(const RefinedMesh& m, const std::vector<int>& edgePath,
                         const std::vector<int>& anchorOfVertex) {
  RegionMap r;
  const int nf = m.faceCount();
  r.faceRegion.assign(nf, -1);
  std::vector<int> faces, stack;
  RegionScratch sc;
  for (int f0 = 0; f0 < nf; ++f0) {
    if (r.faceRegion[f0] >= 0) continue;
    floodFaces(m, edgePath, f0, static_cast<int>(r.regions.size()), r.faceRegion, faces, stack);
    r.firstFace.push_back(f0);
    r.regions.push_back(describeRegion(m, edgePath, anchorOfVertex, faces, sc));
  }
  return r;
}

void updateRegion(RegionMap& map, const RefinedMesh& m, const std::vector<int>& edgePath,
                  const std::vector<int>& anchorOfVertex, int region, RegionScratch& sc) {
  const int nf = m.faceCount();
  std::vector<int> todo;
  for (int f = 0; f < nf; ++f) {
    if (f < static_cast<int>(map.faceRegion.size()) && map.faceRegion[f] != region) continue;
    todo.push_back(f);  // ascending, so every piece is flooded from its lowest face
  }
  map.faceRegion.resize(nf, -1);
  for (int f : todo) map.faceRegion[f] = -1;
  std::vector<int> faces, stack;
  bool first = true;
  for (int f0 : todo) {
    if (map.faceRegion[f0] >= 0) continue;
    const int id = first ? region : static_cast<int>(map.regions.size());
    floodFaces(m, edgePath, f0, id, map.faceRegion, faces, stack);
    Region described = describeRegion(m, edgePath, anchorOfVertex, faces, sc);
    if (first) {
      map.regions[id] = std::move(described);
      map.firstFace[id] = f0;
    } else {
      map.regions.push_back(std::move(described));
      map.firstFace.push_back(f0);
    }
    first = false;
  }
}

Region regionAt(const RefinedMesh& m, const std::vector<int>& edgePath, const std::vector<int>& anchorOf, int f0,
                RegionScratch& sc, std::vector<int>& faces) {
  faces.assign(1, f0);
  return describeRegion(m, edgePath, anchorOf, faces, sc, true);
}

std::vector<RegionSignature> regionSignaturesAt(const RefinedMesh& m, const std::vector<int>& edgePath,
                                                const std::vector<int>& anchorOf, const std::vector<LayoutEdge>& edges,
                                                const std::vector<int>& seedFaces, RegionScratch& sc,
                                                std::vector<std::vector<int>>* regionFaces) {
  std::vector<RegionSignature> out;
  if (regionFaces) regionFaces->clear();
  sc.fit(m);
  const uint32_t first = sc.stamp + 1;  // faces of this call's regions carry stamps from here on
  std::vector<int> faces;
  for (int f : seedFaces) {
    if (sc.faceMark[f] >= first) continue;
    out.push_back(signatureOf(regionAt(m, edgePath, anchorOf, f, sc, faces), edges));
    if (regionFaces) regionFaces->push_back(std::move(faces));
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool RegionSignature::operator<(const RegionSignature& o) const {
  return std::tie(euler, inside, loops) < std::tie(o.euler, o.inside, o.loops);
}
bool RegionSignature::operator==(const RegionSignature& o) const {
  return euler == o.euler && inside == o.inside && loops == o.loops;
}

std::vector<RegionSignature> regionSignatures(const RefinedMesh& mesh, const std::vector<int>& edgePath,
                                              const std::vector<int>& anchorOf, const std::vector<LayoutEdge>& edges) {
  const RegionMap rm = analyzeRegions(mesh, edgePath, anchorOf);
  std::vector<RegionSignature> out;
  for (const Region& r : rm.regions) out.push_back(signatureOf(r, edges));
  std::sort(out.begin(), out.end());
  return out;
}

RegionTracker::RegionTracker(const RefinedMesh& m, const std::vector<int>& edgePath,
                             const std::vector<int>& anchorOf, const std::vector<LayoutEdge>& edges)
    : mesh_(m), edgePath_(edgePath), anchorOf_(anchorOf), edges_(edges), label_(m.faceCount(), -1) {
  std::vector<int> faces;
  for (int f = 0; f < m.faceCount(); ++f) {
    if (label_[f] >= 0) continue;
    const Region r = regionAt(m, edgePath, anchorOf, f, scratch_, faces);
    for (int g : faces) label_[g] = static_cast<int>(sig_.size());
    sig_.push_back(signatureOf(r, edges));
  }
}

/// The boundary loop through halfedge h as (side, direction) at its corners, rotated to its
/// smallest entry as in a signature; sawTwin: whether it runs through halfedge twinOf too.
std::vector<std::pair<int, int>> RegionTracker::loopFrom(int h0, bool& sawTwin, int twinOf) const {
  std::vector<std::pair<int, int>> loop;
  sawTwin = false;
  int h = h0;
  do {
    if (h == twinOf) sawTwin = true;
    const int v = mesh_.from(h);
    if (v < static_cast<int>(anchorOf_.size()) && anchorOf_[v] >= 0) {
      const int side = edgePath_[RefinedMesh::edgeOf(h)];
      loop.emplace_back(side, edges_[side].a == anchorOf_[v] ? 1 : 0);
    }
    h = nextBoundary(mesh_, edgePath_, h);
  } while (h != h0);
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

std::vector<RegionSignature> RegionTracker::add(const std::vector<int>& chain, int region) {
  label_.resize(mesh_.faceCount(), region);  // faces from splits
  Undo u;
  u.region = region;
  u.before = sig_[region];
  const RegionSignature& old = u.before;
  const int hl = mesh_.findHalfedge(chain[0], chain[1]), hr = RefinedMesh::twin(hl);
  const int a = anchorOf_[chain.front()], b = anchorOf_[chain.back()];

  // Entries of new loops; old loops sharing one were touched by the path and are replaced.
  auto untouched = [&](const std::vector<std::vector<std::pair<int, int>>>& fresh) {
    std::vector<std::pair<int, int>> seen;
    for (const auto& l : fresh) seen.insert(seen.end(), l.begin(), l.end());
    std::sort(seen.begin(), seen.end());
    std::vector<std::vector<std::pair<int, int>>> keep;
    for (const auto& l : old.loops) {
      bool touched = false;
      for (const auto& x : l) touched = touched || std::binary_search(seen.begin(), seen.end(), x);
      if (!touched) keep.push_back(l);
    }
    return keep;
  };
  auto without = [](std::vector<int> v, const std::vector<int>& drop) {
    v.erase(std::remove_if(v.begin(), v.end(), [&](int x) { return std::find(drop.begin(), drop.end(), x) != drop.end(); }), v.end());
    return v;
  };
  // Endpoints that were inside the region: each one turns the Euler characteristic by -1
  // (cutting a path of k edges in adds 1 - that many).
  int insideEnds = 0;
  for (int x : {a, b})
    if (std::find(old.inside.begin(), old.inside.end(), x) != old.inside.end()) ++insideEnds;
  if (a == b) insideEnds = std::min(insideEnds, 1);

  bool twinOnLeft = false, dummy = false;
  std::vector<std::pair<int, int>> left = loopFrom(hl, twinOnLeft, hr);
  auto joined = [&](std::vector<std::vector<std::pair<int, int>>> fresh) {
    RegionSignature s;
    s.euler = old.euler + 1 - insideEnds;
    s.inside = without(old.inside, {a, b});
    s.loops = untouched(fresh);
    s.loops.insert(s.loops.end(), fresh.begin(), fresh.end());
    std::sort(s.loops.begin(), s.loops.end());
    return s;
  };
  if (twinOnLeft) {  // one loop runs along both sides: the region stays in one piece
    sig_[region] = joined({left});
    undo_.push_back(std::move(u));
    return {sig_[region]};
  }
  std::vector<std::pair<int, int>> right = loopFrom(hr, dummy, -1);
  // Two loops: a split, unless the sides meet around a handle. Flood both in lockstep.
  side_.resize(mesh_.faceCount(), 0);
  ++round_;
  const uint32_t mark[2] = {2 * round_, 2 * round_ + 1};
  std::vector<int> queue[2] = {{mesh_.face(hl)}, {mesh_.face(hr)}};
  size_t head[2] = {0, 0};
  side_[queue[0][0]] = mark[0];
  side_[queue[1][0]] = mark[1];
  int complete = -1;
  bool met = queue[0][0] == queue[1][0];
  while (!met && complete < 0) {
    for (int s = 0; s < 2 && !met && complete < 0; ++s) {
      if (head[s] == queue[s].size()) {
        complete = s;
        break;
      }
      const int f = queue[s][head[s]++];
      for (int k = 0, h = mesh_.faceHalfedge(f); k < 3; ++k, h = mesh_.next(h)) {
        if (edgePath_[RefinedMesh::edgeOf(h)] >= 0) continue;
        const int g = mesh_.face(RefinedMesh::twin(h));
        if (side_[g] == mark[1 - s]) {
          met = true;
          break;
        }
        if (side_[g] != mark[s]) side_[g] = mark[s], queue[s].push_back(g);
      }
    }
  }
  if (met) {  // across a handle: still one region, with one loop more
    sig_[region] = joined({left, right});
    undo_.push_back(std::move(u));
    return {sig_[region]};
  }
  // The side `complete` is cut off, its faces all in its queue: describe it, and the rest from
  // what changed.
  std::vector<int>& faces = queue[complete];
  const RegionSignature small = signatureOf(describeRegion(mesh_, edgePath_, anchorOf_, faces, scratch_), edges_);
  const std::vector<std::pair<int, int>>& bigLoop = complete == 0 ? right : left;
  RegionSignature big;
  big.euler = old.euler + 1 - insideEnds - small.euler;
  big.inside = without(without(old.inside, {a, b}), small.inside);
  std::vector<std::vector<std::pair<int, int>>> fresh = small.loops;
  fresh.push_back(bigLoop);
  big.loops = untouched(fresh);
  big.loops.push_back(bigLoop);
  std::sort(big.loops.begin(), big.loops.end());
  u.split = static_cast<int>(sig_.size());
  for (int f : faces) label_[f] = u.split;
  u.moved = std::move(faces);
  sig_[region] = big;
  sig_.push_back(small);
  undo_.push_back(std::move(u));
  std::vector<RegionSignature> out{small, big};
  std::sort(out.begin(), out.end());
  return out;
}

void RegionTracker::undo() {
  Undo& u = undo_.back();
  sig_[u.region] = std::move(u.before);
  if (u.split >= 0) {
    for (int f : u.moved) label_[f] = u.region;
    sig_.pop_back();
  }
  undo_.pop_back();
  // Faces the mesh no longer has (a path rolled back with its splits) lose their labels.
  label_.resize(std::min(label_.size(), static_cast<size_t>(mesh_.faceCount())));
}

double chainLength(const RefinedMesh& m, const std::vector<int>& chain) {
  double len = 0;
  for (size_t k = 1; k < chain.size(); ++k) len += (m.position(chain[k]) - m.position(chain[k - 1])).norm();
  return len;
}

std::vector<double> chainFractions(const RefinedMesh& m, const std::vector<int>& chain) {
  std::vector<double> acc(chain.size(), 0.0);
  for (size_t k = 1; k < chain.size(); ++k) acc[k] = acc[k - 1] + (m.position(chain[k]) - m.position(chain[k - 1])).norm();
  const double total = acc.empty() ? 0.0 : acc.back();
  for (size_t k = 0; k < chain.size(); ++k)
    acc[k] = total > 0 ? acc[k] / total : static_cast<double>(k) / static_cast<double>(std::max<size_t>(1, chain.size() - 1));
  return acc;
}

int leavingHalfedge(const RefinedMesh& m, const std::vector<int>& chain, int v) {
  if (chain.front() == v) return m.findHalfedge(chain[0], chain[1]);
  return m.findHalfedge(chain.back(), chain[chain.size() - 2]);
}

std::vector<int> rotationAt(const RefinedMesh& m, const std::vector<int>& edgePath, int v) {
  std::vector<int> out;
  const int start = m.outgoing(v);
  if (start < 0) return out;
  int h = start;
  do {
    const int p = edgePath[RefinedMesh::edgeOf(h)];
    if (p >= 0) out.push_back(p);
    h = m.rotateCCW(h);
  } while (h != start);
  return out;
}

namespace {
/// Per input face, the label of its largest refined sub-face.
std::vector<int> labelOfInputFaces(const RefinedMesh& m, const std::vector<int>& label) {
  std::vector<int> out(m.inputFaceCount(), -1);
  if (label.empty()) return out;
  // The area of each label within each input face (a face crossed by paths is split among a few).
  std::vector<std::vector<std::pair<int, double>>> area(m.inputFaceCount());
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto v = m.faceVertices(f);
    const double a = (m.position(v[1]) - m.position(v[0])).cross(m.position(v[2]) - m.position(v[0])).norm();
    auto& parts = area[m.inputFace(f)];
    auto it = std::find_if(parts.begin(), parts.end(), [&](const auto& x) { return x.first == label[f]; });
    if (it == parts.end()) parts.emplace_back(label[f], a);
    else it->second += a;
  }
  for (size_t in = 0; in < area.size(); ++in) {
    double best = -1.0;
    for (const auto& [l, a] : area[in])
      if (a > best) best = a, out[in] = l;
  }
  return out;
}
}  // namespace

std::vector<int> inputFacePatch(const Layout& layout) { return labelOfInputFaces(layout.mesh, layout.facePatch); }

std::vector<int> inputFaceCluster(const Layout& layout) { return labelOfInputFaces(layout.mesh, layout.faceCluster); }

int RegionDistances::deepest() const {
  int best = -1;
  for (size_t k = 0; k < vertices.size(); ++k)
    if (best < 0 || toBoundary[k] > toBoundary[best]) best = static_cast<int>(k);
  return best;
}

std::vector<int> matchingRegionVertices(const RegionDistances& source, int s, const RegionDistances& target,
                                        int count) {
  const auto at = std::find(source.vertices.begin(), source.vertices.end(), s);
  if (at == source.vertices.end() || target.vertices.empty() || source.sides != target.sides || count < 1) return {};
  const size_t k = static_cast<size_t>(at - source.vertices.begin());
  const double depthS = source.toBoundary[static_cast<size_t>(source.deepest())];
  const double depthT = target.toBoundary[static_cast<size_t>(target.deepest())];
  std::vector<std::pair<double, int>> cost(target.vertices.size());
  for (size_t v = 0; v < target.vertices.size(); ++v) {
    double c = 0;
    for (size_t j = 0; j < source.sides.size(); ++j) {
      const double x = source.toSide[k][j] / depthS, y = target.toSide[v][j] / depthT;
      c += std::isfinite(x) && std::isfinite(y) ? (x - y) * (x - y) : std::isfinite(x) || std::isfinite(y) ? 1e6 : 0.0;
    }
    cost[v] = {c, target.vertices[v]};
  }
  const size_t n = std::min(cost.size(), static_cast<size_t>(count));
  std::partial_sort(cost.begin(), cost.begin() + static_cast<std::ptrdiff_t>(n), cost.end());
  std::vector<int> best(n);
  for (size_t i = 0; i < n; ++i) best[i] = cost[i].second;
  return best;
}

bool regionDistances(const Layout& layout, const RegionSignature& region, RegionDistances& out) {
  out = RegionDistances{};
  const RefinedMesh& m = layout.mesh;
  std::vector<int> anchorOf(m.vertexCount(), -1);
  for (int i = 0; i < layout.anchorCount(); ++i) anchorOf[layout.anchorVertices[i]] = i;
  const RegionMap rm = analyzeRegions(m, layout.edgePath, anchorOf);
  RegionScratch scratch;
  std::vector<std::vector<int>> faces;
  for (size_t i = 0; i < rm.regions.size(); ++i) {
    const auto sig = regionSignaturesAt(m, layout.edgePath, anchorOf, layout.edges, {rm.firstFace[i]}, scratch, &faces);
    if (sig.size() != 1 || !(sig[0] == region)) continue;
    std::vector<char> inside(m.vertexCount(), 0), onBoundary(m.vertexCount(), 0);
    std::vector<int> boundary;
    for (int f : faces[0])
      for (int v : m.faceVertices(f)) {
        if (inside[v]) continue;
        inside[v] = 1;
        if (anchorOf[v] >= 0 || onPath(m, layout.edgePath, v)) boundary.push_back(v), onBoundary[v] = 1;
      }
    for (const auto& loop : region.loops)
      for (const auto& [edge, direction] : loop)
        if (std::find(out.sides.begin(), out.sides.end(), edge) == out.sides.end()) out.sides.push_back(edge);
    // Dijkstra from `sources` over the region's edges (a boundary vertex is reached, never left
    // but as a source, so no distance runs through another region).
    constexpr double inf = std::numeric_limits<double>::infinity();
    auto distances = [&](const std::vector<int>& sources) {
      std::vector<double> dist(m.vertexCount(), inf);
      using Item = std::pair<double, int>;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      for (int v : sources) dist[v] = 0, queue.push({0.0, v});
      while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > dist[v] || (d > 0 && onBoundary[v])) continue;
        const int start = m.outgoing(v);
        int h = start;
        do {
          const int w = m.to(h);
          const double dw = d + m.edgeLength(RefinedMesh::edgeOf(h));
          if (inside[w] && dw < dist[w]) dist[w] = dw, queue.push({dw, w});
          h = m.rotateCCW(h);
        } while (h != start);
      }
      return dist;
    };
    const std::vector<double> toBoundary = distances(boundary);
    std::vector<std::vector<double>> toSide;
    for (int e : out.sides) toSide.push_back(distances(layout.edges[e].vertices));
    for (int v = 0; v < m.inputVertexCount(); ++v) {
      if (!inside[v] || !(toBoundary[v] > 0) || toBoundary[v] == inf) continue;
      out.vertices.push_back(v);
      out.toBoundary.push_back(toBoundary[v]);
      std::vector<double> d;
      for (const auto& side : toSide) d.push_back(side[v]);
      out.toSide.push_back(std::move(d));
    }
    return true;
  }
  return false;
}

Status assemblePatches(Layout& layout) {
  const RefinedMesh& m = layout.mesh;
  std::vector<int> anchorOf(m.vertexCount(), -1);
  for (int i = 0; i < layout.anchorCount(); ++i) anchorOf[layout.anchorVertices[i]] = i;
  RegionMap rm = analyzeRegions(m, layout.edgePath, anchorOf);
  layout.patches.clear();
  for (size_t i = 0; i < rm.regions.size(); ++i) {
    const Region& reg = rm.regions[i];
    if (!reg.isTriangle()) {
      return Status::error(ErrorCode::InternalError, "region " + std::to_string(i) + " is not a triangular patch");
    }
    Patch p;
    const RegionLoop& loop = reg.loops[0];
    for (int k = 0; k < 3; ++k) {
      p.corners[k] = loop.corners[k];
      p.edges[k] = loop.sides[k];
      const LayoutEdge& e = layout.edges[p.edges[k]];
      p.forward[k] = (e.a == loop.corners[k]);
    }
    p.faces = reg.faces;
    layout.patches.push_back(p);
  }
  layout.facePatch = rm.faceRegion;
  layout.rotation.assign(layout.anchorCount(), {});
  for (int i = 0; i < layout.anchorCount(); ++i) layout.rotation[i] = rotationAt(m, layout.edgePath, layout.anchorVertices[i]);
  return Status::success();
}

double lengthDetour(const Layout& source, const Layout& target) {
  std::vector<double> ratio;
  for (size_t e = 0; e < source.edges.size() && e < target.edges.size(); ++e)
    if (source.edges[e].length > 0 && target.edges[e].length > 0) ratio.push_back(target.edges[e].length / source.edges[e].length);
  if (ratio.empty()) return 1.0;
  std::vector<double> sorted = ratio;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  double sum = 0;
  for (double x : ratio) sum += std::max(x / median, median / x);
  return sum / static_cast<double>(ratio.size());
}

LayoutCheck validateLayout(const Layout& layout, int expectedEuler) {
  LayoutCheck c;
  auto fail = [&](const std::string& what) {
    c.status = Status::error(ErrorCode::InternalError, "invalid layout: " + what);
    return c;
  };
  const RefinedMesh& m = layout.mesh;
  const int V = layout.anchorCount(), E = static_cast<int>(layout.edges.size()),
            F = static_cast<int>(layout.patches.size());
  c.eulerCharacteristic = V - E + F;
  if (c.eulerCharacteristic != expectedEuler)
    return fail("V - E + F = " + std::to_string(V) + " - " + std::to_string(E) + " + " + std::to_string(F) +
                " = " + std::to_string(c.eulerCharacteristic) + ", the surface has " + std::to_string(expectedEuler));
  if (static_cast<int>(layout.edgePath.size()) != m.edgeCount()) return fail("edgePath size");
  std::vector<int> anchorOf(m.vertexCount(), -1);
  for (int i = 0; i < V; ++i) {
    const int v = layout.anchorVertices[i];
    if (v < 0 || v >= m.vertexCount()) return fail("anchor " + std::to_string(i) + " is no vertex of the mesh");
    if (anchorOf[v] >= 0) return fail("anchors " + std::to_string(anchorOf[v]) + " and " + std::to_string(i) + " share a vertex");
    anchorOf[v] = i;
  }
  for (int e = 0; e < m.edgeCount(); ++e)
    if (layout.edgePath[e] < -1 || layout.edgePath[e] >= E) return fail("mesh edge " + std::to_string(e) + " names no path");
  // Paths: simple edge chains between their anchors, sharing no vertex but end anchors.
  std::vector<int> owner(m.vertexCount(), -1);
  std::vector<int> edgeCount(E, 0);
  for (int e = 0; e < m.edgeCount(); ++e)
    if (layout.edgePath[e] >= 0) ++edgeCount[layout.edgePath[e]];
  for (int p = 0; p < E; ++p) {
    const LayoutEdge& le = layout.edges[p];
    const std::string name = "edge " + std::to_string(p) + " (" + std::to_string(le.a) + "-" + std::to_string(le.b) + ")";
    if (le.a < 0 || le.a >= V || le.b < 0 || le.b >= V) return fail(name + " ends at no anchor");
    if (le.a == le.b) return fail(name + " is a loop");
    if (le.vertices.size() < 2 || le.vertices.front() != layout.anchorVertices[le.a] ||
        le.vertices.back() != layout.anchorVertices[le.b])
      return fail(name + " does not run between its anchors");
    if (static_cast<int>(le.vertices.size()) - 1 != edgeCount[p]) return fail(name + " owns other mesh edges");
    for (size_t k = 0; k < le.vertices.size(); ++k) {
      const int v = le.vertices[k];
      if (k + 1 < le.vertices.size()) {
        const int h = m.findHalfedge(v, le.vertices[k + 1]);
        if (h < 0 || layout.edgePath[RefinedMesh::edgeOf(h)] != p) return fail(name + " is not a chain of its mesh edges");
      }
      if (k == 0 || k + 1 == le.vertices.size()) continue;
      if (anchorOf[v] >= 0) return fail(name + " passes through anchor " + std::to_string(anchorOf[v]));
      if (owner[v] >= 0) return fail(name + " meets edge " + std::to_string(owner[v]) + " at vertex " + std::to_string(v));
      owner[v] = p;
    }
  }
  // Patches: triangles; each layout edge on two patch sides, once in each direction.
  RegionMap rm = analyzeRegions(m, layout.edgePath, anchorOf);
  if (static_cast<int>(rm.regions.size()) != F) return fail("the paths cut the surface into " +
                                                            std::to_string(rm.regions.size()) + " regions, not " + std::to_string(F));
  std::vector<int> fwd(E, 0), bwd(E, 0);
  for (size_t i = 0; i < rm.regions.size(); ++i) {
    if (!rm.regions[i].isTriangle()) return fail("region " + std::to_string(i) + " is not a disk with three anchor corners");
    for (int k = 0; k < 3; ++k) {
      const int p = rm.regions[i].loops[0].sides[k];
      (layout.edges[p].a == rm.regions[i].loops[0].corners[k] ? fwd : bwd)[p]++;
    }
  }
  for (int p = 0; p < E; ++p)
    if (fwd[p] != 1 || bwd[p] != 1) return fail("edge " + std::to_string(p) + " is not on exactly two patch sides");
  // Face labels: every region's faces carry one patch, a different one per region, whose corners
  // and sides are the region's boundary loop (up to where it starts) and whose face count is the
  // region's.
  if (static_cast<int>(layout.facePatch.size()) != m.faceCount()) return fail("facePatch size");
  std::vector<int> patchOfRegion(rm.regions.size(), -1), regionOfPatch(F, -1);
  for (int f = 0; f < m.faceCount(); ++f) {
    const int r = rm.faceRegion[f], p = layout.facePatch[f];
    if (p < 0 || p >= F) return fail("face " + std::to_string(f) + " has no patch");
    if (patchOfRegion[r] < 0) {
      if (regionOfPatch[p] >= 0) return fail("patch " + std::to_string(p) + " spans two regions");
      patchOfRegion[r] = p, regionOfPatch[p] = r;
    } else if (patchOfRegion[r] != p) {
      return fail("region " + std::to_string(r) + " holds faces of patches " + std::to_string(patchOfRegion[r]) +
                  " and " + std::to_string(p));
    }
  }
  for (size_t i = 0; i < rm.regions.size(); ++i) {
    const Patch& P = layout.patches[patchOfRegion[i]];
    const RegionLoop& loop = rm.regions[i].loops[0];
    bool same = false;
    for (int shift = 0; shift < 3 && !same; ++shift) {
      same = true;
      for (int k = 0; k < 3; ++k)
        same = same && P.corners[(k + shift) % 3] == loop.corners[k] && P.edges[(k + shift) % 3] == loop.sides[k];
    }
    if (!same) return fail("patch " + std::to_string(patchOfRegion[i]) + " does not match the region its faces form");
    for (int k = 0; k < 3; ++k)
      if (P.forward[k] != (layout.edges[P.edges[k]].a == P.corners[k]))
        return fail("patch " + std::to_string(patchOfRegion[i]) + " has side " + std::to_string(k) + " in the wrong direction");
    if (P.faces != rm.regions[i].faces) return fail("patch " + std::to_string(patchOfRegion[i]) + " miscounts its faces");
  }
  // Rotation system: at each patch corner, the incoming and outgoing sides are consecutive
  // (outgoing, then incoming, counter-clockwise) in the anchor's rotation.
  if (static_cast<int>(layout.rotation.size()) != V) return fail("rotation system size");
  // Each anchor's rotation lists exactly the path ends there, each once.
  std::vector<int> ends(V, 0);
  for (const LayoutEdge& le : layout.edges) ++ends[le.a], ++ends[le.b];
  for (int a = 0; a < V; ++a)
    if (static_cast<int>(layout.rotation[a].size()) != ends[a])
      return fail("rotation at anchor " + std::to_string(a) + " lists " + std::to_string(layout.rotation[a].size()) +
                  " path ends, the paths have " + std::to_string(ends[a]));
  for (const Patch& p : layout.patches) {
    for (int k = 0; k < 3; ++k) {
      const int a = p.corners[k];
      const int out = p.edges[k], in = p.edges[(k + 2) % 3];
      const auto& rot = layout.rotation[a];
      bool found = false;
      for (size_t s = 0; s < rot.size() && !found; ++s)
        found = rot[s] == out && rot[(s + 1) % rot.size()] == in;
      if (!found) return fail("rotation at anchor " + std::to_string(a) + " disagrees with a patch");
    }
  }
  return c;
}

}  // namespace cbd
