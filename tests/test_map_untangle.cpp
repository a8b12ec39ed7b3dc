// The last stage of the cross-map: removing flipped triangles from M_st (map_untangle.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "cbd/distortion.h"
#include "cbd/map_untangle.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

/// The identity map of a mesh onto itself: every vertex on a face of its own, at its corner.
void identityMap(const IndexedMesh& m, std::vector<FacePoint>& on, std::vector<Vec3>& image) {
  on.assign(m.vertexCount(), FacePoint{});
  image = m.positions;
  for (int f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      FacePoint& p = on[m.faces[f][k]];
      if (p.face >= 0) continue;
      p.face = f;
      p.bary = Vec3::Unit(k);
    }
}

Vec3 pointOf(const IndexedMesh& m, const FacePoint& p) {
  const auto& t = m.faces[p.face];
  return p.bary[0] * m.positions[t[0]] + p.bary[1] * m.positions[t[1]] + p.bary[2] * m.positions[t[2]];
}

/// Whether `image` lies on the target where `p` says: p names a face of m, its barycentric
/// coordinates are inside it (to rounding), and they give `image`.
::testing::AssertionResult imageOnItsFace(const IndexedMesh& m, const FacePoint& p, const Vec3& image) {
  if (p.face < 0 || p.face >= m.faceCount()) return ::testing::AssertionFailure() << "on no face (" << p.face << ")";
  if (p.bary.minCoeff() < -1e-12)
    return ::testing::AssertionFailure() << "outside face " << p.face << ": barycentric " << p.bary.transpose();
  const double off = (pointOf(m, p) - image).norm();
  if (off >= 1e-12) return ::testing::AssertionFailure() << off << " away from its face point";
  return ::testing::AssertionSuccess();
}

/// A bumpy icosphere of the given subdivision level, its identity map, and every `anchorEvery`-th
/// vertex fixed.
void bumpyIdentity(int level, int anchorEvery, IndexedMesh& m, std::vector<FacePoint>& on, std::vector<Vec3>& image,
                   std::vector<char>& fixed) {
  m = fx::icosphere(level);
  for (auto& p : m.positions) p *= 1.0 + 0.1 * std::sin(5 * p.x()) * std::cos(4 * p.y());
  identityMap(m, on, image);
  fixed.assign(m.vertexCount(), 0);
  for (int v = 0; v < m.vertexCount(); v += anchorEvery) fixed[v] = 1;
}

/// Every free vertex's image slid into one of its faces (a jittered map on the surface:
/// distorted, not folded).
void jitterIntoFaces(const IndexedMesh& m, const std::vector<char>& fixed, std::vector<FacePoint>& on,
                     std::vector<Vec3>& image) {
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (fixed[v]) continue;
    const auto& t = m.faces[on[v].face];
    const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
    const double s = 0.25 + 0.2 * std::sin(1.7 * v);  // how far into the face, 0.05 .. 0.45
    on[v].bary = Vec3::Constant(0.5 * s);
    on[v].bary[k] = 1.0 - s;
    image[v] = pointOf(m, on[v]);
  }
}

/// What a polish must leave of `before` (a map of m onto itself, anchors `fixed`): no flipped or
/// degenerate triangle, E_ang below a tenth of `reference`'s, E_L2 not above it, every image on
/// its face, the anchors where they were. `what` names the run in messages.
void expectPolished(const IndexedMesh& m, const std::vector<char>& fixed, const std::vector<Vec3>& before,
                    const DistortionMetrics& reference, const std::vector<FacePoint>& on,
                    const std::vector<Vec3>& image, const std::string& what) {
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  EXPECT_EQ(d.flipped, 0) << what;
  EXPECT_EQ(d.degenerate, 0) << what;
  EXPECT_LT(d.eAng, 0.1 * reference.eAng) << what << ": before " << reference.eAng << ", polished " << d.eAng;
  EXPECT_LE(d.eL2, reference.eL2 * (1 + 1e-9)) << what << ": before " << reference.eL2 << ", polished " << d.eL2;
  for (int v = 0; v < m.vertexCount(); ++v) {
    EXPECT_TRUE(imageOnItsFace(m, on[v], image[v])) << what << ": vertex " << v;
    if (fixed[v]) EXPECT_EQ(image[v], before[v]) << what << ": anchor " << v << " moved";
  }
}

