#include "cbd/refined_mesh.h"

#include <algorithm>
#include <cassert>
#include <unordered_map>

namespace cbd {

RefinedMesh::RefinedMesh(const IndexedMesh& mesh) {
  const int nv = mesh.vertexCount(), nf = mesh.faceCount();
  inputVertices_ = nv;
  inputFaces_ = nf;
  pos_ = mesh.positions;
  loc_.assign(nv, SurfacePoint{});
  out_.assign(nv, -1);
  inputFaceVerts_ = mesh.faces;
  faceHe_.resize(nf);
  inputFace_.resize(nf);
  to_.assign(3 * static_cast<size_t>(nf), -1);
  next_.assign(to_.size(), -1);
  face_.assign(to_.size(), -1);
  // Pair the halfedges of each undirected edge: edge e owns halfedges 2e and 2e+1.
  std::unordered_map<long long, int> open;  // key (from, to) -> halfedge waiting for its twin
  open.reserve(to_.size());
  int nextEdge = 0;
  auto key = [nv](int a, int b) { return static_cast<long long>(a) * nv + b; };
  std::vector<int> heOfCorner(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      int h;
      auto it = open.find(key(b, a));
      if (it != open.end()) {
        h = it->second ^ 1;
        open.erase(it);
      } else {
        h = 2 * nextEdge++;
        open.emplace(key(a, b), h);
      }
      to_[h] = b;
      face_[h] = f;
      heOfCorner[3 * f + k] = h;
      if (out_[a] < 0) out_[a] = h;
    }
    for (int k = 0; k < 3; ++k) next_[heOfCorner[3 * f + k]] = heOfCorner[3 * f + (k + 1) % 3];
    faceHe_[f] = heOfCorner[3 * f];
    inputFace_[f] = f;
  }
  assert(open.empty() && "RefinedMesh needs a closed oriented manifold");
  to_.resize(2 * static_cast<size_t>(nextEdge));
  next_.resize(to_.size());
  face_.resize(to_.size());
  onInputEdge_.assign(nextEdge, 1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.faces[f][k];
      if (loc_[v].face < 0) {
        loc_[v].face = f;
        loc_[v].bary = Vec3::Zero();
        loc_[v].bary[k] = 1.0;
      }
    }
}

int RefinedMesh::findHalfedge(int a, int b) const {
  const int start = out_[a];
  if (start < 0) return -1;
  int h = start;
  do {
    if (to_[h] == b) return h;
    h = rotateCCW(h);
  } while (h != start);
  return -1;
}

std::array<int, 3> RefinedMesh::faceVertices(int f) const {
  const int h = faceHe_[f];
  return {from(h), to_[h], to_[next_[h]]};
}

Vec3 RefinedMesh::baryIn(int v, int f) const {
  const SurfacePoint& p = loc_[v];
  if (p.face == f) return p.bary;
  // v lies on the boundary of both p.face and f: re-express its weights on f's corners.
  const auto& src = inputFaceVerts_[p.face];
  const auto& dst = inputFaceVerts_[f];
  Vec3 b = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (p.bary[i] == 0.0) continue;
    for (int j = 0; j < 3; ++j)
      if (dst[j] == src[i]) b[j] += p.bary[i];
  }
  return b;
}

