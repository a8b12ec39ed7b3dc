#include "cbd/map_smoothing.h"

#include "cbd/map_untangle.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <Eigen/Dense>

namespace cbd {
namespace {

/// Where a source vertex is in the common domain: inside a patch, on a layout edge (with the
/// patch it is expressed in), or an anchor (fixed).
struct DomainState {
  int patch = -1;
  Vec2 uv = Vec2::Zero();
  int edge = -1;    ///< layout edge it lies on, or -1
  bool anchor = false;
};

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The affine isometry taking patch q's domain triangle onto the copy of it unfolded across
/// their shared layout edge e into patch p's chart.
struct Unfold {
  Vec2 o, x, y;      // image of q's domain corner 0 and of its two edge vectors
  Vec2 apply(const Vec2& uv, const Vec2& c0, const Eigen::Matrix2d& inv) const {
    const Eigen::Vector2d ab = inv * (uv - c0);
    return o + ab.x() * x + ab.y() * y;
  }
};

bool unfold(const Layout& L, int p, int q, int e, Unfold& u) {
  const Patch &P = L.patches[p], &Q = L.patches[q];
  int kp = -1, kq = -1;
  for (int k = 0; k < 3; ++k) {
    if (P.edges[k] == e) kp = k;
    if (Q.edges[k] == e) kq = k;
  }
  if (kp < 0 || kq < 0) return false;
  // In p, side kp runs corners[kp] -> corners[kp+1]; in q the same edge runs the other way.
  const Vec2 A = domainCorner(kp), B = domainCorner(kp + 1), C = domainCorner(kp + 2);
  const Vec2 mid = 0.5 * (A + B), Cr = 2.0 * mid - C;  // C reflected across AB (equilateral)
  Vec2 img[3];
  img[kq % 3] = B;
  img[(kq + 1) % 3] = A;
  img[(kq + 2) % 3] = Cr;
  u.o = img[0];
  u.x = img[1] - img[0];
  u.y = img[2] - img[0];
  return true;
}

}  // namespace

MapSmoothingResult smoothCrossMap(const IndexedMesh& S, const Layout& Ls, const PatchParameterization& sp,
                                  const IndexedMesh& T, const Layout& Lt, const PatchParameterization& tp,
                                  CrossMap& map, const MapSmoothingOptions& options) {
  MapSmoothingResult r;
  const int nv = S.vertexCount();
  // Initial domain states from the source parameterization.
  std::vector<DomainState> st(nv);
  std::vector<int> edgeOfVertex(Ls.mesh.vertexCount(), -1);
  for (size_t e = 0; e < Ls.edges.size(); ++e)
    for (size_t k = 1; k + 1 < Ls.edges[e].vertices.size(); ++k) edgeOfVertex[Ls.edges[e].vertices[k]] = static_cast<int>(e);
  std::vector<char> isAnchor(Ls.mesh.vertexCount(), 0);
  for (int v : Ls.anchorVertices) isAnchor[v] = 1;
  for (int v = 0; v < nv; ++v) {
    const int h = Ls.mesh.outgoing(v);
    if (h < 0) continue;
    const int f = Ls.mesh.face(h);
    const auto c = Ls.mesh.faceVertices(f);
    st[v].patch = Ls.facePatch[f];
    st[v].uv = sp.cornerUV[f][std::find(c.begin(), c.end(), v) - c.begin()];
    st[v].edge = edgeOfVertex[v];
    st[v].anchor = isAnchor[v] != 0;
  }
  // Patches on both sides of each layout edge.
  std::vector<std::array<int, 2>> sides(Ls.edges.size(), {-1, -1});
  for (size_t p = 0; p < Ls.patches.size(); ++p)
    for (int k = 0; k < 3; ++k) {
      auto& s = sides[Ls.patches[p].edges[k]];
      (s[0] < 0 ? s[0] : s[1]) = static_cast<int>(p);
    }
  std::vector<std::vector<int>> nbr(nv);
  std::vector<std::vector<int>> facesOf(nv);
  for (int f = 0; f < S.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      nbr[S.faces[f][k]].push_back(S.faces[f][(k + 1) % 3]);
      facesOf[S.faces[f][k]].push_back(f);
    }
  for (auto& n : nbr) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  const TargetNormals targetNormals(T);
  auto flipped = [&](int f) {
    const auto& t = S.faces[f];
    const auto& x = map.sourceImage;
    const auto& on = map.sourceToTarget;
    const bool flat = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).squaredNorm() == 0;  // a collapse counts too
    return flat || targetNormals.flipped(x[t[0]], x[t[1]], x[t[2]], on[t[0]], on[t[1]], on[t[2]]);
  };
  for (int f = 0; f < S.faceCount(); ++f) r.flippedBefore += flipped(f);

  const PatchLocator locator(Lt, tp);
  const Vec2 c0 = domainCorner(0);
  Eigen::Matrix2d basis;
  basis.col(0) = domainCorner(1) - c0;
  basis.col(1) = domainCorner(2) - c0;
  const Eigen::Matrix2d inv = basis.inverse();
  auto inside = [&](const Vec2& uv, double eps) {  // strictly inside the domain triangle
    for (int k = 0; k < 3; ++k)
      if (cross2(domainCorner(k + 1) - domainCorner(k), uv - domainCorner(k)) < eps) return false;
    return true;
  };
  // A neighbour's position in the chart of patch p (unfolded across edge e when needed).
  auto inChart = [&](int w, int p, int q, int e, Vec2& out) {
    const DomainState& s = st[w];
    if (s.patch == p) return out = s.uv, true;
    Unfold u;
    if (q >= 0 && s.patch == q) {  // across the path v lies on
      if (!unfold(Ls, p, q, e, u)) return false;
      out = u.apply(s.uv, c0, inv);
      return true;
    }
    if (s.anchor) {  // a corner of p
      for (int k = 0; k < 3; ++k)
        if (Ls.anchorVertices[Ls.patches[p].corners[k]] == w) return out = domainCorner(k), true;
      return false;
    }
    if (s.edge >= 0 && unfold(Ls, p, s.patch, s.edge, u)) {  // on a side of p, stored in the other patch
      out = u.apply(s.uv, c0, inv);
      return true;
    }
    return false;
  };