/// Vertices within `rings` edges of v.
std::vector<int> ringDistance(const IndexedMesh& m, int v) {
  std::vector<std::vector<int>> nbr(m.vertexCount());
  for (const auto& t : m.faces)
    for (int k = 0; k < 3; ++k) nbr[t[k]].push_back(t[(k + 1) % 3]);
  std::vector<int> d(m.vertexCount(), -1), q{v};
  d[v] = 0;
  for (size_t i = 0; i < q.size(); ++i)
    for (int w : nbr[q[i]])
      if (d[w] < 0) d[w] = d[q[i]] + 1, q.push_back(w);
  return d;
}

/// The identity of `m` with the disk of `rings` rings round vertex a squeezed into a wedge: every
/// direction about a at a sixth of its angle, so that a's neighbours all lie on one side of it.
/// Whether a is an anchor is the caller's `fixed`.
void squeezeDisk(const IndexedMesh& m, int a, std::vector<FacePoint>& on, std::vector<Vec3>& image,
                       int rings = 3) {
  identityMap(m, on, image);
  const std::vector<int> d = ringDistance(m, a);
  const Vec3 n = m.positions[a].normalized();
  const Vec3 ax = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized(), ay = n.cross(ax);
  // The squeezed point of v, located on the sphere by the closest face centre's face.
  auto locate = [&](const Vec3& p) {
    int best = -1;
    double bestD = 1e300;
    for (int f = 0; f < m.faceCount(); ++f) {
      const auto& t = m.faces[f];
      const double dd = ((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3 - p).squaredNorm();
      if (dd < bestD) bestD = dd, best = f;
    }
    // Barycentric coordinates of p projected into that face.
    const auto& t = m.faces[best];
    const Vec3 e1 = m.positions[t[1]] - m.positions[t[0]], e2 = m.positions[t[2]] - m.positions[t[0]];
    const Vec3 q = p - m.positions[t[0]];
    const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2), det = a11 * a22 - a12 * a12;
    const double b1 = (a22 * e1.dot(q) - a12 * e2.dot(q)) / det, b2 = (a11 * e2.dot(q) - a12 * e1.dot(q)) / det;
    Vec3 b(1 - b1 - b2, b1, b2);
    b = b.cwiseMax(0.0);
    return FacePoint{best, b / b.sum()};
  };
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (d[v] < 1 || d[v] > rings) continue;
    const Vec3 r = m.positions[v] - m.positions[a];
    const double angle = std::atan2(r.dot(ay), r.dot(ax)), len = (r - n * n.dot(r)).norm();
    const double squeezed = (angle < 0 ? angle + 2 * M_PI : angle) / 6.0;
    const Vec3 p = (m.positions[a] + len * (std::cos(squeezed) * ax + std::sin(squeezed) * ay)).normalized();
    on[v] = locate(p);
    image[v] = pointOf(m, on[v]);
  }
}

/// An icosphere's identity map with the disk round its anchor (vertex 0, the only fixed vertex)
/// squeezed into a wedge (`squeezeDisk`).
struct FoldedAnchorStar {
  IndexedMesh m = fx::icosphere(3);
  const int a = 0;
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  std::vector<char> fixed;
  FoldedAnchorStar() : fixed(m.vertexCount(), 0) {
    squeezeDisk(m, a, on, image);
    fixed[a] = 1;
  }
};

}  // namespace

TEST(MapUntangle, IdentityIsLeftUnchanged) {
  const IndexedMesh m = fx::icosphere(3);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  identityMap(m, on, image);
  const std::vector<Vec3> before = image;
  const MapUntangleResult r = untangleCrossMap(m, m, std::vector<char>(m.vertexCount(), 0), on, image);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.flippedBefore, 0);
  EXPECT_EQ(r.flippedAfter, 0);
  EXPECT_EQ(r.moves, 0);
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_EQ(image[v], before[v]);
}