int RefinedMesh::splitEdge(int h, double t) {
  const int t0 = h ^ 1;
  const int a = from(h), b = to_[h];
  const int hn = next_[h], hp = next_[hn];
  const int tn = next_[t0], tp = next_[tn];
  const int c = to_[hn], d = to_[tn];
  const int f1 = face_[h], f2 = face_[t0];
  const int e = edgeOf(h);

  // The new vertex, on the input surface.
  const int m = vertexCount();
  const SplitUndo undo{{}, faceHe_[f1], faceHe_[f2], out_[b]};
  pos_.push_back((1.0 - t) * pos_[a] + t * pos_[b]);
  SurfacePoint sp;
  sp.face = inputFace_[f1];
  sp.bary = (1.0 - t) * baryIn(a, sp.face) + t * baryIn(b, sp.face);
  loc_.push_back(sp);

  const int e1 = halfedgeCount(), e2 = e1 + 2, e3 = e1 + 4;  // pairs (m->b), (m->c), (m->d)
  to_.resize(e1 + 6);
  next_.resize(e1 + 6);
  face_.resize(e1 + 6);
  const int f3 = faceCount(), f4 = f3 + 1;
  faceHe_.resize(f4 + 1);
  inputFace_.resize(f4 + 1);

  to_[h] = m;                  // a -> m
  to_[e1] = b, to_[e1 ^ 1] = m;
  to_[e2] = c, to_[e2 ^ 1] = m;
  to_[e3] = d, to_[e3 ^ 1] = m;
  // f1 = (a, m, c)
  next_[h] = e2, next_[e2] = hp, next_[hp] = h;
  face_[h] = face_[e2] = face_[hp] = f1;
  faceHe_[f1] = h;
  // f3 = (m, b, c)
  next_[e1] = hn, next_[hn] = e2 ^ 1, next_[e2 ^ 1] = e1;
  face_[e1] = face_[hn] = face_[e2 ^ 1] = f3;
  faceHe_[f3] = e1;
  inputFace_[f3] = inputFace_[f1];
  // f2 = (m, a, d): t0 now runs m -> a
  next_[t0] = tn, next_[tn] = e3 ^ 1, next_[e3 ^ 1] = t0;
  face_[t0] = face_[tn] = face_[e3 ^ 1] = f2;
  faceHe_[f2] = t0;
  // f4 = (b, m, d)
  next_[e1 ^ 1] = e3, next_[e3] = tp, next_[tp] = e1 ^ 1;
  face_[e1 ^ 1] = face_[e3] = face_[tp] = f4;
  faceHe_[f4] = e1 ^ 1;
  inputFace_[f4] = inputFace_[f2];

  out_.push_back(e1);
  if (out_[b] == t0) out_[b] = e1 ^ 1;

  const char input = onInputEdge_[e];
  onInputEdge_.push_back(input);  // edge (m, b) continues the split edge
  onInputEdge_.push_back(0);      // diagonals lie inside input faces
  onInputEdge_.push_back(0);
  last_ = {h, m, edgeOf(e1), edgeOf(e2), edgeOf(e3), f3, f4};
  history_.push_back(undo);
  history_.back().record = last_;
  return m;
}

void RefinedMesh::undoSplits(int count) {
  while (static_cast<int>(history_.size()) > std::max(count, 0)) {
    const SplitUndo& u = history_.back();
    const SplitRecord& r = u.record;
    // The inverse of splitEdge: halfedges, faces and the vertex it appended go; the entries it
    // rewrote get their old values (read back from the new elements, which still hold them).
    const int h = r.halfedge, t0 = h ^ 1;
    const int e1 = 2 * r.edgeContinued, e2 = 2 * r.edgeDiagonalA, e3 = 2 * r.edgeDiagonalB;
    const int b = to_[e1], hn = next_[e1], hp = next_[e2], tn = next_[t0], tp = next_[e3];
    const int f1 = face_[h], f2 = face_[t0];
    to_[h] = b;
    next_[h] = hn, next_[hn] = hp, next_[hp] = h;
    next_[t0] = tn, next_[tn] = tp, next_[tp] = t0;
    face_[hn] = f1, face_[tp] = f2;
    faceHe_[f1] = u.faceHalfedgeA, faceHe_[f2] = u.faceHalfedgeB;
    out_[b] = u.farOutgoing;
    pos_.pop_back();
    loc_.pop_back();
    out_.pop_back();
    to_.resize(e1), next_.resize(e1), face_.resize(e1);
    faceHe_.resize(r.faceNewA), inputFace_.resize(r.faceNewA);
    onInputEdge_.resize(r.edgeContinued);
    history_.pop_back();
    last_ = history_.empty() ? SplitRecord{} : history_.back().record;
  }
}

IndexedMesh RefinedMesh::toIndexed() const {
  IndexedMesh out;
  out.positions = pos_;
  out.faces.reserve(faceHe_.size());
  for (int f = 0; f < faceCount(); ++f) out.faces.push_back(faceVertices(f));
  return out;
}

double surfaceArea(const RefinedMesh& m) {
  double a = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto v = m.faceVertices(f);
    a += 0.5 * (m.position(v[1]) - m.position(v[0])).cross(m.position(v[2]) - m.position(v[0])).norm();
  }
  return a;
}

}  // namespace cbd
