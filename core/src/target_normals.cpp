#include "cbd/target_normals.h"

namespace cbd {

std::vector<Vec3> faceNormals(const IndexedMesh& m) {
  std::vector<Vec3> n(m.faceCount(), Vec3::Zero());
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    const Vec3 c = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    const double l = c.norm();
    if (l > 0) n[f] = c / l;
  }
  return n;
}

TargetNormals::TargetNormals(const IndexedMesh& target) : mesh_(target), normal_(cbd::faceNormals(target)) {
  const int nv = target.vertexCount();
  starBegin_.assign(nv + 1, 0);
  for (const auto& t : target.faces)
    for (int v : t) ++starBegin_[v + 1];
  for (int v = 0; v < nv; ++v) starBegin_[v + 1] += starBegin_[v];
  star_.resize(starBegin_[nv]);
  std::vector<int> fill(starBegin_.begin(), starBegin_.end() - 1);
  for (int f = 0; f < target.faceCount(); ++f)
    for (int v : target.faces[f]) star_[fill[v]++] = f;
}

Vec3 TargetNormals::closestAt(const FacePoint& p, const Vec3& n) const {
  if (p.face < 0) return Vec3::Zero();
  constexpr double eps = 1e-9;
  const auto& t = mesh_.faces[p.face];
  int inside = 0, corner = -1;
  for (int k = 0; k < 3; ++k)
    if (p.bary[k] > eps) ++inside, corner = k;
  Vec3 best = normal_[p.face];
  if (inside == 3) return best;
  double bestDot = best.dot(n);
  auto consider = [&](int f) {
    const double d = normal_[f].dot(n);
    if (d > bestDot) bestDot = d, best = normal_[f];
  };
  if (inside == 1) {  // at the vertex of `corner`: every face around it
    const int v = t[corner];
    for (int i = starBegin_[v]; i < starBegin_[v + 1]; ++i) consider(star_[i]);
  } else if (inside == 2) {  // on the edge opposite the corner whose coordinate is ~0: both faces
    int off = 0;
    while (p.bary[off] > eps) ++off;
    const int a = t[(off + 1) % 3], b = t[(off + 2) % 3];
    for (int i = starBegin_[a]; i < starBegin_[a + 1]; ++i) {
      const auto& g = mesh_.faces[star_[i]];
      if (g[0] == b || g[1] == b || g[2] == b) consider(star_[i]);
    }
  }
  return best;
}

bool TargetNormals::flipped(const Vec3& i0, const Vec3& i1, const Vec3& i2, const FacePoint& p0, const FacePoint& p1,
                            const FacePoint& p2) const {
  const Vec3 n = (i1 - i0).cross(i2 - i0);
  return n.dot(closestAt(p0, n) + closestAt(p1, n) + closestAt(p2, n)) < 0;
}

}  // namespace cbd
