#include "cbd/map_untangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "cbd/distortion.h"

namespace cbd {

namespace {

/// Squared diagonal of the bounding box of `points`.
double boxDiagonal2(const std::vector<Vec3>& points) {
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).squaredNorm();
}

/// Per source vertex: the triangles around it, and its neighbours (sorted, each once).
struct Stars {
  std::vector<std::vector<int>> facesOf, nbr;
  explicit Stars(const IndexedMesh& S) : facesOf(S.vertexCount()), nbr(S.vertexCount()) {
    for (int f = 0; f < S.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        facesOf[S.faces[f][k]].push_back(f);
        nbr[S.faces[f][k]].push_back(S.faces[f][(k + 1) % 3]);
        nbr[S.faces[f][k]].push_back(S.faces[f][(k + 2) % 3]);
      }
    for (auto& n : nbr) {
      std::sort(n.begin(), n.end());
      n.erase(std::unique(n.begin(), n.end()), n.end());
    }
  }
};

/// The average of the images of v's neighbours with the source's mean-value weights (Floater
/// 2003) over v's triangles `facesOfV`; false when the weights vanish.
bool meanValueAverage(const IndexedMesh& S, const std::vector<int>& facesOfV, int v, const std::vector<Vec3>& image,
                      Vec3& out) {
  Vec3 m = Vec3::Zero();
  double ws = 0;
  for (int f : facesOfV) {
    const auto& t = S.faces[f];
    const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
    const Vec3 ea = S.positions[a] - S.positions[v], eb = S.positions[b] - S.positions[v];
    const double tn = std::tan(0.5 * std::atan2(ea.cross(eb).norm(), ea.dot(eb)));
    const double wa = tn / std::max(ea.norm(), 1e-300), wb = tn / std::max(eb.norm(), 1e-300);
    m += wa * image[a] + wb * image[b];
    ws += wa + wb;
  }
  if (!(ws > 0)) return false;
  out = m / ws;
  return true;
}

/// The mean length of the edges from v's image to its neighbours' images.
double meanImageEdge(const std::vector<int>& nbrOfV, int v, const std::vector<Vec3>& image) {
  double len = 0;
  for (int w : nbrOfV) len += (image[w] - image[v]).norm();
  return len / static_cast<double>(nbrOfV.size());
}

/// An orthonormal pair spanning the plane normal to the unit vector n.
void tangentFrame(const Vec3& n, Vec3& x, Vec3& y) {
  x = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  y = n.cross(x);
}

/// The summed unit normals of the target faces under the three images of a face.
Vec3 targetNormalSum(const std::vector<Vec3>& normal, int f0, int f1, int f2) {
  Vec3 nt = Vec3::Zero();
  for (int f : {f0, f1, f2})
    if (f >= 0) nt += normal[f];
  return nt;
}

}  // namespace

bool imageFlipped(const Vec3& i0, const Vec3& i1, const Vec3& i2, const std::vector<Vec3>& normal, int f0, int f1,
                  int f2) {
  return (i1 - i0).cross(i2 - i0).dot(targetNormalSum(normal, f0, f1, f2)) < 0;
}

namespace {

/// Straight walks over a closed triangle mesh: a displacement is laid into the plane of the
/// start face and followed across edges, each crossing rotating what is left of it about the
/// edge into the next face's plane (the unfolding isometry), so the walk stays on the surface.
class SurfaceWalker {
 public:
  explicit SurfaceWalker(const IndexedMesh& m) : m_(m), normal_(faceNormals(m)), across_(m.faceCount(), {-1, -1, -1}) {
    std::unordered_map<std::uint64_t, int> half;
    half.reserve(3 * m.faces.size());
    auto key = [](int a, int b) { return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b); };
    for (int f = 0; f < m.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) half.emplace(key(m.faces[f][k], m.faces[f][(k + 1) % 3]), f);
    for (int f = 0; f < m.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {  // across_[f][k]: the face across the edge opposite corner k
        const auto it = half.find(key(m.faces[f][(k + 2) % 3], m.faces[f][(k + 1) % 3]));
        if (it != half.end()) across_[f][k] = it->second;
      }
  }

  const std::vector<Vec3>& normals() const { return normal_; }

  Vec3 point(const FacePoint& p) const {
    const auto& t = m_.faces[p.face];
    return p.bary[0] * m_.positions[t[0]] + p.bary[1] * m_.positions[t[1]] + p.bary[2] * m_.positions[t[2]];
  }

  /// Walk from `start` by `d` (its component along the start face's normal is dropped).
  FacePoint walk(FacePoint p, Vec3 d) const {
    for (int step = 0; step < 512; ++step) {
      const auto& t = m_.faces[p.face];
      const Vec3& n = normal_[p.face];
      d -= n * n.dot(d);
      // Barycentric change db (summing to 0) with db1 e1 + db2 e2 = d.
      const Vec3 e1 = m_.positions[t[1]] - m_.positions[t[0]], e2 = m_.positions[t[2]] - m_.positions[t[0]];
      const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2), det = a11 * a22 - a12 * a12;
      if (!(det > 0)) return p;
      const double r1 = e1.dot(d), r2 = e2.dot(d);
      const double db1 = (a22 * r1 - a12 * r2) / det, db2 = (a11 * r2 - a12 * r1) / det;
      const Vec3 db(-db1 - db2, db1, db2);
      const Vec3 end = p.bary + db;
      if (end.minCoeff() >= 0) {
        p.bary = end / end.sum();
        return p;
      }
      // Leave through the edge opposite the corner whose coordinate reaches 0 first.
      double s = 2.0;
      int k = -1;
      for (int c = 0; c < 3; ++c)
        if (db[c] < 0) {
          const double sc = std::max(0.0, p.bary[c]) / -db[c];
          if (sc < s) s = sc, k = c;
        }
      s = std::min(s, 1.0);
      Vec3 b = p.bary + s * db;
      b[k] = 0.0;
      b = b.cwiseMax(0.0);
      b /= b.sum();
      const int next = across_[p.face][k];
      if (next < 0) return p.bary = b, p;
      // Rotate the rest of the step about the crossed edge into the next face's plane.
      const int va = t[(k + 1) % 3], vb = t[(k + 2) % 3];
      const Vec3 axis = (m_.positions[vb] - m_.positions[va]).normalized();
      const Vec3 rest = (1.0 - s) * d;
      const Vec3 ug = n.cross(axis), uh = normal_[next].cross(axis);
      d = rest.dot(axis) * axis + rest.dot(ug) * uh;
      FacePoint q;
      q.face = next;
      const auto& u = m_.faces[next];
      for (int c = 0; c < 3; ++c) q.bary[c] = u[c] == va ? b[(k + 1) % 3] : u[c] == vb ? b[(k + 2) % 3] : 0.0;
      p = q;
      if (d.squaredNorm() == 0) return p;
    }
    return p;
  }