TEST(MapUntangle, ReportsTheDegenerateTrianglesOfTheMapItReturns) {
  // Three anchors of one face, two of them mapped onto the same point: that triangle stays
  // degenerate whatever moves (anchors never move), and the result counts it as the metrics do.
  const IndexedMesh m = fx::icosphere(3);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  identityMap(m, on, image);
  std::vector<char> fixed(m.vertexCount(), 0);
  const auto& f = m.faces[0];
  for (int v : f) fixed[v] = 1;
  image[f[2]] = image[f[0]], on[f[2]] = on[f[0]];
  const MapUntangleResult r = untangleCrossMap(m, m, fixed, on, image);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  EXPECT_GE(d.degenerate, 1);
  EXPECT_EQ(r.degenerateAfter, d.degenerate);
  EXPECT_EQ(r.flippedAfter, d.flipped);
}

TEST(MapUntangle, IdentityOfASpikyMeshHasNoFlipWhateverFaceHoldsEachVertex) {
  // Sharp spikes: at a spike's tip the faces around it face far apart. Each vertex of the
  // identity map is located in the face around it that disagrees most with its neighbours, so
  // the test against located faces alone (imageFlipped) sees flips that are not there; the
  // metrics' test (the closest normal of the faces touching a corner) sees none, and the
  // untangling leaves the map alone.
  IndexedMesh m = fx::icosphere(1);
  for (int v = 0; v < m.vertexCount(); v += 3) m.positions[v] *= 3.0;
  const std::vector<Vec3> normal = faceNormals(m);
  std::vector<std::vector<int>> star(m.vertexCount());
  for (int f = 0; f < m.faceCount(); ++f)
    for (int v : m.faces[f]) star[v].push_back(f);
  std::vector<FacePoint> on(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) {
    double worst = 2;
    for (int f : star[v])
      for (int g : star[v])
        if (normal[f].dot(normal[g]) < worst) {
          worst = normal[f].dot(normal[g]);
          on[v].face = f;
          const auto& t = m.faces[f];
          on[v].bary = Vec3::Unit(static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin()));
        }
  }
  std::vector<Vec3> image = m.positions;
  int strict = 0;
  for (const auto& t : m.faces)
    strict += imageFlipped(image[t[0]], image[t[1]], image[t[2]], normal, on[t[0]].face, on[t[1]].face, on[t[2]].face);
  ASSERT_GT(strict, 0) << "the fixture must fool the located-face test";
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  EXPECT_EQ(d.flipped, 0);
  EXPECT_NEAR(d.eL2, 1.0, 1e-12);
  const MapUntangleResult r = untangleCrossMap(m, m, std::vector<char>(m.vertexCount(), 0), on, image);
  EXPECT_EQ(r.flippedBefore, 0);
  EXPECT_EQ(r.attempts, 0);
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_EQ(image[v], m.positions[v]);
  // A triangle really turned over is still flipped for the metrics: on a smooth sphere, throw
  // a vertex's image across a neighbour, into the middle of a face beyond it.
  const IndexedMesh sphere = fx::icosphere(2);
  std::vector<FacePoint> son;
  std::vector<Vec3> simage;
  identityMap(sphere, son, simage);
  const int v = 0;
  const auto& t0 = sphere.faces[son[v].face];
  const int w = t0[0] == v ? t0[1] : t0[0];  // a neighbour of v
  int beyond = -1;  // a face around w, opposite v: sharing no vertex with v's faces but w
  for (int f = 0; f < sphere.faceCount() && beyond < 0; ++f) {
    const auto& t = sphere.faces[f];
    if (std::find(t.begin(), t.end(), w) == t.end()) continue;
    bool nearV = false;
    for (int x : t)
      if (x != w)
        for (const auto& g : sphere.faces)
          if (std::find(g.begin(), g.end(), v) != g.end() && std::find(g.begin(), g.end(), x) != g.end()) nearV = true;
    if (!nearV) beyond = f;
  }
  ASSERT_GE(beyond, 0);
  son[v] = FacePoint{beyond, Vec3::Constant(1.0 / 3)};
  const auto& tb = sphere.faces[beyond];
  simage[v] = (sphere.positions[tb[0]] + sphere.positions[tb[1]] + sphere.positions[tb[2]]) / 3;
  const TargetNormals tn(sphere);
  const std::vector<Vec3> sn = faceNormals(sphere);
  int lenient = 0, located = 0;
  for (const auto& t : sphere.faces) {
    lenient += tn.flipped(simage[t[0]], simage[t[1]], simage[t[2]], son[t[0]], son[t[1]], son[t[2]]);
    located += imageFlipped(simage[t[0]], simage[t[1]], simage[t[2]], sn, son[t[0]].face, son[t[1]].face, son[t[2]].face);
  }
  EXPECT_GT(lenient, 0);
  EXPECT_LE(lenient, located);
}

