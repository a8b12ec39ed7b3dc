#include "cbd/parameterization.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <mutex>
#include <string>
#include <cmath>
#include <functional>
#include <thread>
#include <unordered_map>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

namespace cbd {

Vec2 domainCorner(int k) {
  static const Vec2 c[3] = {Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(0.5, std::sqrt(3.0) / 2.0)};
  return c[k % 3];
}

namespace {

/// Per vertex: the layout edge it lies on (-1 off paths, -2 an anchor) and its arc-length
/// fraction from the edge's anchor `a`.
struct PathPosition {
  std::vector<int> edge;
  std::vector<double> fraction;
};

PathPosition pathPositions(const Layout& L) {
  PathPosition pp;
  pp.edge.assign(L.mesh.vertexCount(), -1);
  pp.fraction.assign(L.mesh.vertexCount(), 0.0);
  for (int v : L.anchorVertices) pp.edge[v] = -2;
  for (size_t e = 0; e < L.edges.size(); ++e) {
    const auto& c = L.edges[e].vertices;
    const std::vector<double> f = chainFractions(L.mesh, c);
    for (size_t k = 1; k + 1 < c.size(); ++k) {
      pp.edge[c[k]] = static_cast<int>(e);
      pp.fraction[c[k]] = f[k];
    }
  }
  return pp;
}

/// Where vertex v of a face of patch p lands on the boundary of the domain triangle, or false
/// for an interior vertex.
bool boundaryUV(const Layout& L, const PathPosition& pp, const Patch& patch, int v, Vec2& uv) {
  const int on = pp.edge[v];
  if (on == -1) return false;
  if (on == -2) {
    for (int k = 0; k < 3; ++k)
      if (L.anchorVertices[patch.corners[k]] == v) {
        uv = domainCorner(k);
        return true;
      }
    return false;  // an anchor inside the patch cannot happen in a valid layout
  }
  for (int k = 0; k < 3; ++k) {
    if (patch.edges[k] != on) continue;
    const double s = patch.forward[k] ? pp.fraction[v] : 1.0 - pp.fraction[v];
    uv = (1.0 - s) * domainCorner(k) + s * domainCorner(k + 1);
    return true;
  }
  return false;
}

}  // namespace

int splitCollinearFaces(Layout& L) {
  int splits = 0;
  for (bool changed = true; changed;) {
    changed = false;
    const PathPosition pp = pathPositions(L);
    const int nf = L.mesh.faceCount();
    for (int f = 0; f < nf; ++f) {
      const auto v = L.mesh.faceVertices(f);
      const Patch& patch = L.patches[L.facePatch[f]];
      // All three corners on one side of the patch (anchors count for both their sides)?
      bool collinear = false;
      for (int k = 0; k < 3 && !collinear; ++k) {
        const int e = patch.edges[k];
        const int a = L.anchorVertices[L.edges[e].a], b = L.anchorVertices[L.edges[e].b];
        collinear = true;
        for (int x : v) collinear = collinear && (pp.edge[x] == e || x == a || x == b);
      }
      if (!collinear) continue;
      // Split the longest edge of the face that is not on a path: it gains an interior vertex.
      int best = -1;
      double bestLen = -1;
      for (int k = 0, h = L.mesh.faceHalfedge(f); k < 3; ++k, h = L.mesh.next(h)) {
        const int e = RefinedMesh::edgeOf(h);
        if (L.edgePath[e] >= 0) continue;
        if (L.mesh.edgeLength(e) > bestLen) bestLen = L.mesh.edgeLength(e), best = h;
      }
      if (best < 0) continue;
      const int pa = L.facePatch[L.mesh.face(best)], pb = L.facePatch[L.mesh.face(RefinedMesh::twin(best))];
      L.mesh.splitEdge(best, 0.5);
      const auto& rec = L.mesh.lastSplit();
      L.edgePath.resize(L.mesh.edgeCount(), -1);
      L.facePatch.resize(L.mesh.faceCount(), -1);
      L.facePatch[rec.faceNewA] = pa;
      L.facePatch[rec.faceNewB] = pb;
      if (!L.faceCluster.empty()) {
        L.faceCluster.resize(L.mesh.faceCount(), -1);
        L.faceCluster[rec.faceNewA] = L.faceCluster[L.mesh.face(best)];
        L.faceCluster[rec.faceNewB] = L.faceCluster[L.mesh.face(RefinedMesh::twin(best))];
      }
      ++splits;
      changed = true;
      break;  // path positions changed: recompute
    }
  }
  for (Patch& p : L.patches) p.faces = 0;
  for (int p : L.facePatch) ++L.patches[p].faces;
  return splits;
}

bool meanValueMap(const RefinedMesh& mesh, const std::vector<int>& faces,
                  const std::function<bool(int, int, Vec2&)>& fixedAt, std::vector<std::array<Vec2, 3>>& uv,
                  int* unknowns) {
  std::unordered_map<int, int> index;  // free vertex -> unknown
  std::unordered_map<int, char> isFixed;
  for (int f : faces) {
    const auto v = mesh.faceVertices(f);
    for (int k = 0; k < 3; ++k) {
      if (index.count(v[k]) || isFixed.count(v[k])) continue;
      Vec2 at = Vec2::Zero();
      if (fixedAt(f, k, at)) isFixed.emplace(v[k], 1);
      else index.emplace(v[k], static_cast<int>(index.size()));
    }
  }
  const int n = static_cast<int>(index.size());
  if (unknowns) *unknowns = n;
  std::vector<Vec2> solved(n);
  if (n > 0) {
    // Mean-value weights (Floater 2003): w_ij = (tan(a1/2) + tan(a2/2)) / |v_i - v_j|. A vertex
    // with a zero or non-finite weight (a zero angle or a zero-length edge: degenerate faces,
    // which edge splits along many paths can leave) takes uniform weights instead. Every row then
    // has positive weights, which is all Floater's bijectivity theorem asks of a row.
    struct Term {
      int i;
      int j;   // unknown, or -1: fixed at `at`
      double weight;
      Vec2 at;
    };
    std::vector<Term> terms;
    std::vector<char> uniform(n, 0);
    for (int f : faces) {
      const auto v = mesh.faceVertices(f);
      for (int k = 0; k < 3; ++k) {
        auto it = index.find(v[k]);
        if (it == index.end()) continue;
        const int i = it->second;
        const Vec3 &pi = mesh.position(v[k]), &pj = mesh.position(v[(k + 1) % 3]), &pk = mesh.position(v[(k + 2) % 3]);
        const Vec3 ej = pj - pi, ek = pk - pi;
        const double angle = std::atan2(ej.cross(ek).norm(), ej.dot(ek));
        const double t = std::tan(0.5 * angle);
        for (int side = 1; side <= 2; ++side) {
          const int w = v[(k + side) % 3];
          const double weight = t / (mesh.position(w) - pi).norm();
          if (!(weight > 0.0) || !std::isfinite(weight)) uniform[i] = 1;
          Term term{i, -1, weight, Vec2::Zero()};
          auto jt = index.find(w);
          if (jt != index.end()) term.j = jt->second;
          else if (!fixedAt(f, (k + side) % 3, term.at)) return false;  // fixed at one corner, free at another
          terms.push_back(term);
        }
      }
    }
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
    std::vector<double> diag(n, 0.0);
    for (const Term& term : terms) {
      const double weight = uniform[term.i] ? 1.0 : term.weight;
      diag[term.i] += weight;
      if (term.j >= 0) trip.emplace_back(term.i, term.j, -weight);
      else rhs.row(term.i) += weight * term.at.transpose();
    }
    for (int i = 0; i < n; ++i) trip.emplace_back(i, i, diag[i]);
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(trip.begin(), trip.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success) return false;
    const Eigen::MatrixXd x = lu.solve(rhs);
    for (int i = 0; i < n; ++i) solved[i] = Vec2(x(i, 0), x(i, 1));
  }
  uv.assign(faces.size(), {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()});
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto v = mesh.faceVertices(faces[i]);
    for (int k = 0; k < 3; ++k) {
      auto it = index.find(v[k]);
      if (it != index.end()) uv[i][k] = solved[it->second];
      else if (!fixedAt(faces[i], k, uv[i][k])) return false;
    }
  }
  return true;
}