 private:
  const IndexedMesh& m_;
  std::vector<Vec3> normal_;
  std::vector<std::array<int, 3>> across_;
};

/// How one vertex's image triangles look: how many are flipped or degenerate, and their
/// summed cost (angle distortion of the good ones, a large penalty growing with the
/// disagreement for the bad ones).
struct Score {
  int bad = 0;
  double cost = 0.0;
  bool overBound = false;  ///< a good triangle costs more than its bound (scoring stopped there)
  bool betterThan(const Score& o) const { return bad < o.bad || (bad == o.bad && cost < o.cost * (1.0 - 1e-9)); }
};

/// Angle distortion (s1/s2 + s2/s1)/2 - 1 of the map from triangle (s0,s1,s2) to (i0,i1,i2),
/// both in their own planes: |J|_F^2 / (2 |det J|) - 1.
double angleDistortion(const Vec3& s0, const Vec3& s1, const Vec3& s2, const Vec3& i0, const Vec3& i1, const Vec3& i2,
                       double* frobenius = nullptr) {
  auto frame = [](const Vec3& p0, const Vec3& p1, const Vec3& p2, double& a, double& bx, double& by) {
    const Vec3 e = p1 - p0, f = p2 - p0;
    a = e.norm();
    const Vec3 x = e / a;
    bx = f.dot(x);
    by = e.cross(f).norm() / a;
  };
  double sa, sbx, sby, ia, ibx, iby;
  frame(s0, s1, s2, sa, sbx, sby);
  frame(i0, i1, i2, ia, ibx, iby);
  if (frobenius) *frobenius = 1e12;
  if (!(sa > 0 && sby > 0 && ia > 0 && iby > 0)) return 1e12;
  // J = I * S^-1 with S = [sa sbx; 0 sby], I = [ia ibx; 0 iby].
  const double j11 = ia / sa, j12 = (ibx - ia * sbx / sa) / sby, j22 = iby / sby;
  if (frobenius) *frobenius = j11 * j11 + j12 * j12 + j22 * j22;
  return (j11 * j11 + j12 * j12 + j22 * j22) / (2.0 * j11 * j22) - 1.0;
}

}  // namespace

