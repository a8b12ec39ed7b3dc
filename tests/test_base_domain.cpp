// The base domain as a surface (base_domain.h): lattice chart maps, the gluing of the patches,
// walks across patch sides, each surface mapped onto D and back, point location among faces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cbd/anchor_sampling.h"
#include "cbd/base_domain.h"
#include "cbd/parameterization.h"
#include "cbd/source_layout.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {

ChartMap randomMap(std::mt19937& rng) {
  std::uniform_int_distribution<int> rot(0, 5), shift(-4, 4);
  return {rot(rng), shift(rng), shift(rng)};
}

/// A layout of the icosphere with 16 farthest-point anchors, split for parameterization, and its
/// patch parameterization.
struct SphereLayout {
  IndexedMesh mesh;
  Layout layout;
  PatchParameterization param;
};
SphereLayout sphereLayout() {
  SphereLayout s;
  s.mesh = fx::icosphere(3);
  SourceLayoutResult r = buildSourceLayout(s.mesh, farthestPointSampling(s.mesh, 16));
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  s.layout = std::move(r.layout);
  splitCollinearFaces(s.layout);
  s.param = parameterizePatches(s.layout);
  EXPECT_TRUE(s.param.status.ok());
  return s;
}

}  // namespace

TEST(ChartMap, ComposesAndInvertsExactlyOnTheLattice) {
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    const ChartMap a = randomMap(rng), b = randomMap(rng), c = randomMap(rng);
    EXPECT_EQ((a * b) * c, a * (b * c));
    EXPECT_EQ(a * a.inverse(), ChartMap{});
    EXPECT_EQ(a.inverse() * a, ChartMap{});
    const Vec2 x(0.3 * i, -0.7 + 0.01 * i);
    EXPECT_NEAR(((a * b).apply(x) - a.apply(b.apply(x))).norm(), 0.0, 1e-12);
    // The linear part is a rotation by 60 degrees times `rot`.
    const Eigen::Matrix2d L = a.linear();
    EXPECT_NEAR((L * L.transpose() - Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-15);
    EXPECT_NEAR(std::atan2(L(1, 0), L(0, 0)), std::remainder(a.rot * M_PI / 3.0, 2 * M_PI), 1e-12);
  }
}

TEST(BaseDomain, GluesEveryPatchSideOntoItsNeighboursOtherWayRound) {
  const SphereLayout s = sphereLayout();
  const BaseDomain D(s.layout);
  EXPECT_EQ(D.patchCount(), static_cast<int>(s.layout.patches.size()));
  EXPECT_NEAR(D.area(), D.patchCount() * std::sqrt(3.0) / 4.0, 1e-12);
  for (int p = 0; p < D.patchCount(); ++p)
    for (int k = 0; k < 3; ++k) {
      const int q = D.neighbour(p, k);
      ASSERT_GE(q, 0);
      const int j = D.sideOf(q, s.layout.patches[p].edges[k], p);
      ASSERT_GE(j, 0);
      // Side k of p lands on side j of q reversed, p's triangle outside q's, and back again.
      const ChartMap& m = D.across(p, k);
      EXPECT_NEAR((m.apply(domainCorner(k)) - domainCorner(j + 1)).norm(), 0.0, 1e-12);
      EXPECT_NEAR((m.apply(domainCorner(k + 1)) - domainCorner(j)).norm(), 0.0, 1e-12);
      EXPECT_LT(insideSide(m.apply(domainCorner(k + 2)), j), -0.5);
      EXPECT_EQ(D.across(q, j) * m, ChartMap{});
    }
}