PatchParameterization parameterizePatches(const Layout& L, const ParameterizationOptions& options,
                                          const Progress& progress) {
  PatchParameterization out;
  const int nf = L.mesh.faceCount();
  out.cornerUV.assign(nf, {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()});
  const PathPosition pp = pathPositions(L);
  std::vector<std::vector<int>> facesOf(L.patches.size());
  for (int f = 0; f < nf; ++f) facesOf[L.facePatch[f]].push_back(f);

  std::atomic<int> next{0}, interior{0};
  std::atomic<bool> failed{false};
  std::string error;
  std::mutex errorMutex;
  auto work = [&] {
    for (int p; (p = next++) < static_cast<int>(L.patches.size());) {
      if (!progress.report(static_cast<double>(p) / L.patches.size(), "mapping the patches")) {
        failed = true;
        continue;
      }
      const Patch& patch = L.patches[p];
      std::vector<std::array<Vec2, 3>> uv;
      int n = 0;
      const bool ok = meanValueMap(
          L.mesh, facesOf[p],
          [&](int f, int k, Vec2& at) { return boundaryUV(L, pp, patch, L.mesh.faceVertices(f)[k], at); }, uv, &n);
      if (!ok) {
        std::lock_guard<std::mutex> lock(errorMutex);
        failed = true;
        error = "the mean-value system of patch " + std::to_string(p) + " is singular";
        continue;
      }
      interior += n;
      for (size_t i = 0; i < facesOf[p].size(); ++i) out.cornerUV[facesOf[p][i]] = uv[i];
    }
  };
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min<int>(threads, static_cast<int>(L.patches.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  out.interiorVertices = interior;
  if (failed)
    out.status = progress.cancelled() ? Status::error(ErrorCode::Cancelled, "cancelled while mapping the patches")
                                      : Status::error(ErrorCode::InternalError, error);
  return out;
}

namespace {

/// Grid-indexed point location among the faces of one patch in the domain triangle.
class GridLocator {
 public:
  GridLocator(const std::vector<int>& faces, const std::vector<std::array<Vec2, 3>>& uv) : uv_(uv) {
    n_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(faces.size()))));
    // A face is listed in every cell its bounding box meets. In a sound parameterization that is
    // a few cells per face; faces spanning much of the domain (patches whose two surfaces
    // disagree wildly: anchors that do not correspond) would make it faces x cells, gigabytes.
    // Then the grid is coarsened until the lists fit the budget: slower queries, bounded memory.
    const double budget = 64.0 * static_cast<double>(faces.size()) + 65536.0;
    auto entries = [&] {
      double total = 0;
      for (int f : faces) {
        const auto [x0, y0, x1, y1] = cellRange(uv[f]);
        total += static_cast<double>(x1 - x0 + 1) * (y1 - y0 + 1);
      }
      return total;
    };
    while (n_ > 1 && entries() > budget) n_ = std::max(1, n_ / 2);
    cells_.assign(static_cast<size_t>(n_) * n_, {});
    for (int f : faces) {
      const auto [x0, y0, x1, y1] = cellRange(uv[f]);
      for (int x = x0; x <= x1; ++x)
        for (int y = y0; y <= y1; ++y) cells_[static_cast<size_t>(y) * n_ + x].push_back(f);
    }
  }
  /// The face holding p and its barycentric coordinates (best effort at the domain's edges).
  bool locate(const Vec2& p, int& face, Vec3& bary) const {
    double best = -1e300;
    const auto [cx, cy] = cell(p);
    for (int ring = 0; ring <= n_ && best < -1e-12; ++ring) {
      for (int x = cx - ring; x <= cx + ring; ++x)
        for (int y = cy - ring; y <= cy + ring; ++y) {
          if (x < 0 || y < 0 || x >= n_ || y >= n_) continue;
          if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
          for (int f : cells_[static_cast<size_t>(y) * n_ + x]) {
            const Vec3 b = barycentric(p, uv_[f]);
            const double m = b.minCoeff();
            if (m > best) best = m, face = f, bary = b;
          }
        }
      if (ring >= 1 && best > -1e-6) break;
    }
    if (best < -1e-6) return false;
    bary = bary.cwiseMax(0.0);
    bary /= bary.sum();
    // A point on a vertex of the face (an anchor at a domain corner) lands exactly on it.
    for (int k = 0; k < 3; ++k)
      if (bary[k] > 1.0 - 1e-12) bary = Vec3::Unit(k);
    return true;
  }

 private:
  static Vec3 barycentric(const Vec2& p, const std::array<Vec2, 3>& t) {
    const Vec2 a = t[1] - t[0], b = t[2] - t[0], c = p - t[0];
    const double det = a.x() * b.y() - a.y() * b.x();
    if (std::abs(det) < 1e-300) return Vec3(-1e300, -1e300, -1e300);
    const double u = (c.x() * b.y() - c.y() * b.x()) / det, v = (a.x() * c.y() - a.y() * c.x()) / det;
    return Vec3(1.0 - u - v, u, v);
  }
  std::pair<int, int> cell(const Vec2& p) const {
    auto clampi = [&](double t) { return std::clamp(static_cast<int>(std::floor(t * n_)), 0, n_ - 1); };
    return {clampi(p.x()), clampi(p.y() / (std::sqrt(3.0) / 2.0))};
  }
  /// The cells (x0, y0, x1, y1, inclusive) the bounding box of triangle t meets.
  std::array<int, 4> cellRange(const std::array<Vec2, 3>& t) const {
    Vec2 lo = t[0], hi = lo;
    for (const Vec2& p : t) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const auto [x0, y0] = cell(lo);
    const auto [x1, y1] = cell(hi);
    return {x0, y0, x1, y1};
  }
  const std::vector<std::array<Vec2, 3>>& uv_;
  int n_ = 1;
  std::vector<std::vector<int>> cells_;
};

}  // namespace

