#include "cbd/base_domain.h"

#include <algorithm>
#include <cmath>

namespace cbd {
namespace {

constexpr double kHalfSqrt3 = 0.86602540378443864676;

/// Lattice coordinates (a, b) turned by 60 degrees: (1, 0) -> (0, 1), (0, 1) -> (-1, 1).
std::array<int, 2> turn(int a, int b, int steps) {
  for (int i = 0; i < ((steps % 6) + 6) % 6; ++i) {
    const int na = -b, nb = a + b;
    a = na, b = nb;
  }
  return {a, b};
}

/// Corner k of the domain triangle in lattice coordinates.
std::array<int, 2> cornerLattice(int k) {
  static const int c[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  return {c[k % 3][0], c[k % 3][1]};
}

}  // namespace

Eigen::Matrix2d ChartMap::linear() const {
  static const double c[6] = {1.0, 0.5, -0.5, -1.0, -0.5, 0.5};
  static const double s[6] = {0.0, kHalfSqrt3, kHalfSqrt3, 0.0, -kHalfSqrt3, -kHalfSqrt3};
  Eigen::Matrix2d m;
  m << c[rot], -s[rot], s[rot], c[rot];
  return m;
}

Vec2 ChartMap::translation() const { return Vec2(a + 0.5 * b, kHalfSqrt3 * b); }

ChartMap ChartMap::operator*(const ChartMap& o) const {
  const auto t = turn(o.a, o.b, rot);
  return {(rot + o.rot) % 6, t[0] + a, t[1] + b};
}

ChartMap ChartMap::inverse() const {
  const int r = (6 - rot) % 6;
  const auto t = turn(a, b, r);
  return {r, -t[0], -t[1]};
}

double insideSide(const Vec2& uv, int k) {
  switch (k) {
    case 0: return uv.y();
    case 1: return -kHalfSqrt3 * (uv.x() - 1.0) - 0.5 * uv.y();
    default: return kHalfSqrt3 * uv.x() - 0.5 * uv.y();
  }
}

BaseDomain::BaseDomain(const Layout& L) {
  const int np = static_cast<int>(L.patches.size());
  next_.assign(np, {-1, -1, -1});
  across_.assign(np, {});
  edge_.assign(np, {-1, -1, -1});
  std::vector<std::vector<std::pair<int, int>>> sides(L.edges.size());
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < 3; ++k) {
      edge_[p][k] = L.patches[p].edges[k];
      sides[L.patches[p].edges[k]].emplace_back(p, k);
    }
  for (const auto& s : sides) {
    if (s.size() != 2) continue;  // validateLayout rules this out
    for (int i = 0; i < 2; ++i) {
      const auto [p, k] = s[i];
      const auto [q, j] = s[1 - i];
      // Side k of p runs corner k -> k+1; the same path is side j of q the other way round:
      // corner k of p goes to corner j+1 of q, corner k+1 to corner j.
      ChartMap m;
      m.rot = ((2 * j + 3 - 2 * k) % 6 + 6) % 6;
      const auto from = turn(cornerLattice(k)[0], cornerLattice(k)[1], m.rot);
      m.a = cornerLattice(j + 1)[0] - from[0];
      m.b = cornerLattice(j + 1)[1] - from[1];
      next_[p][k] = q;
      across_[p][k] = m;
    }
  }
}

int BaseDomain::sideOf(int p, int e, int q) const {
  for (int k = 0; k < 3; ++k)
    if (edge_[p][k] == e && next_[p][k] == q) return k;
  return -1;
}

double BaseDomain::area() const { return patchCount() * 0.5 * kHalfSqrt3; }

bool BaseDomain::walk(DomainPoint& pt, Vec2 d, ChartMap* toStart) const {
  // A point within rounding of a side counts as inside: no walk ping-pongs across a side it ends on.
  constexpr double eps = 1e-14;
  ChartMap acc;
  const int limit = 8 * patchCount() + 64;
  for (int step = 0; step < limit; ++step) {
    const Vec2 end = pt.uv + d;
    double first = 2.0;
    int side = -1;
    for (int k = 0; k < 3; ++k) {
      const double s1 = insideSide(end, k);
      if (s1 >= -eps) continue;
      const double s0 = insideSide(pt.uv, k);
      const double t = s0 <= 0 ? 0.0 : s0 / (s0 - s1);
      if (t < first) first = t, side = k;
    }
    if (side < 0) {
      pt.uv = end;
      if (toStart) *toStart = acc;
      return true;
    }
    const ChartMap& m = across_[pt.patch][side];
    pt.uv = m.apply(pt.uv + first * d);
    d = m.linear() * ((1.0 - first) * d);
    acc = acc * m.inverse();
    pt.patch = next_[pt.patch][side];
  }
  return false;
}

SurfaceInDomain::SurfaceInDomain(const Layout& L, const PatchParameterization& P, const BaseDomain& D)
    : layout_(L), param_(P), domain_(D), locator_(L, P) {
  const RefinedMesh& m = L.mesh;
  vertexFace_.assign(m.vertexCount(), -1);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (m.outgoing(v) >= 0) vertexFace_[v] = m.face(m.outgoing(v));
  vertexPath_.assign(m.vertexCount(), -1);
  for (size_t e = 0; e < L.edges.size(); ++e) {
    const auto& c = L.edges[e].vertices;
    for (size_t k = 1; k + 1 < c.size(); ++k) vertexPath_[c[k]] = static_cast<int>(e);
  }
  childBegin_.assign(m.inputFaceCount() + 1, 0);
  for (int g = 0; g < m.faceCount(); ++g) ++childBegin_[m.inputFace(g) + 1];
  for (int f = 0; f < m.inputFaceCount(); ++f) childBegin_[f + 1] += childBegin_[f];
  child_.resize(m.faceCount());
  std::vector<int> fill(childBegin_.begin(), childBegin_.end() - 1);
  for (int g = 0; g < m.faceCount(); ++g) child_[fill[m.inputFace(g)]++] = g;
  std::vector<double> areaD(m.vertexCount(), 0.0);
  density_.assign(m.vertexCount(), 0.0);
  for (int g = 0; g < m.faceCount(); ++g) {
    const auto tv = m.faceVertices(g);
    const auto& uv = P.cornerUV[g];
    const double a3 = 0.5 * (m.position(tv[1]) - m.position(tv[0])).cross(m.position(tv[2]) - m.position(tv[0])).norm();
    const Vec2 e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
    const double a2 = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
    for (int w : tv) density_[w] += a3, areaD[w] += a2;
  }
  for (int w = 0; w < m.vertexCount(); ++w) density_[w] = areaD[w] > 0 ? density_[w] / areaD[w] : 0.0;
}

bool SurfaceInDomain::locate(const DomainPoint& p, Hit& hit) const {
  int g = -1;
  Vec3 b;
  if (p.patch < 0 || !locator_.locate(p.patch, p.uv, g, b)) return false;
  const RefinedMesh& m = layout_.mesh;
  const auto tv = m.faceVertices(g);
  const auto& uv = param_.cornerUV[g];
  hit.position = b[0] * m.position(tv[0]) + b[1] * m.position(tv[1]) + b[2] * m.position(tv[2]);
  hit.point.face = m.inputFace(g);
  hit.edgeCloseness = b.minCoeff();
  hit.point.bary.setZero();
  for (int k = 0; k < 3; ++k) hit.point.bary += b[k] * m.baryIn(tv[k], hit.point.face);
  Eigen::Matrix<double, 3, 2> E;
  E << m.position(tv[1]) - m.position(tv[0]), m.position(tv[2]) - m.position(tv[0]);
  Eigen::Matrix2d U;
  U << uv[1] - uv[0], uv[2] - uv[0];
  const Eigen::Matrix2d Ui = U.inverse();  // rows: the gradients of b1, b2 in uv
  hit.jacobian = E * Ui;
  hit.density = b[0] * density_[tv[0]] + b[1] * density_[tv[1]] + b[2] * density_[tv[2]];
  hit.densitySlope = Ui.transpose() * Vec2(density_[tv[1]] - density_[tv[0]], density_[tv[2]] - density_[tv[0]]);
  return true;
}

DomainPoint SurfaceInDomain::vertexPoint(int v) const {
  DomainPoint p;
  const int g = vertexFace_[v];
  if (g < 0) return p;
  const auto tv = layout_.mesh.faceVertices(g);
  const int c = static_cast<int>(std::find(tv.begin(), tv.end(), v) - tv.begin());
  p.patch = layout_.facePatch[g];
  p.uv = param_.cornerUV[g][c];
  return p;
}

bool SurfaceInDomain::toDomain(const FacePoint& p, DomainPoint& out) const {
  if (p.face < 0 || p.face >= static_cast<int>(childBegin_.size()) - 1) return false;
  const RefinedMesh& m = layout_.mesh;
  double best = -1e300;
  for (int i = childBegin_[p.face]; i < childBegin_[p.face + 1]; ++i) {
    const int g = child_[i];
    const auto tv = m.faceVertices(g);
    // The child's corners in the input face's barycentric coordinates; solve for the point's
    // coordinates in the child (two equations suffice: all three sum to one).
    const Vec3 b0 = m.baryIn(tv[0], p.face), b1 = m.baryIn(tv[1], p.face), b2 = m.baryIn(tv[2], p.face);
    Eigen::Matrix2d A;
    A << b1[1] - b0[1], b2[1] - b0[1], b1[2] - b0[2], b2[2] - b0[2];
    if (std::abs(A.determinant()) < 1e-300) continue;
    const Vec2 l = A.inverse() * Vec2(p.bary[1] - b0[1], p.bary[2] - b0[2]);
    const Vec3 lam(1.0 - l[0] - l[1], l[0], l[1]);
    if (lam.minCoeff() <= best) continue;
    best = lam.minCoeff();
    const auto& uv = param_.cornerUV[g];
    out.patch = layout_.facePatch[g];
    out.uv = lam[0] * uv[0] + lam[1] * uv[1] + lam[2] * uv[2];
  }
  return best > -1e-6;
}

std::vector<std::array<ChartMap, 3>> SurfaceInDomain::faceCharts() const {
  const RefinedMesh& m = layout_.mesh;
  std::vector<std::array<ChartMap, 3>> out(m.faceCount());
  for (int g = 0; g < m.faceCount(); ++g) {
    const auto tv = m.faceVertices(g);
    for (int k = 0; k < 3; ++k) out[g][k] = transitionAt(tv[k], vertexPoint(tv[k]).patch, layout_.facePatch[g]);
  }
  return out;
}

ChartMap SurfaceInDomain::transitionAt(int v, int from, int to) const {
  if (from == to) return {};
  if (vertexPath_[v] >= 0) {
    const int k = domain_.sideOf(from, vertexPath_[v], to);
    return k >= 0 ? domain_.across(from, k) : ChartMap{};
  }
  // An anchor: a corner of both triangles; it never moves, so the translation that takes one
  // corner onto the other is the map.
  int cf = 0, ct = 0;
  for (int k = 0; k < 3; ++k) {
    if (layout_.anchorVertices[layout_.patches[from].corners[k]] == v) cf = k;
    if (layout_.anchorVertices[layout_.patches[to].corners[k]] == v) ct = k;
  }
  return {0, cornerLattice(ct)[0] - cornerLattice(cf)[0], cornerLattice(ct)[1] - cornerLattice(cf)[1]};
}

namespace {

/// Barycentric coordinates of p in triangle t (a very negative triple for a degenerate t).
Vec3 barycentric2(const Vec2& p, const std::array<Vec2, 3>& t) {
  const Vec2 a = t[1] - t[0], b = t[2] - t[0], c = p - t[0];
  const double det = a.x() * b.y() - a.y() * b.x();
  if (std::abs(det) < 1e-300) return Vec3::Constant(-1e300);
  const double u = (c.x() * b.y() - c.y() * b.x()) / det, v = (a.x() * c.y() - a.y() * c.x()) / det;
  return Vec3(1.0 - u - v, u, v);
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Whether triangle t meets the domain triangle (separating axes: the sides of both).
bool meetsDomainTriangle(const std::array<Vec2, 3>& t) {
  for (int k = 0; k < 3; ++k)
    if (insideSide(t[0], k) < 0 && insideSide(t[1], k) < 0 && insideSide(t[2], k) < 0) return false;
  const double s = cross2(t[1] - t[0], t[2] - t[0]) >= 0 ? 1.0 : -1.0;
  for (int i = 0; i < 3; ++i) {
    const Vec2 &a = t[i], &b = t[(i + 1) % 3];
    bool allOut = true;
    for (int k = 0; k < 3 && allOut; ++k) allOut = s * cross2(b - a, domainCorner(k) - a) < 0;
    if (allOut) return false;
  }
  return true;
}

bool isDomainCorner(const Vec2& uv) {
  for (int k = 0; k < 3; ++k)
    if ((uv - domainCorner(k)).squaredNorm() < 1e-24) return true;
  return false;
}

int gridCell(double x, int n) { return std::clamp(static_cast<int>(std::floor(x * n)), 0, n - 1); }

}  // namespace

TrianglesInDomain::TrianglesInDomain(const BaseDomain& D, const std::vector<std::array<int, 3>>& faces,
                                     const std::vector<DomainPoint>& points,
                                     const std::vector<std::array<ChartMap, 3>>& charts) {
  grids_.resize(D.patchCount());
  struct State {
    int patch;
    ChartMap fromFirst;  // the first state's frame -> this state's frame
    std::array<Vec2, 3> tri;
  };
  std::vector<State> states;
  for (size_t f = 0; f < faces.size(); ++f) {
    const auto& t = faces[f];
    if (points[t[0]].patch < 0 || points[t[1]].patch < 0 || points[t[2]].patch < 0) continue;
    // The face in the frame of the patch of a corner that is no cone point (a cone point's chart
    // map fixes where it lies, not which way its patch turns), then flooded across the sides it
    // crosses (a face near a cone point may meet one patch twice: states differ by their map).
    int first = 0;
    while (first < 2 && isDomainCorner(points[t[first]].uv)) ++first;
    const ChartMap toFirst = charts[f][first].inverse();
    std::array<Vec2, 3> tri;
    for (int k = 0; k < 3; ++k) tri[k] = toFirst.apply(charts[f][k].apply(points[t[k]].uv));
    states.assign(1, State{points[t[first]].patch, ChartMap{}, tri});
    for (size_t i = 0; i < states.size() && states.size() < 64; ++i) {
      const State s = states[i];
      if (i > 0 && !meetsDomainTriangle(s.tri)) continue;
      grids_[s.patch].entries.push_back({static_cast<int>(f), s.tri});
      for (int k = 0; k < 3; ++k) {
        if (insideSide(s.tri[0], k) >= 0 && insideSide(s.tri[1], k) >= 0 && insideSide(s.tri[2], k) >= 0) continue;
        const int q = D.neighbour(s.patch, k);
        if (q < 0) continue;
        const ChartMap& c = D.across(s.patch, k);
        const ChartMap m = c * s.fromFirst;
        bool seen = false;
        for (const State& o : states) seen = seen || (o.patch == q && o.fromFirst == m);
        if (!seen) states.push_back({q, m, {c.apply(s.tri[0]), c.apply(s.tri[1]), c.apply(s.tri[2])}});
      }
    }
  }
  constexpr double height = 0.86602540378443864676;
  for (Grid& g : grids_) {
    g.n = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(g.entries.size()))));
    g.cells.assign(static_cast<size_t>(g.n) * g.n, {});
    for (size_t i = 0; i < g.entries.size(); ++i) {
      Vec2 lo = g.entries[i].corner[0], hi = lo;
      for (const Vec2& p : g.entries[i].corner) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      for (int x = gridCell(lo.x(), g.n); x <= gridCell(hi.x(), g.n); ++x)
        for (int y = gridCell(lo.y() / height, g.n); y <= gridCell(hi.y() / height, g.n); ++y)
          g.cells[static_cast<size_t>(y) * g.n + x].push_back(static_cast<int>(i));
    }
  }
}