namespace {

/// E_ang and E_L2 of the map (as computeDistortion has them, with the arithmetic of
/// angleDistortion; degenerate image triangles left out).
struct MapMetrics {
  double eAng = 0.0, eL2 = 0.0;
};
MapMetrics metricsOf(const IndexedMesh& S, const std::vector<Vec3>& image) {
  double sumAs = 0, sumAt = 0, l2 = 0, ang = 0;
  for (const auto& t : S.faces) {
    const Vec3 &s0 = S.positions[t[0]], &s1 = S.positions[t[1]], &s2 = S.positions[t[2]];
    const Vec3 &i0 = image[t[0]], &i1 = image[t[1]], &i2 = image[t[2]];
    const double as = 0.5 * (s1 - s0).cross(s2 - s0).norm(), at = 0.5 * (i1 - i0).cross(i2 - i0).norm();
    double frob = 0;
    const double a = angleDistortion(s0, s1, s2, i0, i1, i2, &frob);
    if (!(at > 0) || frob >= 1e12) continue;
    sumAs += as, sumAt += at, l2 += at * 0.5 * frob, ang += as * a;
  }
  MapMetrics m;
  if (sumAt > 0) m.eAng = ang / sumAs, m.eL2 = std::sqrt(l2 / sumAt) * std::sqrt(sumAs / sumAt);
  return m;
}

double l2StretchOf(const IndexedMesh& S, const std::vector<Vec3>& image) { return metricsOf(S, image).eL2; }

/// E_ang x E_L2^w of the map (the polish's objective), for choosing among untanglings.
double productOf(const IndexedMesh& S, const std::vector<Vec3>& image, double w) {
  const MapMetrics m = metricsOf(S, image);
  return m.eAng * std::pow(m.eL2, w);
}

/// One run of stages 1-4 with the options' bound (flip counts are left to the caller: 0 here).
/// Internally a triangle is bad when it faces
/// against the normals of the target faces its corners were located in (`imageFlipped`): at a
/// corner on a target edge or vertex that is stricter than the metrics' test, never looser.
MapUntangleResult untangleOnce(const IndexedMesh& S, const IndexedMesh& T, const SurfaceWalker& walker,
                               const Stars& stars, const std::vector<char>& fixed, std::vector<FacePoint>& onTarget,
                               std::vector<Vec3>& image, const MapUntangleOptions& options, const Progress& progress) {
  MapUntangleResult r;
  const char* const stage = "removing flipped triangles";
  const int nv = S.vertexCount(), nf = S.faceCount();
  const std::vector<Vec3>& normal = walker.normals();
  const double diag2 = boxDiagonal2(T.positions);
  // Target area per unit of source area, over the whole surfaces.
  double areaS = 0, areaT = 0;
  for (const auto& t : S.faces) areaS += (S.positions[t[1]] - S.positions[t[0]]).cross(S.positions[t[2]] - S.positions[t[0]]).norm();
  for (const auto& t : T.faces) areaT += (T.positions[t[1]] - T.positions[t[0]]).cross(T.positions[t[2]] - T.positions[t[0]]).norm();
  const double areaScale = areaS > 0 && areaT > 0 ? areaT / areaS : 1.0;
  const std::vector<std::vector<int>>&facesOf = stars.facesOf, &nbr = stars.nbr;
  auto movable = [&](int v) { return !facesOf[v].empty() && onTarget[v].face >= 0 && !(v < (int)fixed.size() && fixed[v]); };

  // Face f's image with vertex v (optionally) at (x, on face g): bad (flipped or degenerate)
  // and its cost.
  struct FaceEval {
    bool bad = false, degenerate = false;
    double cost = 0.0;
  };
  auto evalFace = [&](int f, int v, const Vec3& x, int g) {
    const auto& t = S.faces[f];
    Vec3 p[3];
    int on[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = t[k] == v ? x : image[t[k]];
      on[k] = t[k] == v ? g : onTarget[t[k]].face;
    }
    FaceEval e;
    const Vec3 c = (p[1] - p[0]).cross(p[2] - p[0]);
    if (degenerateImageArea(0.5 * c.norm(), diag2)) {  // as the metrics count it
      e.bad = e.degenerate = true;
      e.cost = 1e9;
      return e;
    }
    const Vec3 nt = targetNormalSum(normal, on[0], on[1], on[2]);
    const double l = nt.norm();
    const double q = l > 0 ? c.dot(nt) / (c.norm() * l) : 1.0;
    if (q < 0) {
      e.bad = true;
      e.cost = 1e6 * (1.0 - q);
      return e;
    }
    // Angle distortion plus area distortion relative to the global scale (both 0 at best).
    const double sourceArea = (S.positions[t[1]] - S.positions[t[0]]).cross(S.positions[t[2]] - S.positions[t[0]]).norm();
    const double sigma = c.norm() / (sourceArea * areaScale);
    e.cost = std::min(1e5, angleDistortion(S.positions[t[0]], S.positions[t[1]], S.positions[t[2]], p[0], p[1], p[2]) +
                               0.5 * (sigma + 1.0 / sigma) - 1.0);
    return e;
  };
  auto bad = [&](int f) { return evalFace(f, -1, Vec3::Zero(), -1).bad; };
  // With `bound` (per triangle of v, in facesOf order), stops at the first good triangle above
  // its bound.
  auto score = [&](int v, const Vec3& x, int g, const std::vector<double>* bound = nullptr) {
    Score s;
    for (size_t i = 0; i < facesOf[v].size(); ++i) {
      const FaceEval e = evalFace(facesOf[v][i], v, x, g);
      if (bound && !e.bad && e.cost > (*bound)[i]) {
        s.overBound = true;
        return s;
      }
      s.bad += e.bad;
      s.cost += e.cost;
    }
    return s;
  };
  auto countBad = [&] {
    int n = 0;
    for (int f = 0; f < nf; ++f) n += bad(f);
    return n;
  };
  // Averages of the neighbours' images: uniform, and with the source's mean-value weights.
  auto averages = [&](int v) {
    std::vector<Vec3> out;
    Vec3 u = Vec3::Zero();
    for (int w : nbr[v]) u += image[w];
    out.push_back(u / static_cast<double>(nbr[v].size()));
    Vec3 m;
    if (meanValueAverage(S, facesOf[v], v, image, m)) out.push_back(m);
    return out;
  };
  auto apply = [&](int v, const FacePoint& fp) {
    onTarget[v] = fp;
    image[v] = walker.point(fp);
    ++r.moves;
  };

  // Source-edge distance of every vertex from the vertices of a bad triangle, up to `rings`
  // (-1 beyond).
  auto ringsAroundBad = [&](int rings) {
    std::vector<int> dist(nv, -1), frontier;
    for (int f = 0; f < nf; ++f)
      if (bad(f))
        for (int v : S.faces[f])
          if (dist[v] < 0) dist[v] = 0, frontier.push_back(v);
    for (int d = 1; d <= rings; ++d) {
      std::vector<int> next;
      for (int v : frontier)
        for (int w : nbr[v])
          if (dist[w] < 0) dist[w] = d, next.push_back(w);
      frontier.swap(next);
    }
    return dist;
  };
  // Each connected region of the movable vertices with 0 <= dist < limit that touches a bad
  // triangle is handed to `relax(region, faces)` (its vertices, and every triangle they are
  // on); the result is kept when those triangles have fewer bad ones than before, else undone.
  // True when some region was kept.
  auto relaxRegions = [&](const std::vector<int>& dist, int limit, auto&& relax) {
    bool improved = false;
    std::vector<char> seen(nv, 0);
    auto inside = [&](int v) { return dist[v] >= 0 && dist[v] < limit && movable(v); };
    for (int seed = 0; seed < nv; ++seed) {
      if (seen[seed] || !inside(seed)) continue;
      std::vector<int> region{seed};
      seen[seed] = 1;
      for (size_t i = 0; i < region.size(); ++i)
        for (int w : nbr[region[i]])
          if (!seen[w] && inside(w)) seen[w] = 1, region.push_back(w);
      std::vector<int> faces;
      for (int v : region) faces.insert(faces.end(), facesOf[v].begin(), facesOf[v].end());
      std::sort(faces.begin(), faces.end());
      faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
      auto regionBad = [&] {
        int n = 0;
        for (int f : faces) n += bad(f);
        return n;
      };
      const int before = regionBad();
      if (before == 0) continue;
      std::vector<FacePoint> keepFp;
      std::vector<Vec3> keepX;
      for (int v : region) keepFp.push_back(onTarget[v]), keepX.push_back(image[v]);
      relax(region, faces);
      if (regionBad() < before) {
        improved = true;
        for (size_t i = 0; i < region.size(); ++i)
          if (image[region[i]] != keepX[i]) ++r.moves;
      } else {
        for (size_t i = 0; i < region.size(); ++i) onTarget[region[i]] = keepFp[i], image[region[i]] = keepX[i];
      }
    }
    return improved;
  };

  int badNow = countBad();
  // Stages 1-4 with a bound `cap` on the distortion a local move may leave behind.
  auto untangleWith = [&](const double cap) {
  int ring = 0;
  int stalled = 0;
  for (int round = 0; round < options.maxRounds && badNow > 0; ++round) {
    if (!progress.report(0.5 * round / options.maxRounds, stage)) break;
    // 1. Local moves of the vertices of bad triangles.
    std::vector<char> active(nv, 0);
    for (int f = 0; f < nf; ++f)
      if (bad(f))
        for (int v : S.faces[f]) active[v] = movable(v);
    for (int pass = 0; pass < 4; ++pass) {
      bool any = false;
      for (int v = 0; v < nv; ++v) {
        if (!active[v]) continue;
        const Score cur = score(v, image[v], onTarget[v].face);
        if (cur.bad == 0) continue;
        std::vector<Vec3> goals = averages(v);
        for (int f : facesOf[v]) {  // across the opposite edge of each bad triangle
          if (!bad(f)) continue;
          const auto& t = S.faces[f];
          const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
          goals.push_back(0.5 * (image[t[(k + 1) % 3]] + image[t[(k + 2) % 3]]));
        }
        Score best = cur;
        FacePoint bestFp;
        // Per triangle of v, the most distortion a move may leave on it: `cap`, or what a good
        // triangle has already if that is more (a flipped one gets `cap`).
        std::vector<double> bound;
        for (int f : facesOf[v]) {
          const FaceEval e = evalFace(f, -1, Vec3::Zero(), -1);
          bound.push_back(e.bad ? cap : std::max(cap, e.cost));
        }
        auto tryStep = [&](const Vec3& d) {
          const FacePoint fp = walker.walk(onTarget[v], d);
          // Trading a flip for a badly distorted triangle is no gain, nor is making a distorted
          // one (a sliver of the source, say) worse: such candidates are out.
          const Score s = score(v, walker.point(fp), fp.face, &bound);
          if (!s.overBound && s.betterThan(best)) best = s, bestFp = fp;
        };
        for (const Vec3& goal : goals)
          for (double step : {1.0, 0.5, 0.25, 0.125, 1.5}) tryStep(step * (goal - image[v]));
        // A ring of directions in the tangent plane, at fractions of the image edge length.
        const double len = meanImageEdge(nbr[v], v, image);
        Vec3 ax, ay;
        tangentFrame(normal[onTarget[v].face], ax, ay);
        for (double radius : {0.1, 0.3, 0.6, 1.0, 2.0})
          for (int k = 0; k < 12; ++k) {
            const double a = 2.0 * M_PI * k / 12.0;
            tryStep(radius * len * (std::cos(a) * ax + std::sin(a) * ay));
          }
        if (best.betterThan(cur)) {
          apply(v, bestFp);
          any = true;
          for (int w : nbr[v]) active[w] = movable(w);
        }
      }
      if (!any) break;
    }
    const int after = countBad();
    if (after == 0) {
      badNow = 0;
      break;
    }
    // 2. Where local moves stall, relax a ring around what is left, never adding a bad triangle.
    if (after < badNow) ring = std::max(ring, 1);
    else if (ring < options.maxRing) ++ring;
    else if (++stalled >= 2) break;  // the widest ring did not help twice: nothing moves any more
    badNow = after;
    const std::vector<int> dist = ringsAroundBad(ring);
    for (int sweep = 0; sweep < 3; ++sweep)
      for (int v = 0; v < nv; ++v) {
        if (dist[v] < 0 || !movable(v)) continue;
        const Score cur = score(v, image[v], onTarget[v].face);
        const Vec3 goal = averages(v).back();
        const FacePoint fp = walker.walk(onTarget[v], 0.5 * (goal - image[v]));
        const Score s = score(v, walker.point(fp), fp.face);
        if (s.bad <= cur.bad && s.cost < cur.cost) apply(v, fp);
      }
    // 3. A fold (several triangles flipped over together) gives way to no single move: each
    //    connected region within the ring is relaxed as a whole, its outer ring fixed (a
    //    convex-combination map of a disk, as Tutte's), and kept only when it has fewer bad
    //    triangles than before.
    relaxRegions(dist, ring, [&](const std::vector<int>& region, const std::vector<int>&) {
      for (int sweep = 0; sweep < 40; ++sweep)
        for (int v : region) {
          onTarget[v] = walker.walk(onTarget[v], averages(v).back() - image[v]);
          image[v] = walker.point(onTarget[v]);
        }
    });
    badNow = countBad();
  }
  // 4. What is left: a smooth energy that stays finite on flipped triangles (the regularised
  //    determinant of Escobar et al. 2003, "Simultaneous untangling and smoothing of
  //    tetrahedral meshes"), minimised over every vertex within `maxRing` rings of a bad
  //    triangle at once by Gauss-Seidel sweeps of line-searched gradient steps along the
  //    surface, so that folds that no single move resolves come undone together. Kept only
  //    when fewer triangles are bad.
  for (int pass = 0; pass < options.energyPasses && badNow > 0 && options.energySweeps > 0; ++pass) {
    if (!progress.report(0.5 + 0.25 * pass / options.energyPasses, stage)) break;
    const std::vector<int> dist = ringsAroundBad(options.maxRing);
    // The region's own area scale (image area per unit of source area, before relaxing): the
    // energy's area term then keeps the local scale of the composed map rather than pulling it
    // to the global one (which, where the map compresses, spreads the region over its
    // neighbours and raises E_L2).
    double regionScale = areaScale;
    // Signed image area along the target normal, per unit of (region-scaled) source area.
    auto signedRatio = [&](int f, int v, const Vec3& x, int g) {
      const auto& t = S.faces[f];
      Vec3 p[3];
      int on[3];
      for (int k = 0; k < 3; ++k) p[k] = t[k] == v ? x : image[t[k]], on[k] = t[k] == v ? g : onTarget[t[k]].face;
      const Vec3 c = (p[1] - p[0]).cross(p[2] - p[0]);
      Vec3 nt = targetNormalSum(normal, on[0], on[1], on[2]);
      nt = nt.norm() > 0 ? Vec3(nt.normalized()) : (c.norm() > 0 ? Vec3(c.normalized()) : Vec3::UnitZ());
      const double sa = (S.positions[t[1]] - S.positions[t[0]]).cross(S.positions[t[2]] - S.positions[t[0]]).norm();
      return c.dot(nt) / (sa * regionScale);
    };
    double delta = 0;
    auto faceEnergy = [&](int f, int v, const Vec3& x, int g) {
      const auto& t = S.faces[f];
      Vec3 p[3];
      for (int k = 0; k < 3; ++k) p[k] = t[k] == v ? x : image[t[k]];
      const double d = signedRatio(f, v, x, g);
      const double h = 0.5 * (d + std::sqrt(d * d + 4.0 * delta * delta));
      if (!(h > 0)) return 1e12;
      // |J|_F^2 of the map from the source triangle onto the image, in their planes.
      const Vec3 e = S.positions[t[1]] - S.positions[t[0]], ef = S.positions[t[2]] - S.positions[t[0]];
      const Vec3 ie = p[1] - p[0], ief = p[2] - p[0];
      const double sa = e.norm(), sbx = ef.dot(e) / sa, sby = e.cross(ef).norm() / sa;
      const double ia = ie.norm();
      if (!(ia > 0)) return 1e12;
      const double ibx = ief.dot(ie) / ia, iby = ie.cross(ief).norm() / ia;
      const double j11 = ia / sa, j12 = (ibx - ia * sbx / sa) / sby, j22 = iby / sby;
      const double frob = (j11 * j11 + j12 * j12 + j22 * j22) / regionScale;
      return frob / (2.0 * h) + 0.5 * (h + 1.0 / h) + options.energyStretchWeight * 0.5 * h * frob;
    };
    auto vertexEnergy = [&](int v, const Vec3& x, int g) {
      double e = 0;
      for (int f : facesOf[v]) e += faceEnergy(f, v, x, g);
      return e;
    };
    // Each connected region of the rings on its own.
    const bool improved = relaxRegions(dist, options.maxRing + 1, [&](const std::vector<int>& region,
                                                                        const std::vector<int>& faces) {
      double as = 0, at = 0;
      for (int f : faces) {
        const auto& t = S.faces[f];
        as += (S.positions[t[1]] - S.positions[t[0]]).cross(S.positions[t[2]] - S.positions[t[0]]).norm();
        at += (image[t[1]] - image[t[0]]).cross(image[t[2]] - image[t[0]]).norm();
      }
      regionScale = as > 0 && at > 0 ? at / as : areaScale;
      for (int sweep = 0; sweep < options.energySweeps; ++sweep) {
        double dmin = 1e300;
        for (int f : faces) dmin = std::min(dmin, signedRatio(f, -1, Vec3::Zero(), -1));
        const double eps = 1e-3;
        delta = dmin < eps ? std::sqrt(eps * (eps - dmin)) : 0.0;
        for (int v : region) {
          const double e0 = vertexEnergy(v, image[v], onTarget[v].face);
          const double len = meanImageEdge(nbr[v], v, image);
          if (!(len > 0)) continue;
          Vec3 ax, ay;
          tangentFrame(normal[onTarget[v].face], ax, ay);
          const double hstep = 1e-4 * len;
          auto along = [&](const Vec3& d) {
            const FacePoint fp = walker.walk(onTarget[v], d);
            return vertexEnergy(v, walker.point(fp), fp.face);
          };
          const Vec3 grad = (along(hstep * ax) - along(-hstep * ax)) / (2 * hstep) * ax +
                            (along(hstep * ay) - along(-hstep * ay)) / (2 * hstep) * ay;
          if (!(grad.norm() > 0)) continue;
          const Vec3 dir = -grad.normalized();
          for (double step = 0.5 * len; step > 1e-3 * len; step *= 0.5) {
            const FacePoint fp = walker.walk(onTarget[v], step * dir);
            if (vertexEnergy(v, walker.point(fp), fp.face) < e0) {
              onTarget[v] = fp;
              image[v] = walker.point(fp);
              break;
            }
          }
        }
      }
    });
    badNow = countBad();
    if (!improved) break;
  }
  };
  untangleWith(options.maxDistortion);
  // Where flips survive the bound, a last attempt with a looser one (the energy of stage 4 and
  // the polish then spread the distortion such moves leave behind).
  // Each such attempt is kept only when it does not raise the map's L2 stretch by more than
  // `maxStretchGrowth` (the metric weighs the stretched triangles such moves leave by area).
  auto l2Stretch = [&] { return l2StretchOf(S, image); };
  for (double f = options.lastResortFactor; badNow > 0 && f > 1 && f <= options.lastResortFactor * options.lastResortFactor;
       f *= options.lastResortFactor) {
    if (!progress.report(0.75, stage)) break;
    const std::vector<FacePoint> keepFp = onTarget;
    const std::vector<Vec3> keepX = image;
    const int keepMoves = r.moves, keepBad = badNow;
    const double before = l2Stretch();
    untangleWith(options.maxDistortion * f);
    if (badNow < keepBad && l2Stretch() <= options.maxStretchGrowth * before) continue;
    onTarget = keepFp, image = keepX, r.moves = keepMoves, badNow = keepBad;
    break;
  }
  // Flips are counted by the caller, as the metrics count them.
  for (int f = 0; f < nf; ++f) r.degenerateAfter += evalFace(f, -1, Vec3::Zero(), -1).degenerate;
  return r;
}

/// Stage 5: Gauss-Seidel sweeps that move single images along the target surface so that
/// E_ang x E_L2^w falls (`polishProduct`, w = `polishStretchWeight`) or, else, neither the
/// numerator of E_ang (sum of source area x angle distortion) nor E_L2 (sum of image area x
/// |J|^2 / 2 over the squared image area) grows and one falls; and no triangle of the vertex
/// turns bad (flipped or degenerate by the untangling's own test) nor, if it was bad already,
/// flipped by the metrics' test. Candidates: half way to the mean-value average of the
/// neighbours' images, and steps of one mean image edge down to a thousandth of it (halving)
/// in the tangent plane along the steepest descent of that product (else along the bisector of
/// the two metrics' steepest descents); the candidate that lowers the objective most is kept,
/// not the first that lowers it at all, which settles in a worse local minimum.
/// Only vertices next to a move are visited again. Returns the number of accepted moves.
int polishMap(const IndexedMesh& S, const IndexedMesh& T, const SurfaceWalker& walker, const Stars& stars,
              const TargetNormals& targetNormals, const std::vector<char>& fixed, std::vector<FacePoint>& onTarget,
              std::vector<Vec3>& image, const MapUntangleOptions& options, const Progress& progress) {
  if (options.polishSweeps <= 0) return 0;
  const int nv = S.vertexCount(), nf = S.faceCount();
  const std::vector<Vec3>& normal = walker.normals();
  const double diag2 = boxDiagonal2(T.positions);
  const std::vector<std::vector<int>>&facesOf = stars.facesOf, &nbr = stars.nbr;
  std::vector<double> sourceArea(nf);
  double sumAs = 0;
  for (int f = 0; f < nf; ++f) {
    const auto& t = S.faces[f];
    sourceArea[f] = 0.5 * (S.positions[t[1]] - S.positions[t[0]]).cross(S.positions[t[2]] - S.positions[t[0]]).norm();
    sumAs += sourceArea[f];
  }
  // One triangle's share of the metrics with vertex v (optionally) at x, located at `where`.
  // `bad` is the untangling's strict test; a triangle that fails it already may stay so, but
  // must not turn flipped by the metrics' looser one (`flipped`).
  struct Terms {
    bool bad = false, flipped = false;
    double at = 0, l2 = 0, ang = 0;
  };
  auto terms = [&](int f, int v, const Vec3& x, const FacePoint* where) {
    const auto& t = S.faces[f];
    Vec3 p[3];
    const FacePoint* on[3];
    for (int k = 0; k < 3; ++k) p[k] = t[k] == v ? x : image[t[k]], on[k] = t[k] == v ? where : &onTarget[t[k]];
    Terms e;
    const Vec3 c = (p[1] - p[0]).cross(p[2] - p[0]);
    e.at = 0.5 * c.norm();
    double frob = 0;
    const double a = angleDistortion(S.positions[t[0]], S.positions[t[1]], S.positions[t[2]], p[0], p[1], p[2], &frob);
    e.bad = degenerateImageArea(e.at, diag2) || frob >= 1e12 ||
            imageFlipped(p[0], p[1], p[2], normal, on[0]->face, on[1]->face, on[2]->face);
    e.flipped = e.bad && targetNormals.flipped(p[0], p[1], p[2], *on[0], *on[1], *on[2]);
    e.l2 = e.at * 0.5 * frob;
    e.ang = sourceArea[f] * a;
    return e;
  };
  double sumAt = 0, sumL2 = 0, sumAng = 0;
  for (int f = 0; f < nf; ++f) {
    const Terms e = terms(f, -1, Vec3::Zero(), nullptr);
    if (e.bad && degenerateImageArea(e.at, diag2)) continue;
    sumAt += e.at, sumL2 += e.l2, sumAng += e.ang;
  }
  if (!(sumAt > 0)) return 0;
  // A map without angle distortion but for rounding (the identity, a similarity) is where the
  // polish would end anyway: its relative gains would be rounding noise.
  if (sumAng <= 1e-12 * sumAs) return 0;
  auto movable = [&](int v) { return !facesOf[v].empty() && onTarget[v].face >= 0 && !(v < (int)fixed.size() && fixed[v]); };
  std::vector<char> active(nv, 0);
  for (int v = 0; v < nv; ++v) active[v] = movable(v);
  int moves = 0;
  std::vector<Terms> cur;
  // The order the sweeps visit the vertices in: by index, or a permutation drawn from
  // `polishOrderSeed` (Fisher-Yates over a splitmix64 stream: the same on every platform).
  std::vector<int> order(nv);
  for (int v = 0; v < nv; ++v) order[v] = v;
  if (options.polishOrderSeed != 0) {
    std::uint64_t state = options.polishOrderSeed;
    auto next64 = [&state] {
      std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      return z ^ (z >> 31);
    };
    for (int i = nv - 1; i > 0; --i) std::swap(order[i], order[next64() % static_cast<std::uint64_t>(i + 1)]);
  }
  for (int sweep = 0; sweep < options.polishSweeps; ++sweep) {
    if (!progress.report(static_cast<double>(sweep) / options.polishSweeps, "polishing the map")) break;
    std::vector<char> next(nv, 0);
    int swept = 0;
    const double angStart = sumAng, l2Start = sumL2 / (sumAt * sumAt);
    for (const int v : order) {
      if (!active[v]) continue;
      // The vertex's triangles as they are; a degenerate one is left to the untangling.
      cur.clear();
      double at0 = 0, l20 = 0, ang0 = 0;
      bool degenerate = false;
      for (int f : facesOf[v]) {
        cur.push_back(terms(f, -1, Vec3::Zero(), nullptr));
        degenerate |= degenerateImageArea(cur.back().at, diag2) || cur.back().l2 >= 1e11;
        at0 += cur.back().at, l20 += cur.back().l2, ang0 += cur.back().ang;
      }
      if (degenerate) continue;
      const double l2Now = sumL2 / (sumAt * sumAt);
      // (E_ang numerator of the star, E_L2 proxy of the whole map) with v at fp; nullopt-like
      // `ok` false when a good triangle turns bad.
      auto evaluate = [&](const FacePoint& fp, const Vec3& x, bool& ok, double& at, double& l2) {
        double ang = 0;
        at = 0, l2 = 0;
        ok = true;
        for (size_t i = 0; i < facesOf[v].size(); ++i) {
          const Terms e = terms(facesOf[v][i], v, x, &fp);
          if ((e.bad && !cur[i].bad) || (e.flipped && !cur[i].flipped)) ok = false;
          at += e.at, l2 += e.l2, ang += e.ang;
        }
        const double a = sumAt - at0 + at;
        return std::make_pair(ang, a > 0 ? (sumL2 - l20 + l2) / (a * a) : 1e300);
      };
      // The candidates' score: the first-order change of the objective (relative to the
      // map's), or for the two-metric rule the sum of both relative changes; a candidate is
      // admissible when it turns no triangle bad and lowers that objective (else: raises
      // neither metric and lowers one). The best admissible candidate is kept.
      struct Candidate {
        FacePoint fp;
        Vec3 x;
        double at = 0, l2 = 0, ang = 0, score = 0;
      };
      Candidate best;
      bool found = false;
      auto consider = [&](const FacePoint& fp) {
        Candidate c{fp, walker.point(fp)};
        bool ok = false;
        const auto [ang, l2Map] = evaluate(fp, c.x, ok, c.at, c.l2);
        if (!ok) return;
        c.ang = ang;
        if (options.polishProduct) {
          c.score = (ang - ang0) / sumAng + 0.5 * options.polishStretchWeight * (l2Map - l2Now) / l2Now;
          if (!(c.score < -1e-12)) return;
        } else {
          if (ang > ang0 || l2Map > l2Now || !(ang < ang0 * (1 - 1e-12) || l2Map < l2Now * (1 - 1e-12))) return;
          c.score = (ang - ang0) / sumAng + (l2Map - l2Now) / l2Now;
        }
        if (!found || c.score < best.score) best = c, found = true;
      };
      ++swept;
      // Half way to the mean-value average of the neighbours' images (the source's weights).
      Vec3 m;
      if (meanValueAverage(S, facesOf[v], v, image, m)) consider(walker.walk(onTarget[v], 0.5 * (m - image[v])));
      // Steps along the steepest descent of the objective, by central differences on the
      // surface: from one mean image edge down to a thousandth of it, halving.
      const double len = meanImageEdge(nbr[v], v, image);
      if (len > 0) {
        Vec3 ax, ay;
        tangentFrame(normal[onTarget[v].face], ax, ay);
        const double h = 1e-4 * len;
        Vec3 gAng = Vec3::Zero(), gL2 = Vec3::Zero();
        for (const Vec3& axis : {ax, ay}) {
          std::pair<double, double> side[2];
          for (int s = 0; s < 2; ++s) {
            const FacePoint fp = walker.walk(onTarget[v], (s ? -h : h) * axis);
            bool ok = false;
            double at = 0, l2 = 0;
            side[s] = evaluate(fp, walker.point(fp), ok, at, l2);
          }
          gAng += (side[0].first - side[1].first) / (2 * h) * axis;
          gL2 += (side[0].second - side[1].second) / (2 * h) * axis;
        }
        Vec3 dir = Vec3::Zero();
        if (options.polishProduct) {
          dir = -(gAng / sumAng + 0.5 * options.polishStretchWeight * gL2 / l2Now);
          if (dir.norm() > 0) dir /= dir.norm();
        } else {
          if (gAng.norm() > 0) dir -= gAng.normalized();
          if (gL2.norm() > 0) dir -= gL2.normalized();
        }
        if (dir.norm() > 1e-6) {  // else no descent, or the two pull opposite ways
          dir.normalize();
          for (double step = len; step > 1e-3 * len; step *= 0.5) consider(walker.walk(onTarget[v], step * dir));
        }
      }
      if (!found) continue;
      sumAt += best.at - at0, sumL2 += best.l2 - l20, sumAng += best.ang - ang0;
      onTarget[v] = best.fp, image[v] = best.x;
      ++moves;
      for (int w : nbr[v]) next[w] = movable(w);
    }
    active.swap(next);
    // Converged: nothing left to visit, or the sweep gained less than the tolerance.
    const double angRatio = sumAng / angStart, l2Ratio = sumL2 / (sumAt * sumAt) / l2Start;
    if (swept == 0 || (options.polishProduct ? angRatio * std::sqrt(l2Ratio) >= 1 - options.polishTolerance
                                             : angRatio >= 1 - options.polishTolerance &&
                                                   l2Ratio >= 1 - options.polishTolerance))
      break;
  }
  return moves;
}

/// Lays the disk of `rings` source rings round the fixed vertex a out anew round a's image: the
/// source's disk flattened into a's tangent plane (directions by angle about a's normal,
/// distances as they are), scaled to the present mean distance of a's neighbours, turned to
/// fit the vertices round the disk that stay, and put on the target by straight walks from a's
/// image. The disk holds only vertices nearer (in rings) to a than to any other fixed vertex:
/// another anchor and its own neighbourhood stay where they are, so a restart never tears an
/// anchor's star off that anchor's image. False (nothing moved) when `rings` < 1 or
/// the disk holds an unmapped vertex.
bool reembedStar(const IndexedMesh& S, const Stars& stars, const SurfaceWalker& walker, const std::vector<char>& fixed,
                 int a, int rings, std::vector<FacePoint>& onTarget, std::vector<Vec3>& image) {
  if (rings < 1 || stars.facesOf[a].empty() || onTarget[a].face < 0) return false;
  auto isFixed = [&](int v) { return v < (int)fixed.size() && fixed[v]; };
  // Ring distances from a out to 2 * rings, and from the other fixed vertices in that ball
  // (multi-source), within it: a vertex of the disk is at most `rings` from a, so one at most
  // that far from another fixed vertex lies within 2 * rings of a.
  std::unordered_map<int, int> dist{{a, 0}};
  std::vector<int> ball{a};
  for (size_t i = 0; i < ball.size(); ++i) {
    const int d = dist.at(ball[i]);
    if (d == 2 * rings) continue;
    for (int w : stars.nbr[ball[i]])
      if (dist.emplace(w, d + 1).second) ball.push_back(w);
  }
  std::unordered_map<int, int> other;
  std::vector<int> front;
  for (int v : ball)
    if (v != a && isFixed(v)) other.emplace(v, 0), front.push_back(v);
  for (size_t i = 0; i < front.size(); ++i) {
    const int d = other.at(front[i]);
    if (d == rings) continue;
    for (int w : stars.nbr[front[i]])
      if (dist.count(w) && other.emplace(w, d + 1).second) front.push_back(w);
  }
  // The disk (a's side of that split, up to `rings`) and the vertices next to it that stay
  // (`around`: the ring beyond it and the other anchors' sides), which decide the turn.
  std::vector<int> disk{a}, around;
  std::unordered_map<int, char> seen{{a, 1}};
  for (size_t i = 0; i < disk.size(); ++i)
    for (int w : stars.nbr[disk[i]]) {
      if (!seen.emplace(w, 1).second) continue;
      const auto o = other.find(w);
      const int d = dist.at(w);
      if (d <= rings && (o == other.end() || o->second > d)) disk.push_back(w);
      else around.push_back(w);
    }
  for (size_t i = 1; i < disk.size(); ++i)
    if (onTarget[disk[i]].face < 0) return false;
  // The source's tangent frame at a (area-weighted normal of its triangles).
  Vec3 ns = Vec3::Zero();
  for (int f : stars.facesOf[a]) {
    const auto& t = S.faces[f];
    ns += (S.positions[t[1]] - S.positions[t[0]]).cross(S.positions[t[2]] - S.positions[t[0]]);
  }
  if (!(ns.norm() > 0)) return false;
  ns.normalize();
  Vec3 sx, sy, ax, ay;
  tangentFrame(ns, sx, sy);
  tangentFrame(walker.normals()[onTarget[a].face], ax, ay);
  double srcMean = 0, imgMean = 0;
  int ring1 = 0;
  for (int w : stars.nbr[a]) srcMean += (S.positions[w] - S.positions[a]).norm(), imgMean += (image[w] - image[a]).norm(), ++ring1;
  if (!(ring1 > 0 && srcMean > 0 && imgMean > 0)) return false;
  const double scale = imgMean / srcMean;
  // The turn that fits the images of the vertices round the disk best (circular mean of the
  // differences of the angles about a): those stay, and the disk must join them.
  auto sourceAngle = [&](int w) {
    const Vec3 d = S.positions[w] - S.positions[a];
    return std::atan2(d.dot(sy), d.dot(sx));
  };
  double c = 0, sn = 0;
  for (int w : around.empty() ? stars.nbr[a] : around) {
    if (onTarget[w].face < 0) continue;
    const Vec3 d = image[w] - image[a];
    const double phi = std::atan2(d.dot(ay), d.dot(ax)) - sourceAngle(w);
    c += std::cos(phi), sn += std::sin(phi);
  }
  const double offset = std::atan2(sn, c);
  for (size_t i = 1; i < disk.size(); ++i) {
    const int w = disk[i];
    const Vec3 d = S.positions[w] - S.positions[a];
    const double r = (d - ns * ns.dot(d)).norm() * scale, angle = sourceAngle(w) + offset;
    onTarget[w] = walker.walk(onTarget[a], r * (std::cos(angle) * ax + std::sin(angle) * ay));
    image[w] = walker.point(onTarget[w]);
  }
  return true;
}

}  // namespace

