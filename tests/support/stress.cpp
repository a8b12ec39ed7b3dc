#include "support/stress.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "cbd/anchor_sampling.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

namespace cbd::stress {
namespace {

std::vector<int> nearestMap(const IndexedMesh& from, const IndexedMesh& to) {
  std::vector<int> out(from.vertexCount());
  for (int v = 0; v < from.vertexCount(); ++v) {
    int best = 0;
    for (int w = 1; w < to.vertexCount(); ++w)
      if ((to.positions[w] - from.positions[v]).squaredNorm() < (to.positions[best] - from.positions[v]).squaredNorm()) best = w;
    out[v] = best;
  }
  return out;
}

}  // namespace

SyntheticPair makePair(int genus) {
  SyntheticPair p;
  p.genus = genus;
  IndexedMesh tu;
  if (genus == 0) {
    p.name = "sphere -> bumpy ellipsoid";
    p.source = fixtures::icosphere(3);
    tu = fixtures::icosphere(4);
    p.targetOf = nearestMap(p.source, tu);
    p.target = tu;
    for (auto& q : p.target.positions)
      q = Vec3(1.8 * q.x(), q.y(), 0.7 * q.z()) * (1.0 + 0.12 * std::sin(5 * q.x()) * std::cos(4 * q.y()));
  } else if (genus == 1) {
    p.name = "torus -> twisted bumpy torus";
    const double R = 2.0, r = 0.7;
    p.source = fixtures::torus(R, r, 48, 20);
    tu = fixtures::torus(R, r, 60, 24);
    p.targetOf = nearestMap(p.source, tu);
    p.target = tu;
    for (auto& q : p.target.positions) {
      const double u = std::atan2(q.y(), q.x());
      const Vec3 c(R * std::cos(u), R * std::sin(u), 0), radial(std::cos(u), std::sin(u), 0), up(0, 0, 1);
      const Vec3 d = q - c;
      const double a = d.dot(radial), b = d.dot(up), tw = 0.8 * std::sin(u), bump = 1.0 + 0.25 * std::sin(3 * u);  // periodic: no seam
      q = c + bump * ((a * std::cos(tw) - b * std::sin(tw)) * radial + (a * std::sin(tw) + b * std::cos(tw)) * up);
    }
  } else {
    p.name = "double torus -> bent double torus";
    p.source = fixtures::holedPlate(2, 3, 15);
    tu = fixtures::holedPlate(2, 4, 15);
    p.targetOf = nearestMap(p.source, tu);
    p.target = tu;
    for (auto& q : p.target.positions) {
      const double ang = 0.35 * q.y();
      q = Vec3(q.x(), (2.0 + q.z()) * std::sin(ang), (2.0 + 1.5 * q.z()) * std::cos(ang));
    }
  }
  return p;
}

std::vector<int> randomAnchors(const IndexedMesh& mesh, int count, unsigned seed, bool farthest) {
  std::mt19937 rng(seed);
  if (farthest) return farthestPointSampling(mesh, count, static_cast<int>(rng() % mesh.vertexCount()));
  std::vector<int> all(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) all[v] = v;
  std::shuffle(all.begin(), all.end(), rng);
  all.resize(std::min<size_t>(all.size(), static_cast<size_t>(count)));
  return all;
}

Outcome run(const SyntheticPair& pair, const std::vector<int>& sa, LayoutMethod method) {
  Outcome o;
  std::vector<int> ta;
  for (int v : sa) ta.push_back(pair.targetOf[v]);
  // Distinct target anchors are needed: the nearest-vertex map may merge two.
  std::vector<int> sorted = ta;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    o.code = ErrorCode::AnchorsShareVertex;
    o.message = "two anchors map to one target vertex";
    return o;
  }
  CrossParameterizationOptions options;
  options.method = method;
  const int euler = 2 - 2 * pair.genus;
  const CrossParameterizationResult r = crossParameterize(pair.source, sa, pair.target, ta, euler, options);
  o.ok = r.status.ok();
  o.code = r.status.code;
  o.message = r.status.message;
  if (!o.ok) return o;
  o.flipped = r.metrics.flipped;
  bool inv = validateLayout(r.layouts.source, euler).status.ok() && validateLayout(r.layouts.target, euler).status.ok() &&
             checkIsomorphic(r.layouts.source, r.layouts.target).ok();
  for (size_t k = 0; k < sa.size() && inv; ++k) inv = (r.map.sourceImage[sa[k]] - pair.target.positions[ta[k]]).norm() < 1e-9;
  for (int v = 0; v < pair.source.vertexCount() && inv; ++v) {
    const FacePoint& fp = r.map.sourceToTarget[v];
    inv = fp.face >= 0 && fp.bary.minCoeff() > -1e-9 && std::abs(fp.bary.sum() - 1.0) < 1e-9;
  }
  o.invariantsHold = inv;
  return o;
}

}  // namespace cbd::stress