bool TrianglesInDomain::locate(const DomainPoint& p, FacePoint& out) const {
  if (p.patch < 0 || p.patch >= static_cast<int>(grids_.size())) return false;
  constexpr double height = 0.86602540378443864676;
  const Grid& g = grids_[p.patch];
  const int cx = gridCell(p.uv.x(), g.n), cy = gridCell(p.uv.y() / height, g.n);
  double best = -1e300;
  // The face holding p lists p's cell (its bounding box covers it); rings further out only
  // matter for a point rounding put just outside every face.
  for (int ring = 0; ring <= g.n && best < -1e-12; ++ring)
    for (int x = cx - ring; x <= cx + ring; ++x)
      for (int y = cy - ring; y <= cy + ring; ++y) {
        if (x < 0 || y < 0 || x >= g.n || y >= g.n || std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
        for (int i : g.cells[static_cast<size_t>(y) * g.n + x]) {
          const Vec3 b = barycentric2(p.uv, g.entries[i].corner);
          if (b.minCoeff() > best) best = b.minCoeff(), out.face = g.entries[i].face, out.bary = b;
        }
      }
  if (best < -1e-6) return false;
  out.bary = out.bary.cwiseMax(0.0);
  out.bary /= out.bary.sum();
  return true;
}

}  // namespace cbd