TEST(MapUntangle, FoldedVerticesAreUntangledOnTheSurfaceWithAnchorsFixed) {
  // The identity of a bumpy sphere, with a few vertices thrown across their neighbours: their
  // triangles fold over. Anchors (every 7th vertex) must stay where they are.
  IndexedMesh m;
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  std::vector<char> fixed;
  bumpyIdentity(4, 7, m, on, image, fixed);
  const std::vector<int> thrown = {10, 200, 1500};
  for (int v : thrown) {
    ASSERT_FALSE(fixed[v]);
    // A face two rings away from v, on the far side of one of its neighbours.
    const std::vector<int> d = ringDistance(m, v);
    int far = -1;
    for (int f = 0; f < m.faceCount() && far < 0; ++f) {
      const auto& t = m.faces[f];
      if (std::min({d[t[0]], d[t[1]], d[t[2]]}) == 1 && std::max({d[t[0]], d[t[1]], d[t[2]]}) == 2) far = f;
    }
    ASSERT_GE(far, 0);
    on[v].face = far;
    on[v].bary = Vec3(0.2, 0.4, 0.4);
    image[v] = pointOf(m, on[v]);
  }
  const std::vector<Vec3> thrownImage = image;
  const int flippedBefore = computeDistortion(m, image, m, on).flipped;
  ASSERT_GT(flippedBefore, 0) << "the fixture must start with flipped triangles";

  const MapUntangleResult r = untangleCrossMap(m, m, fixed, on, image);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.flippedBefore, flippedBefore);
  EXPECT_EQ(r.flippedAfter, 0);
  EXPECT_EQ(r.degenerateAfter, 0);
  const DistortionMetrics d = computeDistortion(m, image, m, on);
  EXPECT_EQ(d.flipped, 0);
  EXPECT_EQ(d.degenerate, 0);
  EXPECT_GT(r.movedVertices, 0);
  // Every image on the surface; anchors and vertices far from the damage untouched.
  std::vector<int> nearest(m.vertexCount(), 1 << 30);
  for (int v : thrown) {
    const std::vector<int> dv = ringDistance(m, v);
    for (int w = 0; w < m.vertexCount(); ++w) nearest[w] = std::min(nearest[w], dv[w]);
  }
  int farUnchanged = 0, far = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    EXPECT_TRUE(imageOnItsFace(m, on[v], image[v])) << "vertex " << v;
    EXPECT_NEAR(on[v].bary.sum(), 1.0, 1e-12);
    if (fixed[v]) EXPECT_EQ(image[v], thrownImage[v]) << "anchor " << v << " moved";
    if (nearest[v] > 12) ++far, farUnchanged += image[v] == thrownImage[v];
  }
  EXPECT_GT(far, 0);
  EXPECT_EQ(farUnchanged, far) << "vertices far from every fold moved";
  // Untangled means back near the identity: the thrown vertices are close to home again.
  double edge = 0;
  for (const auto& t : m.faces) edge += (m.positions[t[1]] - m.positions[t[0]]).norm();
  edge /= m.faceCount();
  for (int v : thrown) EXPECT_LT((image[v] - m.positions[v]).norm(), 1.5 * edge) << "vertex " << v;
}