TEST(BaseDomain, AWalkThereAndBackEndsWhereItStarted) {
  const SphereLayout s = sphereLayout();
  const BaseDomain D(s.layout);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0), angle(0.0, 2 * M_PI);
  int crossed = 0;
  for (int i = 0; i < 500; ++i) {
    const double a = unit(rng), b = unit(rng) * (1 - a);
    const DomainPoint start{i % D.patchCount(), (1 - a - b) * domainCorner(0) + a * domainCorner(1) + b * domainCorner(2)};
    const Vec2 d = 0.8 * unit(rng) * Vec2(std::cos(angle(rng)), std::sin(angle(rng)));
    DomainPoint p = start;
    ChartMap back;
    ASSERT_TRUE(D.walk(p, d, &back));
    crossed += p.patch != start.patch;
    // The end lies in its triangle, and the map back puts it where the straight step ended.
    for (int k = 0; k < 3; ++k) EXPECT_GE(insideSide(p.uv, k), -1e-12);
    EXPECT_NEAR((back.apply(p.uv) - (start.uv + d)).norm(), 0.0, 1e-12);
    // Walking the same displacement backwards, turned into the end's frame, returns.
    ASSERT_TRUE(D.walk(p, -(back.linear().transpose() * d)));
    EXPECT_EQ(p.patch, start.patch);
    EXPECT_NEAR((p.uv - start.uv).norm(), 0.0, 1e-12);
  }
  EXPECT_GT(crossed, 100);  // the walks do cross sides
}

TEST(SurfaceInDomain, MapsEveryVertexOntoDAndBackOntoItself) {
  const SphereLayout s = sphereLayout();
  const BaseDomain D(s.layout);
  const SurfaceInDomain sd(s.layout, s.param, D);
  for (int v = 0; v < s.mesh.vertexCount(); ++v) {
    const DomainPoint p = sd.vertexPoint(v);
    ASSERT_GE(p.patch, 0);
    SurfaceInDomain::Hit hit;
    ASSERT_TRUE(sd.locate(p, hit));
    EXPECT_NEAR((hit.position - s.mesh.positions[v]).norm(), 0.0, 1e-9);
    // And a point of its face, with its barycentric coordinates, lands on the same point of D.
    FacePoint fp;
    fp.face = hit.point.face;
    fp.bary = hit.point.bary;
    DomainPoint q;
    ASSERT_TRUE(sd.toDomain(fp, q));
    SurfaceInDomain::Hit again;
    ASSERT_TRUE(sd.locate(q, again));
    EXPECT_NEAR((again.position - s.mesh.positions[v]).norm(), 0.0, 1e-9);
  }
}

TEST(TrianglesInDomain, LocatesEveryVertexAndFaceCentreOfTheComposedMap) {
  const SphereLayout s = sphereLayout();
  const BaseDomain D(s.layout);
  const SurfaceInDomain sd(s.layout, s.param, D);
  const IndexedMesh refined = s.layout.mesh.toIndexed();
  std::vector<DomainPoint> points(refined.vertexCount());
  for (int v = 0; v < refined.vertexCount(); ++v) points[v] = sd.vertexPoint(v);
  const std::vector<std::array<ChartMap, 3>> charts = sd.faceCharts();
  const TrianglesInDomain located(D, refined.faces, points, charts);
  for (int v = 0; v < refined.vertexCount(); ++v) {
    FacePoint fp;
    ASSERT_TRUE(located.locate(points[v], fp)) << v;
    const auto& t = refined.faces[fp.face];
    const Vec3 x = fp.bary[0] * refined.positions[t[0]] + fp.bary[1] * refined.positions[t[1]] +
                   fp.bary[2] * refined.positions[t[2]];
    EXPECT_NEAR((x - refined.positions[v]).norm(), 0.0, 1e-9);
  }
  for (int f = 0; f < refined.faceCount(); ++f) {
    // The centre of each face, in the frame of its patch, is found in that face.
    const Vec2 c = (charts[f][0].apply(points[refined.faces[f][0]].uv) + charts[f][1].apply(points[refined.faces[f][1]].uv) +
                    charts[f][2].apply(points[refined.faces[f][2]].uv)) /
                   3.0;
    FacePoint fp;
    ASSERT_TRUE(located.locate({s.layout.facePatch[f], c}, fp));
    EXPECT_EQ(fp.face, f);
    EXPECT_NEAR(fp.bary.minCoeff(), 1.0 / 3.0, 1e-9);
  }
}