  for (int it = 0; it < options.iterations; ++it) {
    for (int v = 0; v < nv; ++v) {
      DomainState& s = st[v];
      if (s.anchor || s.patch < 0) continue;
      const int p = s.patch;
      int q = -1;
      if (s.edge >= 0) {
        const auto sd = sides[s.edge];
        q = sd[0] == p ? sd[1] : sd[0];
      }
      // Source weights: mean-value weights of the source 1-ring (positive; an affine map is
      // a fixed point), w_j = (tan(a1/2) + tan(a2/2)) / |v_j - v|.
      Vec3 target3 = Vec3::Zero();
      double wsum = 0;
      bool ok = true;
      for (int w : nbr[v]) {
        Vec2 dummy;
        if (!inChart(w, p, q, s.edge, dummy)) {
          ok = false;
          break;
        }
      }
      if (ok) {
        for (int f : facesOf[v]) {
          const auto& t = S.faces[f];
          const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
          const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
          const Vec3 ea = S.positions[a] - S.positions[v], eb = S.positions[b] - S.positions[v];
          const double half = 0.5 * std::atan2(ea.cross(eb).norm(), ea.dot(eb));
          const double tn = std::tan(half);
          const double wa = tn / std::max(ea.norm(), 1e-300), wb = tn / std::max(eb.norm(), 1e-300);
          target3 += wa * map.sourceImage[a] + wb * map.sourceImage[b];
          wsum += wa + wb;
        }
      }
      if (!ok || wsum <= 0) continue;
      target3 /= wsum;
      // Project the 3D step into the chart through the target face under v's image.
      const FacePoint& fp = map.sourceToTarget[v];
      int g;
      Vec3 b;
      if (!locator.locate(p, s.uv, g, b)) continue;
      const auto tv = Lt.mesh.faceVertices(g);
      Eigen::Matrix<double, 3, 2> J;  // d(3D)/d(uv) on face g
      {
        const Vec2 &u0 = tp.cornerUV[g][0], &u1 = tp.cornerUV[g][1], &u2 = tp.cornerUV[g][2];
        Eigen::Matrix2d U;
        U.col(0) = u1 - u0;
        U.col(1) = u2 - u0;
        Eigen::Matrix<double, 3, 2> X;
        X.col(0) = Lt.mesh.position(tv[1]) - Lt.mesh.position(tv[0]);
        X.col(1) = Lt.mesh.position(tv[2]) - Lt.mesh.position(tv[0]);
        if (std::abs(U.determinant()) < 1e-300) continue;
        J = X * U.inverse();
      }
      const Vec2 step = J.completeOrthogonalDecomposition().solve(target3 - map.sourceImage[v]);
      Vec2 cand = s.uv + 0.5 * step;
      // Where the candidate lies: inside p, or (for a vertex on a path) inside q unfolded.
      DomainState next = s;
      if (inside(cand, 1e-12)) {
        next.patch = p, next.uv = cand, next.edge = -1;
      } else if (q >= 0) {
        Unfold u;
        if (!unfold(Ls, p, q, s.edge, u)) continue;
        Eigen::Matrix2d Ub;
        Ub.col(0) = u.x;
        Ub.col(1) = u.y;
        const Eigen::Vector2d ab = Ub.inverse() * (cand - u.o);
        const Vec2 inQ = c0 + basis * ab;
        if (!inside(inQ, 1e-12)) {
          ++r.rejected;
          continue;
        }
        next.patch = q, next.uv = inQ, next.edge = -1;
      } else {
        ++r.rejected;
        continue;
      }
      int g2;
      Vec3 b2;
      if (!locator.locate(next.patch, next.uv, g2, b2)) continue;
      const auto tv2 = Lt.mesh.faceVertices(g2);
      const FacePoint oldFp = fp;
      const Vec3 oldImage = map.sourceImage[v];
      int before = 0;
      for (int f : facesOf[v]) before += flipped(f);
      map.sourceImage[v] = b2[0] * Lt.mesh.position(tv2[0]) + b2[1] * Lt.mesh.position(tv2[1]) + b2[2] * Lt.mesh.position(tv2[2]);
      FacePoint nfp;
      nfp.face = Lt.mesh.inputFace(g2);
      for (int k = 0; k < 3; ++k) nfp.bary += b2[k] * Lt.mesh.baryIn(tv2[k], nfp.face);
      map.sourceToTarget[v] = nfp;
      int after = 0;
      for (int f : facesOf[v]) after += flipped(f);
      if (after > before) {
        map.sourceImage[v] = oldImage;
        map.sourceToTarget[v] = oldFp;
        ++r.rejected;
        continue;
      }
      // A vertex that moved off its path is now interior to a patch.
      s = next;
      ++r.moves;
    }
  }
  for (int f = 0; f < S.faceCount(); ++f) r.flippedAfter += flipped(f);
  return r;
}

}  // namespace cbd