TEST(MapUntangle, PolishLowersBothMetricsAndAddsNoFlip) {
  // The identity of a bumpy sphere with every free vertex's image slid into one of its faces
  // (a jittered map on the surface: distorted, not folded), plus one vertex thrown across its
  // neighbours so that there is a flip to untangle. With the polish, E_ang must fall to a tenth of
  // the unpolished untangling's, E_L2 must not rise, and no flip may come back.
  IndexedMesh m;
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  std::vector<char> fixed;
  bumpyIdentity(3, 9, m, on, image, fixed);
  jitterIntoFaces(m, fixed, on, image);
  const int thrown = 100;
  ASSERT_FALSE(fixed[thrown]);
  const std::vector<int> d = ringDistance(m, thrown);
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    if (std::min({d[t[0]], d[t[1]], d[t[2]]}) == 1 && std::max({d[t[0]], d[t[1]], d[t[2]]}) == 2) {
      on[thrown] = FacePoint{f, Vec3(0.2, 0.4, 0.4)};
      break;
    }
  }
  image[thrown] = pointOf(m, on[thrown]);
  ASSERT_GT(computeDistortion(m, image, m, on).flipped, 0);

  MapUntangleOptions raw;
  raw.polishSweeps = 0;
  std::vector<FacePoint> onRaw = on, onPolished = on;
  std::vector<Vec3> imageRaw = image, imagePolished = image;
  const MapUntangleResult rr = untangleCrossMap(m, m, fixed, onRaw, imageRaw, raw);
  const MapUntangleResult rp = untangleCrossMap(m, m, fixed, onPolished, imagePolished);
  ASSERT_EQ(rr.flippedAfter, 0);
  EXPECT_EQ(rp.flippedAfter, 0);
  EXPECT_GT(rp.moves, rr.moves);
  expectPolished(m, fixed, image, computeDistortion(m, imageRaw, m, onRaw), onPolished, imagePolished,
                 "against the unpolished untangling");
}

TEST(MapUntangle, AFlipFreeMapIsPolishedToo) {
  // The jittered identity without any flip: nothing to untangle, but the polish must still run
  // (the result may not depend on whether the composed map happened to have a flip), in the
  // index order and in a seeded one alike.
  IndexedMesh m;
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  std::vector<char> fixed;
  bumpyIdentity(3, 9, m, on, image, fixed);
  jitterIntoFaces(m, fixed, on, image);
  const DistortionMetrics d0 = computeDistortion(m, image, m, on);
  ASSERT_EQ(d0.flipped, 0);
  ASSERT_GT(d0.eAng, 0.05);
  for (const std::uint64_t seed : {0, 7}) {
    MapUntangleOptions o;
    o.polishOrderSeed = seed;
    std::vector<FacePoint> on1 = on;
    std::vector<Vec3> image1 = image;
    const MapUntangleResult r = untangleCrossMap(m, m, fixed, on1, image1, o);
    ASSERT_TRUE(r.status.ok());
    EXPECT_EQ(r.flippedBefore, 0);
    EXPECT_EQ(r.flippedAfter, 0);
    EXPECT_EQ(r.attempts, 0) << "stages 1-6 ran on a map without flips";
    EXPECT_GT(r.moves, 0);
    expectPolished(m, fixed, image, d0, on1, image1, "seed " + std::to_string(seed));
  }
}

TEST(MapUntangle, AnAnchorDiskFoldedIntoAWedgeIsLaidOutAnew) {
  // The identity of a sphere with the disk of 3 rings round an anchor squeezed into a wedge:
  // every direction about the anchor at a sixth of its angle, so that its neighbours all lie on
  // one side of it and the triangle closing its star is turned over (as where the two layouts
  // meet an anchor at very different corner angles, camel -> diplodocus-70 and man -> homer-70).
  FoldedAnchorStar star;
  const IndexedMesh& m = star.m;
  const int a = star.a;
  std::vector<FacePoint>& on = star.on;
  std::vector<Vec3>& image = star.image;
  const std::vector<char>& fixed = star.fixed;
  const std::vector<int> d = ringDistance(m, a);
  const Vec3 n = m.positions[a].normalized();
  const int flippedBefore = computeDistortion(m, image, m, on).flipped;
  ASSERT_GT(flippedBefore, 0) << "the fixture must fold the anchor's star";

  // Laying the disk out anew undoes the fold: nothing flipped, the images back near the
  // identity (the flattened disk of a sphere, scaled), anchors where they were.
  std::vector<FacePoint> on1 = on;
  std::vector<Vec3> image1 = image;
  ASSERT_TRUE(relayAnchorDisk(m, m, fixed, a, 3, on1, image1));
  EXPECT_FALSE(relayAnchorDisk(m, m, fixed, m.vertexCount(), 3, on1, image1));
  const DistortionMetrics dm = computeDistortion(m, image1, m, on1);
  EXPECT_EQ(dm.flipped, 0);
  EXPECT_EQ(dm.degenerate, 0);
  double edge = 0;
  for (const auto& t : m.faces) edge += (m.positions[t[1]] - m.positions[t[0]]).norm();
  edge /= m.faceCount();
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (d[v] >= 1 && d[v] <= 3) EXPECT_LT((image1[v] - m.positions[v]).norm(), 0.25 * edge) << "vertex " << v;
    if (d[v] > 3) EXPECT_EQ(image1[v], image[v]) << "vertex " << v << " outside the disk moved";
    EXPECT_TRUE(imageOnItsFace(m, on1[v], image1[v])) << "vertex " << v;
  }
  // The anchor's neighbours wind once round its image again.
  double winding = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    const int k = static_cast<int>(std::find(t.begin(), t.end(), a) - t.begin());
    if (k == 3) continue;
    Vec3 u = image1[t[(k + 1) % 3]] - image1[a], w = image1[t[(k + 2) % 3]] - image1[a];
    u -= n * n.dot(u), w -= n * n.dot(w);  // in the tangent plane at the anchor
    winding += std::atan2(u.cross(w).dot(n), u.dot(w));
  }
  EXPECT_NEAR(winding, 2 * M_PI, 1e-6);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (fixed[v]) EXPECT_EQ(image1[v], image[v]) << "anchor " << v << " moved";
}

