#include "cbd/map_optimization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace cbd {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat2 = Eigen::Matrix2d;
using Mat32 = Eigen::Matrix<double, 3, 2>;
constexpr double kInf = std::numeric_limits<double>::infinity();

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// A triangle's energy as a function of the ratio d of its image's area to its own and the
/// squared Frobenius norm F of its map: e = F a(d) + b(d); a1, a2, b1, b2 the derivatives in d.
struct Shape {
  double a = 0, a1 = 0, a2 = 0, b = 0, b1 = 0, b2 = 0;
};

/// Symmetric Dirichlet F (1 + 1/d^2) plus w times the conformal energy F / (2d); +inf for d <= 0.
Shape distortionShape(double d, double w) {
  if (d <= 0) return {kInf, 0, 0, 0, 0, 0};
  const double i = 1.0 / d, i2 = i * i;
  return {1.0 + i2 + 0.5 * w * i, -2.0 * i2 * i - 0.5 * w * i2, 6.0 * i2 * i2 + w * i2 * i, 0, 0, 0};
}

/// The distortion term of one source triangle (area `area`, frame S, q = S^-1 S^-T): its map M onto
/// its image, the triangle through its corners' images p[k] (d p_k / d x_k = G[k]), with
/// F = c2 |M|^2 (c2 scales both surfaces to one area) and d = c2 rho A / (2 area): A twice its
/// area in D (corners X[k] = R[k] x_k + t_k), rho the target's area per area of D there (the mean
/// of its corners', rhoSlope[k] = d rho_k / d x_k). So d is the image's area ratio as the target's
/// parameterization sees it: signed by D's orientation, vanishing as the face degenerates in D.
/// Fills the gradient and a positive semi-definite Hessian: through F's and d's first derivatives,
/// their 2 x 2 coefficient matrix projected onto the positive semi-definite cone. Returns d.
template <class ShapeOf>
double distortionTerm(const Vec3 p[3], const Mat32 G[3], const Vec2 X[3], const Mat2 R[3], const bool free[3],
                      const double rho[3], const Vec2 rhoSlope[3], const Mat2& q, double c2, double area, double weight,
                      const ShapeOf& shapeOf, bool derivatives, double& e, Vec6& g, Mat6& H) {
  const Vec3 E1 = p[1] - p[0], E2 = p[2] - p[0];
  const Vec2 P = X[1] - X[0], Q = X[2] - X[0];
  const double F = c2 * (q(0, 0) * E1.squaredNorm() + 2 * q(0, 1) * E1.dot(E2) + q(1, 1) * E2.squaredNorm());
  const double A = cross2(P, Q), r = (rho[0] + rho[1] + rho[2]) / 3.0, k = c2 / (2 * area);
  const Vec3 cc = E1.cross(E2);
  const double dc = k * cc.norm(), dd = k * r * A, d = dd > 0 ? std::sqrt(dc * dd) : dd;
  const Shape s = shapeOf(d);
  e = weight * (F * s.a + s.b);
  if (!derivatives) return d;
  g.setZero();
  H.setZero();
  if (!std::isfinite(e)) return d;
  Mat6 Z = Mat6::Zero();  // d (E1, E2) / d (x0, x1, x2)
  Z.block<3, 2>(0, 0) = Z.block<3, 2>(3, 0) = -G[0];
  Z.block<3, 2>(0, 2) = G[1];
  Z.block<3, 2>(3, 4) = G[2];
  Vec6 gE;
  gE << 2 * c2 * (q(0, 0) * E1 + q(0, 1) * E2), 2 * c2 * (q(0, 1) * E1 + q(1, 1) * E2);
  const Vec2 dA[3] = {Vec2(P.y() - Q.y(), Q.x() - P.x()), Vec2(Q.y(), -Q.x()), Vec2(-P.y(), P.x())};
  Eigen::Matrix<double, 6, 2> B;
  B.col(0) = Z.transpose() * gE;
  for (int c = 0; c < 3; ++c)
    B.col(1).segment<2>(2 * c) = free[c] ? Vec2(k * (r * R[c].transpose() * dA[c] + A / 3.0 * rhoSlope[c])) : Vec2::Zero();
  {  // d = sqrt(dc dd): d' = (dd dc' + dc dd') / (2 d)
    const Vec3 u = cc / cc.norm();
    Vec6 gc;
    gc << k * E2.cross(u), k * u.cross(E1);
    B.col(1) = (dd * Z.transpose() * gc + dc * B.col(1)) / (2 * d);
  }
  g = weight * B * Vec2(s.a, F * s.a1 + s.b1);
  Mat2 M;
  M << 0, s.a1, s.a1, F * s.a2 + s.b2;
  const Eigen::SelfAdjointEigenSolver<Mat2> es(M);
  M = es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).asDiagonal() * es.eigenvectors().transpose();
  Mat6 HF = Mat6::Zero();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) HF.block<3, 3>(3 * i, 3 * j) = 2 * c2 * q(i, j) * Eigen::Matrix3d::Identity();
  H = weight * (s.a * Z.transpose() * HF * Z + B * M * B.transpose());
  return d;
}