struct PatchLocator::Grid {
  std::vector<int> faces;
  GridLocator locator;
  Grid(std::vector<int> f, const std::vector<std::array<Vec2, 3>>& uv) : faces(std::move(f)), locator(faces, uv) {}
};

PatchLocator::PatchLocator(const Layout& layout, const PatchParameterization& param) {
  std::vector<std::vector<int>> facesOf(layout.patches.size());
  for (int f = 0; f < layout.mesh.faceCount(); ++f) facesOf[layout.facePatch[f]].push_back(f);
  for (auto& faces : facesOf) grids_.push_back(new Grid(std::move(faces), param.cornerUV));
}

PatchLocator::~PatchLocator() {
  for (Grid* g : grids_) delete g;
}

bool PatchLocator::locate(int patch, const Vec2& uv, int& face, Vec3& bary) const {
  return grids_[patch]->locator.locate(uv, face, bary);
}

namespace {

/// Map the input vertices of `from` through the domain onto `to`.
Status mapVertices(const Layout& from, const PatchParameterization& fromParam, const Layout& to,
                   const PatchParameterization& toParam, std::vector<FacePoint>& points, std::vector<Vec3>& image) {
  const PatchLocator locator(to, toParam);
  const int nv = from.mesh.inputVertexCount();
  points.assign(nv, FacePoint{});
  image.resize(nv);
  for (int v = 0; v < nv; ++v) {
    image[v] = from.mesh.position(v);
    const int h = from.mesh.outgoing(v);
    if (h < 0) continue;  // unreferenced
    const int f = from.mesh.face(h);
    const auto corners = from.mesh.faceVertices(f);
    const int c = static_cast<int>(std::find(corners.begin(), corners.end(), v) - corners.begin());
    const Vec2 uv = fromParam.cornerUV[f][c];
    int g = -1;
    Vec3 b;
    if (!locator.locate(from.facePatch[f], uv, g, b))
      return Status::error(ErrorCode::InternalError, "point location failed for vertex " + std::to_string(v));
    const auto tv = to.mesh.faceVertices(g);
    image[v] = b[0] * to.mesh.position(tv[0]) + b[1] * to.mesh.position(tv[1]) + b[2] * to.mesh.position(tv[2]);
    FacePoint fp;
    fp.face = to.mesh.inputFace(g);
    for (int k = 0; k < 3; ++k) fp.bary += b[k] * to.mesh.baryIn(tv[k], fp.face);
    points[v] = fp;
  }
  return Status::success();
}

}  // namespace

CrossMap composeCrossMap(const Layout& source, const PatchParameterization& sp, const Layout& target,
                         const PatchParameterization& tp) {
  CrossMap m;
  if (source.patches.size() != target.patches.size()) {
    m.status = Status::error(ErrorCode::InternalError, "the layouts have different patch counts");
    return m;
  }
  m.status = mapVertices(source, sp, target, tp, m.sourceToTarget, m.sourceImage);
  if (m.status) m.status = mapVertices(target, tp, source, sp, m.targetToSource, m.targetImage);
  return m;
}

}  // namespace cbd
