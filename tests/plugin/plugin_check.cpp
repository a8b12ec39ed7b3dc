/// @file plugin_check.cpp
/// Checks on the files MeshLab saved from the cbd plugin's layers (used by the plugin tests):
///   plugin_check mst MST TARGET VERTICES TOL
///       MST has VERTICES vertices and faces, and every vertex lies on TARGET's surface: the
///       largest point-to-triangle distance is at most TOL times TARGET's bbox diagonal.
///   plugin_check colours A B COUNT
///       the sets of per-face RGB colours of A and B are equal and have COUNT elements.
///   plugin_check counts FILE VERTICES [FACES]
///       FILE has that many vertices (and faces).
/// Prints one line per check; exit status 0 when every check holds, 1 otherwise, 2 on usage or
/// file errors.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "cbd/mesh.h"

namespace {

using cbd::Vec3;

bool load(const char* path, cbd::Mesh& m) {
  const cbd::LoadResult r = cbd::loadMesh(path, m);
  if (!r.status.ok()) {
    std::fprintf(stderr, "plugin_check: cannot load '%s': %s\n", path, r.status.message.c_str());
    return false;
  }
  return true;
}

Vec3 pos(const cbd::MeshVertex& v) { return Vec3(v.cP()[0], v.cP()[1], v.cP()[2]); }

/// Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
double pointTriangle2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).squaredNorm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).squaredNorm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).squaredNorm();
}

int checkMst(const char* mstPath, const char* targetPath, int vertices, double tol) {
  cbd::Mesh mst, target;
  if (!load(mstPath, mst) || !load(targetPath, target)) return 2;
  bool ok = true;
  if (mst.vn != vertices || mst.fn == 0) {
    std::printf("FAIL mst: %d vertices, %d faces (expected %d vertices)\n", mst.vn, mst.fn, vertices);
    ok = false;
  } else {
    std::printf("ok   mst: %d vertices, %d faces\n", mst.vn, mst.fn);
  }
  struct Tri {
    Vec3 a, b, c, lo, hi;
  };
  std::vector<Tri> tris;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& f : target.face) {
    if (f.IsD()) continue;
    Tri t{pos(*f.cV(0)), pos(*f.cV(1)), pos(*f.cV(2)), {}, {}};
    t.lo = t.a.cwiseMin(t.b).cwiseMin(t.c);
    t.hi = t.a.cwiseMax(t.b).cwiseMax(t.c);
    lo = lo.cwiseMin(t.lo), hi = hi.cwiseMax(t.hi);
    tris.push_back(t);
  }
  const double diag = (hi - lo).norm();
  double worst = 0.0;
  int worstVertex = -1;
  for (size_t i = 0; i < mst.vert.size(); ++i) {
    if (mst.vert[i].IsD()) continue;
    const Vec3 p = pos(mst.vert[i]);
    double best = std::numeric_limits<double>::max();
    for (const Tri& t : tris) {
      const Vec3 out = (t.lo - p).cwiseMax(p - t.hi).cwiseMax(Vec3::Zero());
      if (out.squaredNorm() >= best) continue;
      best = std::min(best, pointTriangle2(p, t.a, t.b, t.c));
    }
    if (std::sqrt(best) > worst) worst = std::sqrt(best), worstVertex = static_cast<int>(i);
  }
  const double rel = diag > 0 ? worst / diag : worst;
  const bool on = rel <= tol;
  std::printf("%s mst on target: largest vertex distance %.3g = %.3g of the target bbox diagonal (vertex %d; limit %.3g)\n",
              on ? "ok  " : "FAIL", worst, rel, worstVertex, tol);
  return ok && on ? 0 : 1;
}

std::set<std::array<int, 3>> faceColours(const cbd::Mesh& m) {
  std::set<std::array<int, 3>> s;
  for (const auto& f : m.face)
    if (!f.IsD()) s.insert({f.cC()[0], f.cC()[1], f.cC()[2]});
  return s;
}

int checkColours(const char* a, const char* b, int count) {
  cbd::Mesh ma, mb;
  if (!load(a, ma) || !load(b, mb)) return 2;
  const auto ca = faceColours(ma), cb = faceColours(mb);
  const bool same = ca == cb, size = static_cast<int>(ca.size()) == count;
  std::printf("%s colours: %zu distinct face colours in '%s', %zu in '%s', %s (expected %d)\n",
              same && size ? "ok  " : "FAIL", ca.size(), a, cb.size(), b, same ? "the same set" : "different sets",
              count);
  return same && size ? 0 : 1;
}

int checkCounts(const char* path, int vertices, int faces) {
  cbd::Mesh m;
  if (!load(path, m)) return 2;
  const bool ok = m.vn == vertices && (faces < 0 || m.fn == faces);
  std::printf("%s counts: '%s' has %d vertices, %d faces\n", ok ? "ok  " : "FAIL", path, m.vn, m.fn);
  return ok ? 0 : 1;
}

int usage() {
  std::fprintf(stderr,
               "usage: plugin_check mst MST TARGET VERTICES TOL\n"
               "       plugin_check colours A B COUNT\n"
               "       plugin_check counts FILE VERTICES [FACES]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string cmd = argv[1];
  if (cmd == "mst" && argc == 6) return checkMst(argv[2], argv[3], std::atoi(argv[4]), std::atof(argv[5]));
  if (cmd == "colours" && argc == 5) return checkColours(argv[2], argv[3], std::atoi(argv[4]));
  if (cmd == "counts" && (argc == 4 || argc == 5))
    return checkCounts(argv[2], std::atoi(argv[3]), argc == 5 ? std::atoi(argv[4]) : -1);
  return usage();
}