/// Run fn(begin, end, block) over [0, n) in at most `threads` contiguous blocks.
template <class Fn>
void parallelFor(int n, int threads, const Fn& fn) {
  threads = std::max(1, std::min(threads, n / 256 + 1));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back([&, t] { fn(n * t / threads, n * (t + 1) / threads, t); });
  fn(0, n / threads, 0);
  for (auto& th : pool) th.join();
}

/// The first t > 0 where a t^2 + b t + c (c > 0) reaches zero; +inf when it never does.
double smallestPositiveRoot(double a, double b, double c) {
  if (std::abs(a) < 1e-300) return b < 0 ? -c / b : kInf;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return kInf;
  const double s = std::sqrt(disc), q = -0.5 * (b + (b < 0 ? -s : s));
  double r = kInf;
  for (double root : {q / a, q != 0 ? c / q : kInf})
    if (root > 0) r = std::min(r, root);
  return r;
}

/// A sparse Cholesky solver that analyses the matrix's pattern once and factorizes every matrix
/// of that pattern after.
class SparseCholesky {
 public:
  void reset() { analysed_ = -1; }
  bool solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    if (analysed_ != A.nonZeros()) {
      ldlt_.analyzePattern(A);
      analysed_ = A.nonZeros();
    }
    ldlt_.factorize(A);
    if (ldlt_.info() != Eigen::Success) return false;
    x = ldlt_.solve(b);
    return x.allFinite();
  }

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  long analysed_ = -1;
};