TEST(MapUntangle, AnAnchorDiskRestartLeavesAnotherAnchorsNeighbourhoodInPlace) {
  // Two anchors 3 rings apart on a sphere, the map the identity (laying a's disk out anew moves
  // it all the same: the disk is flattened). Restarting a's disk of 4 rings reaches past anchor b: the vertices nearer b than a (b's star among them) must stay where they are,
  // or b's fan is torn off b's image (camel -> diplodocus-70: anchor 1527's fan stretched 8-fold
  // by the restart of anchor 3864, 4 rings away).
  const IndexedMesh m = fx::icosphere(3);
  std::vector<FacePoint> on;
  std::vector<Vec3> image;
  identityMap(m, on, image);
  const int a = 0;
  const std::vector<int> da = ringDistance(m, a);
  int b = -1;
  for (int v = 0; v < m.vertexCount() && b < 0; ++v)
    if (da[v] == 3) b = v;
  ASSERT_GE(b, 0);
  const std::vector<int> db = ringDistance(m, b);
  std::vector<char> fixed(m.vertexCount(), 0);
  fixed[a] = fixed[b] = 1;
  const int rings = 4;
  std::vector<FacePoint> on1 = on;
  std::vector<Vec3> image1 = image;
  ASSERT_TRUE(relayAnchorDisk(m, m, fixed, a, rings, on1, image1));
  int moved = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const bool aSide = da[v] >= 1 && da[v] <= rings && da[v] < db[v];
    if (!aSide) {
      EXPECT_EQ(image1[v], image[v]) << "vertex " << v << " (" << da[v] << " rings from a, " << db[v]
                                     << " from b) is not a's to move";
      continue;
    }
    moved += image1[v] != image[v];
    EXPECT_TRUE(imageOnItsFace(m, on1[v], image1[v])) << "vertex " << v;
  }
  EXPECT_GT(moved, 0) << "a's own side of the disk was not laid out";
  // Laid out anew from the identity, nothing is turned over, b's fan included.
  const DistortionMetrics dm = computeDistortion(m, image1, m, on1);
  EXPECT_EQ(dm.flipped, 0);
  EXPECT_EQ(dm.degenerate, 0);
  for (int f = 0; f < m.faceCount(); ++f) {
    const auto& t = m.faces[f];
    if (t[0] == b || t[1] == b || t[2] == b) EXPECT_NEAR(dm.faceStretch[f], 1.0, 0.05) << "face " << f << " of b's fan";
  }
}