bool relayAnchorDisk(const IndexedMesh& source, const IndexedMesh& target, const std::vector<char>& fixed, int anchor,
                     int rings, std::vector<FacePoint>& onTarget, std::vector<Vec3>& image) {
  if (anchor < 0 || anchor >= source.vertexCount() || rings < 1 || onTarget.size() != image.size() ||
      static_cast<int>(image.size()) != source.vertexCount())
    return false;
  return reembedStar(source, Stars(source), SurfaceWalker(target), fixed, anchor, rings, onTarget, image);
}

MapUntangleResult untangleCrossMap(const IndexedMesh& S, const IndexedMesh& T, const std::vector<char>& fixed,
                                   std::vector<FacePoint>& onTarget, std::vector<Vec3>& image,
                                   const MapUntangleOptions& options, const Progress& progress) {
  const TargetNormals normals(T);
  const double diag2 = boxDiagonal2(T.positions);
  // Degenerate image triangles as the metrics count them (the metrics take the images' box,
  // which covers the same surface as the target's).
  auto degenerate = [&](const std::array<int, 3>& t, const std::vector<Vec3>& x) {
    return degenerateImageArea(0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm(), diag2);
  };
  // Flipped triangles as the metrics count them (degenerate ones apart).
  auto flippedFace = [&](const std::array<int, 3>& t, const std::vector<FacePoint>& on, const std::vector<Vec3>& x) {
    if (on[t[0]].face < 0 || on[t[1]].face < 0 || on[t[2]].face < 0) return false;
    if (degenerate(t, x)) return false;
    return normals.flipped(x[t[0]], x[t[1]], x[t[2]], on[t[0]], on[t[1]], on[t[2]]);
  };
  auto flips = [&](const std::vector<FacePoint>& on, const std::vector<Vec3>& x) {
    int n = 0;
    for (const auto& t : S.faces) n += flippedFace(t, on, x);
    return n;
  };
  const int before = flips(onTarget, image);
  const std::vector<FacePoint> startOn = onTarget;
  const std::vector<Vec3> startImage = image;
  // Built once for every run below.
  const SurfaceWalker walker(T);
  const Stars stars(S);
  MapUntangleResult r;
  // Progress: the runs of stages 1-6 share the first 60 % (run k its half of what is left, as
  // their number depends on what each leaves), the polish the rest.
  int runs = 0;
  auto nextRun = [&] {
    const double a = 0.6 * (1.0 - std::pow(0.5, runs)), b = 0.6 * (1.0 - std::pow(0.5, runs + 1));
    ++runs;
    return progress.part(a, b);
  };
  auto cancelled = [&] {
    r.status = Status::error(ErrorCode::Cancelled, "cancelled while removing flipped triangles");
    return r;
  };
  // Stages 1-6 only where something is flipped; the polish (stage 7) in any case, so that the
  // result does not depend on whether the composed map happened to have a flip.
  if (before > 0) {
    r = untangleOnce(S, T, walker, stars, fixed, onTarget, image, options, nextRun());
    r.flippedBefore = before;
    r.flippedAfter = flips(onTarget, image);
    r.attempts = 1;
    // Where flips survive, the whole run again from the start with other bounds; the map with
    // the fewest flips, then the lowest E_ang x E_L2^w (the polish's objective), is kept.
    double bestScore = r.flippedAfter > 0 ? productOf(S, image, options.polishStretchWeight) : 0.0;
    auto retryFromStart = [&](const MapUntangleOptions& o) {
      if (progress.cancelled()) return;
      std::vector<FacePoint> on = startOn;
      std::vector<Vec3> x = startImage;
      MapUntangleResult t = untangleOnce(S, T, walker, stars, fixed, on, x, o, nextRun());
      t.flippedBefore = before;
      t.flippedAfter = flips(on, x);
      t.attempts = r.attempts + 1;
      const double score = productOf(S, x, options.polishStretchWeight);
      if (t.flippedAfter < r.flippedAfter || (t.flippedAfter == r.flippedAfter && score < bestScore)) {
        r = t, bestScore = score;
        onTarget = std::move(on), image = std::move(x);
      } else {
        r.attempts = t.attempts;
      }
    };
    for (const double bound : options.retryDistortions) {
      if (r.flippedAfter == 0) break;
      MapUntangleOptions o = options;
      o.maxDistortion = bound;
      retryFromStart(o);
    }
    // Flips left next to an anchor: where the composed map folds the anchor's star (its
    // neighbours' images in a wedge on one side of it, as where the two layouts meet the anchor at
    // corner angles far apart), no move of one neighbour undoes it, and relaxations with the
    // anchor fixed inside keep the wedge. The untangling is run again from the kept map with the
    // anchor's neighbours laid out round it anew (reembedStar), kept when fewer flips are left.
    // `o`: the options of the untangling after each restart.
    auto restartAtAnchors = [&](const MapUntangleOptions& o) {
      if (r.flippedAfter == 0 || options.anchorRestartRings.empty()) return;
      std::vector<int> anchors;
      for (const auto& t : S.faces) {
        if (!flippedFace(t, onTarget, image)) continue;
        for (int v : t)
          if (v < (int)fixed.size() && fixed[v]) anchors.push_back(v);
      }
      std::sort(anchors.begin(), anchors.end());
      anchors.erase(std::unique(anchors.begin(), anchors.end()), anchors.end());
      for (int a : anchors) {
        if (r.flippedAfter == 0) break;
        // Every disk size from the same map; the one with the fewest flips, then the lowest
        // E_ang x E_L2^w.
        const std::vector<FacePoint> keptOn = onTarget;
        const std::vector<Vec3> keptImage = image;
        int bestLeft = r.flippedAfter;
        double bestRestartScore = 0;
        MapUntangleResult best;  // the untangling of the restart kept (none: `bestLeft` unchanged)
        for (const int rings : options.anchorRestartRings) {
          if (progress.cancelled()) break;
          std::vector<FacePoint> on = keptOn;
          std::vector<Vec3> x = keptImage;
          if (!reembedStar(S, stars, walker, fixed, a, rings, on, x)) continue;
          const MapUntangleResult t = untangleOnce(S, T, walker, stars, fixed, on, x, o, nextRun());
          ++r.attempts;
          const int left = flips(on, x);
          if (left > bestLeft || (left == bestLeft && bestLeft == r.flippedAfter)) continue;
          const double score = productOf(S, x, options.polishStretchWeight);
          if (left == bestLeft && score >= bestRestartScore) continue;
          bestLeft = left, bestRestartScore = score, best = t;
          onTarget = std::move(on), image = std::move(x);
        }
        if (bestLeft < r.flippedAfter) r.moves += best.moves;
        r.flippedAfter = bestLeft;
      }
    };
    restartAtAnchors(options);
    // Folds that all that leaves far from every anchor (long thin parts mapped onto stubbier
    // ones, many rings from the nearest anchor) give way to
    // relaxation and energy over wider rings: the whole untangling once more from the composed
    // map with `retryMaxRing`, with each bound in turn, kept by the same rule.
    if (r.flippedAfter > 0 && options.retryMaxRing > options.maxRing) {
      bestScore = productOf(S, image, options.polishStretchWeight);
      MapUntangleOptions wide = options;
      wide.maxRing = options.retryMaxRing;
      std::vector<double> bounds{options.maxDistortion};
      bounds.insert(bounds.end(), options.retryDistortions.begin(), options.retryDistortions.end());
      for (const double bound : bounds) {
        if (r.flippedAfter == 0) break;
        MapUntangleOptions o = wide;
        o.maxDistortion = bound;
        retryFromStart(o);
      }
      // A star that the wide rings left folded (what they kept may not be what the restarts
      // above started from): the restarts again, untangling with the wide rings.
      restartAtAnchors(wide);
    }
    // All of that is kept only when it left fewer flips than the composed map had, or as few
    // (on a pair whose layouts disagree wildly, as with very few anchors, the moves can
    // multiply them).
    if (r.flippedAfter > before) {
      onTarget = startOn, image = startImage;
      r.flippedAfter = before, r.moves = 0;  // the moves discarded are not reported
    }
  }
  if (progress.cancelled()) return cancelled();
  // The polish, once, on the map kept: it never turns a triangle bad, so the flip count cannot
  // grow (it is counted again all the same).
  r.moves += polishMap(S, T, walker, stars, normals, fixed, onTarget, image, options, progress.part(0.6, 1.0));
  if (progress.cancelled()) return cancelled();
  r.flippedAfter = flips(onTarget, image);
  r.movedVertices = 0;
  for (size_t v = 0; v < image.size(); ++v) r.movedVertices += image[v] != startImage[v];
  // Degenerate triangles of the map returned.
  r.degenerateAfter = 0;
  for (const auto& t : S.faces) r.degenerateAfter += degenerate(t, image);
  return r;
}

}  // namespace cbd