/// The map (every vertex of the source's refined mesh at a point of D, every face's chart maps,
/// where each vertex lies on the target) and the Newton iteration on it.
class Optimizer {
 public:
  Optimizer(const SurfaceInDomain& sourceInD, const IndexedMesh& T, const SurfaceInDomain& targetInD,
            const BaseDomain& D, const MapOptimizationOptions& o)
      : S_(sourceInD.layout().mesh.toIndexed()), targetInD_(targetInD), D_(D), o_(o) {
    threads_ = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int nv = S_.vertexCount(), nf = S_.faceCount();
    std::vector<char> fixed(nv, 0);
    for (int a : sourceInD.layout().anchorVertices) fixed[a] = 1;
    pt.resize(nv);
    hit.resize(nv);
    var_.assign(nv, -1);
    for (int v = 0; v < nv; ++v) {
      pt[v] = sourceInD.vertexPoint(v);
      if (pt[v].patch >= 0 && !fixed[v]) var_[v] = unknowns_++;
    }
    chart = sourceInD.faceCharts();
    q_.resize(nf);
    area_.resize(nf);
    for (int f = 0; f < nf; ++f) {
      const auto& t = S_.faces[f];
      const Vec3 e1 = S_.positions[t[1]] - S_.positions[t[0]], e2 = S_.positions[t[2]] - S_.positions[t[0]];
      const Vec3 x = e1.normalized(), y = e1.cross(e2).cross(e1).normalized();
      Mat2 frame;
      frame << e1.norm(), e2.dot(x), 0, e2.dot(y);
      const Mat2 inv = frame.inverse();
      q_[f] = inv * inv.transpose();
      area_[f] = 0.5 * e1.cross(e2).norm();
      areaS_ += area_[f];
    }
    c2_ = areaS_ / surfaceArea(T);
    incidentBegin_.assign(nv + 1, 0);
    for (const auto& t : S_.faces)
      for (int v : t) ++incidentBegin_[v + 1];
    for (int v = 0; v < nv; ++v) incidentBegin_[v + 1] += incidentBegin_[v];
    incident_.resize(incidentBegin_[nv]);
    std::vector<int> fill(incidentBegin_.begin(), incidentBegin_.end() - 1);
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) incident_[fill[S_.faces[f][k]]++] = 3 * f + k;
    buildPattern();
  }

  const IndexedMesh& mesh() const { return S_; }

  /// Corner k of face f in the face's chart; twice the face's signed area in D.
  Vec2 corner(int f, int k) const { return chart[f][k].apply(pt[S_.faces[f][k]].uv); }
  double areaInD(int f) const { return cross2(corner(f, 1) - corner(f, 0), corner(f, 2) - corner(f, 0)); }

  /// Locate every vertex on the target; false when a point of D lies on no target face.
  bool locateAll() {
    bool ok = true;
    for (size_t v = 0; v < pt.size(); ++v)
      if (pt[v].patch >= 0) ok = targetInD_.locate(pt[v], hit[v]) && ok;
    return ok;
  }

  /// Face f's term with its corners at `x` (each in the frame of pt[v].patch) and `hits` on the
  /// target; +inf when its area in D is not positive.
  double face(int f, const std::vector<Vec2>& x, const std::vector<SurfaceInDomain::Hit>& hits, bool derivatives,
              Vec6& g, Mat6& H) const {
    const auto& t = S_.faces[f];
    Vec3 p[3];
    Mat32 G[3];
    Vec2 X[3], rhoSlope[3];
    Mat2 R[3];
    bool free[3];
    double rho[3];
    for (int k = 0; k < 3; ++k) {
      const int v = t[k];
      free[k] = var_[v] >= 0;
      p[k] = hits[v].position;
      G[k] = free[k] ? hits[v].jacobian : Mat32::Zero();
      R[k] = chart[f][k].linear();
      X[k] = chart[f][k].apply(x[v]);
      rho[k] = hits[v].density;
      rhoSlope[k] = hits[v].densitySlope;
    }
    double e;
    auto shape = [&](double s) { return distortionShape(s, o_.conformalWeight); };
    distortionTerm(p, G, X, R, free, rho, rhoSlope, q_[f], c2_, area_[f], area_[f] / areaS_, shape, derivatives, e,
                   g, H);
    return e;
  }

  /// Total energy at vertex positions x with images hits.
  double energy(const std::vector<Vec2>& x, const std::vector<SurfaceInDomain::Hit>& hits) const {
    std::vector<double> part(threads_, 0.0);
    parallelFor(S_.faceCount(), threads_, [&](int b, int end, int slot) {
      Vec6 g;
      Mat6 H;
      for (int f = b; f < end; ++f) part[slot] += face(f, x, hits, false, g, H);
    });
    double sum = 0;
    for (double e : part) sum += e;
    return sum;
  }

  std::vector<Vec2> positions() const {
    std::vector<Vec2> x(pt.size());
    for (size_t v = 0; v < pt.size(); ++v) x[v] = pt[v].uv;
    return x;
  }

  /// One iteration; E is the energy before and after. Returns what took the step: a Newton step,
  /// one with the vertices on kinks held, a diagonally scaled gradient step, or none.
  enum class Step { Newton, Held, Gradient, None };
  Step step(double& E) {
    const int nf = S_.faceCount(), n2 = 2 * unknowns_;
    std::vector<Vec6> g(nf);
    std::vector<Mat6> H(nf);
    const std::vector<Vec2> x = positions();
    parallelFor(nf, threads_, [&](int b, int end, int) {
      for (int f = b; f < end; ++f) face(f, x, hit, true, g[f], H[f]);
    });
    Eigen::VectorXd grad = Eigen::VectorXd::Zero(n2);
    Eigen::SparseMatrix<double> A = pattern_;
    double* value = A.valuePtr();
    for (int f = 0; f < nf; ++f) {
      const auto& t = S_.faces[f];
      const int* slot = &slot_[static_cast<size_t>(f) * 36];
      for (int k = 0; k < 3; ++k) {
        if (var_[t[k]] < 0) continue;
        grad.segment<2>(2 * var_[t[k]]) += g[f].segment<2>(2 * k);
        for (int l = 0; l < 3; ++l)
          for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c)
              if (const int s = slot[(3 * k + l) * 4 + 2 * r + c]; s >= 0) value[s] += H[f](2 * k + r, 2 * l + c);
      }
    }
    std::vector<char> held(unknowns_, 0);
    if (lineSearch(E, A, grad, held, true)) return Step::Newton;
    // Where the energy has a kink (a vertex on an edge of the target's parameterization, whose
    // Jacobian jumps there) Newton's direction may climb: those vertices sit the step out.
    for (size_t v = 0; v < pt.size(); ++v)
      if (var_[v] >= 0 && hit[v].edgeCloseness < 1e-6) held[var_[v]] = 1;
    if (lineSearch(E, A, grad, held, true)) return Step::Held;
    return lineSearch(E, A, grad, held, false) ? Step::Gradient : Step::None;
  }

  std::vector<DomainPoint> pt;
  std::vector<SurfaceInDomain::Hit> hit;
  std::vector<std::array<ChartMap, 3>> chart;
  bool lastBounded = false;  ///< the last line search started below the full step, at the injectivity bound

 private:
  /// The Hessian's pattern over the free vertices (lower triangle and every diagonal entry) and,
  /// per face, where each entry of its 6 x 6 block goes (-1: a fixed corner or the upper triangle).
  void buildPattern() {
    const int nf = S_.faceCount(), n2 = 2 * unknowns_;
    std::vector<Eigen::Triplet<double>> trip;
    for (int i = 0; i < n2; ++i) trip.emplace_back(i, i, 0.0);
    for (const auto& t : S_.faces)
      for (int a : t)
        for (int b : t)
          if (var_[a] >= 0 && var_[b] >= 0)
            for (int r = 0; r < 2; ++r)
              for (int c = 0; c < 2; ++c)
                if (2 * var_[a] + r >= 2 * var_[b] + c) trip.emplace_back(2 * var_[a] + r, 2 * var_[b] + c, 0.0);
    pattern_.resize(n2, n2);
    pattern_.setFromTriplets(trip.begin(), trip.end());
    pattern_.makeCompressed();
    slot_.assign(static_cast<size_t>(nf) * 36, -1);
    const int* outer = pattern_.outerIndexPtr();
    const int* inner = pattern_.innerIndexPtr();
    for (int f = 0; f < nf; ++f) {
      const auto& t = S_.faces[f];
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          if (var_[t[k]] >= 0 && var_[t[l]] >= 0)
            for (int r = 0; r < 2; ++r)
              for (int c = 0; c < 2; ++c) {
                const int row = 2 * var_[t[k]] + r, col = 2 * var_[t[l]] + c;
                if (row >= col)
                  slot_[static_cast<size_t>(f) * 36 + (3 * k + l) * 4 + 2 * r + c] =
                      static_cast<int>(std::lower_bound(inner + outer[col], inner + outer[col + 1], row) - inner);
              }
    }
  }

  /// Solve for the step (Newton's, or the gradient scaled by the Hessian's diagonal) with the
  /// `held` unknowns fixed, then search along it: from 0.9 of the largest step before a face's
  /// area in D reaches zero (Smith & Schaefer 2015: each area is quadratic in the step), halving
  /// until the energy falls enough (Armijo).
  bool lineSearch(double& E, Eigen::SparseMatrix<double> A, Eigen::VectorXd grad, const std::vector<char>& held,
                  bool newton) {
    const double scale = A.diagonal().mean();
    for (int k = 0; k < A.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) {
        if (held[it.row() / 2] || held[it.col() / 2]) it.valueRef() = it.row() == it.col() ? scale : 0.0;
        if (it.row() == it.col()) it.valueRef() += 1e-9 * scale;  // positive definite
      }
    for (int i = 0; i < unknowns_; ++i)
      if (held[i]) grad.segment<2>(2 * i).setZero();
    Eigen::VectorXd dir;
    if (newton) {
      if (!solver_.solve(A, -grad, dir)) return false;
    } else {
      dir = -grad.cwiseQuotient(A.diagonal());
    }
    const double slope = grad.dot(dir);
    if (!(slope < 0)) return false;
    double tmax = kInf;
    for (int f = 0; f < S_.faceCount(); ++f) {
      Vec2 V[3];
      for (int k = 0; k < 3; ++k) {
        const int v = S_.faces[f][k];
        V[k] = var_[v] >= 0 ? Vec2(chart[f][k].linear() * dir.segment<2>(2 * var_[v])) : Vec2::Zero();
      }
      const Vec2 P = corner(f, 1) - corner(f, 0), Q = corner(f, 2) - corner(f, 0), U = V[1] - V[0], W = V[2] - V[0];
      tmax = std::min(tmax, smallestPositiveRoot(cross2(U, W), cross2(P, W) + cross2(U, Q), cross2(P, Q)));
    }
    std::vector<DomainPoint> trial(pt);
    std::vector<ChartMap> back(pt.size());
    std::vector<SurfaceInDomain::Hit> trialHit(hit);
    std::vector<Vec2> xt = positions();
    lastBounded = 0.9 * tmax < 1.0;
    for (double t = std::min(1.0, 0.9 * tmax); t > 1e-12 * std::min(1.0, tmax); t *= 0.5) {
      bool ok = true;
      for (size_t v = 0; v < pt.size() && ok; ++v) {
        if (var_[v] < 0) continue;
        const Vec2 dv = t * dir.segment<2>(2 * var_[v]);
        trial[v] = pt[v];
        xt[v] = pt[v].uv + dv;
        ok = D_.walk(trial[v], dv, &back[v]) && targetInD_.locate(trial[v], trialHit[v]);
      }
      if (!ok) continue;
      const double Et = energy(xt, trialHit);
      if (!(Et <= E + 1e-4 * t * slope)) continue;
      // Accepted: a vertex that walked into another patch takes its faces' chart maps along.
      for (size_t v = 0; v < pt.size(); ++v) {
        if (var_[v] < 0) continue;
        if (back[v] != ChartMap{})
          for (int i = incidentBegin_[v]; i < incidentBegin_[v + 1]; ++i) {
            ChartMap& m = chart[incident_[i] / 3][incident_[i] % 3];
            m = m * back[v];
          }
        pt[v] = trial[v];
        hit[v] = trialHit[v];
      }
      E = Et;
      return true;
    }
    return false;
  }

  const IndexedMesh S_;
  const SurfaceInDomain& targetInD_;
  const BaseDomain& D_;
  const MapOptimizationOptions& o_;
  int threads_ = 1, unknowns_ = 0;
  std::vector<int> var_, incidentBegin_, incident_, slot_;
  std::vector<double> area_;
  std::vector<Mat2> q_;
  double c2_ = 1, areaS_ = 0;
  Eigen::SparseMatrix<double> pattern_;
  SparseCholesky solver_;
};

}  // namespace