TEST(MapUntangle, AnchorRestartSkipsRingCountsBelowOne) {
  // The folded anchor star of AnAnchorDiskFoldedIntoAWedgeIsLaidOutAnew, with stages 1-5 all but
  // off so that the flips reach the anchor restart: a ring count of 0 there is skipped (not a
  // disk of the anchor alone, nor an exception out of a lookup beyond the ball), and the next
  // entry lays the star out anew.
  FoldedAnchorStar star;
  const IndexedMesh& m = star.m;
  std::vector<FacePoint>& on = star.on;
  std::vector<Vec3>& image = star.image;
  const std::vector<char>& fixed = star.fixed;
  ASSERT_GT(computeDistortion(m, image, m, on).flipped, 0);
  MapUntangleOptions o;
  o.maxRounds = 0;
  o.energySweeps = 0;
  o.lastResortFactor = 1.0;
  o.retryDistortions.clear();
  o.polishSweeps = 0;
  o.anchorRestartRings = {0, -1};
  {
    std::vector<FacePoint> on1 = on;
    std::vector<Vec3> image1 = image;
    MapUntangleResult r;
    ASSERT_NO_THROW(r = untangleCrossMap(m, m, fixed, on1, image1, o));
    EXPECT_GT(r.flippedAfter, 0) << "stages 1-5 are off and no restart was possible, yet flips went";
    EXPECT_EQ(image1, image) << "a ring count below 1 moved something";
  }
  o.anchorRestartRings = {0, 3};
  MapUntangleResult r;
  ASSERT_NO_THROW(r = untangleCrossMap(m, m, fixed, on, image, o));
  EXPECT_GT(r.flippedBefore, 0);
  EXPECT_EQ(r.flippedAfter, 0);
  EXPECT_EQ(computeDistortion(m, image, m, on).flipped, 0);
}

TEST(MapUntangle, AFoldWiderThanTheRingsIsUndoneByTheWideRingRetry) {
  // The disk of 8 rings round vertex 0 of an icosphere squeezed into a wedge, the only anchor
  // at the far side: a fold no anchor restart reaches (as the man's fingers on man -> homer,
  // 18-26 rings from an anchor). With relaxation and energy limited to 2 rings round what is
  // bad (standing for the default 10 at the bench meshes' scale), every stage and retry leaves
  // flips; the retry with wider rings undoes them all. The polish is off, so what moved is the
  // untangling's.
  const IndexedMesh m = fx::icosphere(4);
  const int centre = 0, disk = 8;
  std::vector<FacePoint> on0;
  std::vector<Vec3> image0;
  squeezeDisk(m, centre, on0, image0, disk);
  const std::vector<int> d = ringDistance(m, centre);
  const int anchor = static_cast<int>(std::max_element(d.begin(), d.end()) - d.begin());
  std::vector<char> fixed(m.vertexCount(), 0);
  fixed[anchor] = 1;
  const int flippedBefore = computeDistortion(m, image0, m, on0).flipped;
  ASSERT_GT(flippedBefore, 0) << "the fixture must fold the disk";
  MapUntangleOptions o;
  o.maxRing = 2;
  o.polishSweeps = 0;
  o.retryMaxRing = 0;
  {
    std::vector<FacePoint> on = on0;
    std::vector<Vec3> image = image0;
    const MapUntangleResult r = untangleCrossMap(m, m, fixed, on, image, o);
    ASSERT_TRUE(r.status.ok());
    EXPECT_GT(r.flippedAfter, 0) << "the fold must need more than 2 rings, or this test shows nothing";
  }
  o.retryMaxRing = 16;
  std::vector<FacePoint> on = on0;
  std::vector<Vec3> image = image0;
  const MapUntangleResult r = untangleCrossMap(m, m, fixed, on, image, o);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.flippedBefore, flippedBefore);
  EXPECT_EQ(r.flippedAfter, 0);
  const DistortionMetrics after = computeDistortion(m, image, m, on);
  EXPECT_EQ(after.flipped, 0);
  EXPECT_EQ(after.degenerate, 0);
  EXPECT_LT(after.eAng, computeDistortion(m, image0, m, on0).eAng);
  // Every image on the surface; the anchor and what lies beyond the fold's reach untouched.
  int beyond = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    EXPECT_TRUE(imageOnItsFace(m, on[v], image[v])) << "vertex " << v;
    if (d[v] <= disk + o.retryMaxRing + 2) continue;
    ++beyond;
    EXPECT_EQ(image[v], image0[v]) << "vertex " << v << " moved";
  }
  EXPECT_GT(beyond, 0);
  EXPECT_EQ(image[anchor], image0[anchor]);
}