CrossMap optimizeCrossMap(const IndexedMesh& S, const IndexedMesh& T, const SurfaceInDomain& sourceInD,
                          const SurfaceInDomain& targetInD, const BaseDomain& D, const MapOptimizationOptions& o,
                          MapOptimizationResult& r, const Progress& progress) {
  r = MapOptimizationResult{};
  CrossMap map;
  auto fail = [&](ErrorCode code, const std::string& message) {
    r.status = map.status = Status::error(code, message);
    return map;
  };
  Optimizer opt(sourceInD, T, targetInD, D, o);
  const IndexedMesh& M = opt.mesh();
  for (int f = 0; f < M.faceCount(); ++f)
    if (opt.areaInD(f) <= 0) return fail(ErrorCode::InternalError, "the composed map is not injective in the base domain");
  if (!opt.locateAll()) return fail(ErrorCode::InternalError, "a point of the base domain is on no target face");
  double E = opt.energy(opt.positions(), opt.hit);
  r.energyBefore = E;
  while (r.iterations < o.maxIterations) {
    const double before = E;
    const Optimizer::Step s = opt.step(E);
    if (s == Optimizer::Step::None) {
      r.stop = MapOptimizationStop::NoDescent;
      break;
    }
    ++r.iterations;
    r.boundedSteps += opt.lastBounded;
    if (!progress.report(r.iterations / (r.iterations + 20.0), "optimizing the map"))
      return fail(ErrorCode::Cancelled, "cancelled while optimizing the map");
    if (s == Optimizer::Step::Newton && before - E < o.tolerance * before) {
      r.stop = MapOptimizationStop::Tolerance;
      // A small decrease after a step the bound cut short says the descent is held up by a face
      // about to degenerate, not that the gradient vanishes.
      r.converged = !opt.lastBounded;
      break;
    }
  }
  r.energyAfter = E;
  // The guard of the invariant: every area in D positive, the areas summing to D's.
  double covered = 0;
  int bad = 0;
  for (int f = 0; f < M.faceCount(); ++f) {
    bad += opt.areaInD(f) <= 0;
    covered += 0.5 * opt.areaInD(f);
  }
  r.injective = bad == 0 && std::abs(covered - D.area()) <= 1e-6 * D.area();
  if (!r.injective)
    return fail(ErrorCode::InternalError, "the optimized map is not injective in the base domain: " +
                                              counted(bad, "face", "faces") + " not positive");
  r.sourcePoints = opt.pt;
  r.sourceCharts = opt.chart;
  map.sourceToTarget.assign(S.vertexCount(), FacePoint{});
  map.sourceImage = S.positions;
  for (int v = 0; v < S.vertexCount(); ++v)  // input vertices come first in the refined mesh
    if (opt.pt[v].patch >= 0) map.sourceToTarget[v] = opt.hit[v].point, map.sourceImage[v] = opt.hit[v].position;
  // M_ts through D: each target vertex located among the source's faces, then on the input face
  // holding that face.
  const TrianglesInDomain inverse(D, M.faces, r.sourcePoints, r.sourceCharts);
  const RefinedMesh& refined = sourceInD.layout().mesh;
  map.targetToSource.assign(T.vertexCount(), FacePoint{});
  map.targetImage = T.positions;
  for (int w = 0; w < T.vertexCount(); ++w) {
    const DomainPoint p = targetInD.vertexPoint(w);
    FacePoint at;
    if (p.patch < 0) continue;
    if (!inverse.locate(p, at))
      return fail(ErrorCode::InternalError, "target vertex " + std::to_string(w) + " is on no source face in D");
    FacePoint& fp = map.targetToSource[w];
    fp.face = refined.inputFace(at.face);
    for (int k = 0; k < 3; ++k) fp.bary += at.bary[k] * refined.baryIn(M.faces[at.face][k], fp.face);
    const auto& t = S.faces[fp.face];
    map.targetImage[w] = fp.bary[0] * S.positions[t[0]] + fp.bary[1] * S.positions[t[1]] + fp.bary[2] * S.positions[t[2]];
  }
  progress.report(1.0, "optimizing the map");
  return map;
}

}  // namespace cbd
