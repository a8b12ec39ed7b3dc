// validateMesh / validateInput: one test per mesh error code, genus of every fixture.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cbd/validate_input.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {
MeshReport check(const IndexedMesh& m) { return validateMesh(m, "test"); }
}  // namespace

TEST(ValidateMesh, GenusOfClosedFixtures) {
  struct Case { const char* name; IndexedMesh mesh; int genus; };
  std::vector<Case> cases = {
      {"tetrahedron", fx::tetrahedron(), 0},
      {"icosphere", fx::icosphere(2), 0},
      {"capped cylinder", fx::cappedCylinder(1, 3, 16, 6), 0},
      {"torus", fx::torus(2, 0.7, 24, 12), 1},
      {"double torus", fx::holedPlate(2, 2, 5), 2},
      {"triple torus", fx::holedPlate(3, 2, 5), 3},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const MeshReport r = check(c.mesh);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.genus, c.genus);
    EXPECT_EQ(r.eulerCharacteristic, 2 - 2 * c.genus);
    EXPECT_EQ(r.eulerCharacteristic, fx::eulerCharacteristic(c.mesh));
    EXPECT_EQ(r.vertices, c.mesh.vertexCount());
    EXPECT_EQ(r.faces, c.mesh.faceCount());
    EXPECT_EQ(r.edges * 2, r.faces * 3);  // closed triangle surface
    EXPECT_EQ(r.components, 1);
  }
}

TEST(ValidateMesh, NotTriangles) {
  const MeshReport r = validateMesh(fx::icosphere(1), "test", /*hadPolygons=*/true);
  EXPECT_EQ(r.status.code, ErrorCode::NotTriangles);
}

TEST(ValidateMesh, EmptyMesh) {
  EXPECT_EQ(check(IndexedMesh{}).status.code, ErrorCode::EmptyMesh);
}

TEST(ValidateMesh, OpenBoundaryNamesAnEdge) {
  const MeshReport r = check(fx::openCylinder(1, 2, 12, 4));
  EXPECT_EQ(r.status.code, ErrorCode::OpenBoundary);
  EXPECT_NE(r.status.message.find("24 boundary edges"), std::string::npos) << r.status.message;
  EXPECT_EQ(check(fx::openCone(10)).status.code, ErrorCode::OpenBoundary);
  EXPECT_NE(r.status.message.find("Close Holes"), std::string::npos) << r.status.message;
}

// A closed surface whose faces do not share vertices (a triangle soup: some OBJ exporters) is
// open everywhere; the advice is to merge vertices, not to close holes. A mesh with a real hole
// whose boundary touches no duplicate is told to close it.
TEST(ValidateMesh, AnUnweldedMeshIsToldToMergeVertices) {
  const IndexedMesh sphere = fx::icosphere(1);
  IndexedMesh soup;
  for (const auto& t : sphere.faces) {
    const int base = soup.vertexCount();
    for (int v : t) soup.positions.push_back(sphere.positions[v]);
    soup.faces.push_back({base, base + 1, base + 2});
  }
  const MeshReport r = check(soup);
  ASSERT_EQ(r.status.code, ErrorCode::OpenBoundary);
  EXPECT_NE(r.status.message.find(std::to_string(3 * sphere.faceCount()) + " boundary edges"), std::string::npos)
      << r.status.message;
  EXPECT_NE(r.status.message.find(std::to_string(soup.vertexCount()) + " of its " + std::to_string(soup.vertexCount()) +
                                  " boundary vertices lie at the position of another vertex"),
            std::string::npos)
      << r.status.message;
  EXPECT_NE(r.status.message.find("Merge Close Vertices"), std::string::npos) << r.status.message;
  EXPECT_EQ(r.status.message.find("Close Holes"), std::string::npos) << r.status.message;
  // An open cylinder whose vertices are all distinct: holes to close.
  const MeshReport open = check(fx::openCylinder(1, 2, 12, 4));
  EXPECT_EQ(open.status.message.find("Merge Close Vertices"), std::string::npos) << open.status.message;
}

TEST(ValidateMesh, NonManifoldEdge) {
  const MeshReport r = check(fx::nonManifoldFan());
  EXPECT_EQ(r.status.code, ErrorCode::NonManifoldEdge);
  EXPECT_NE(r.status.message.find("edge 0-1"), std::string::npos) << r.status.message;
}

TEST(ValidateMesh, NonManifoldVertex) {
  const MeshReport r = check(fx::twoTetrahedraAtVertex());
  EXPECT_EQ(r.status.code, ErrorCode::NonManifoldVertex) << r.status.message;
  EXPECT_NE(r.status.message.find("vertex 0"), std::string::npos) << r.status.message;
}

TEST(ValidateMesh, MultipleComponents) {
  const MeshReport r = check(fx::twoComponents());
  EXPECT_EQ(r.status.code, ErrorCode::MultipleComponents);
  EXPECT_EQ(r.components, 2);
}

TEST(ValidateMesh, DegenerateFace) {
  IndexedMesh m = fx::icosphere(1);
  // Move a vertex onto the midpoint of the opposite edge of one of its faces: zero area.
  const auto f = m.faces[7];
  m.positions[f[0]] = 0.5 * (m.positions[f[1]] + m.positions[f[2]]);
  const MeshReport r = check(m);
  EXPECT_EQ(r.status.code, ErrorCode::DegenerateFace);
  EXPECT_NE(r.status.message.find("face 7"), std::string::npos) << r.status.message;
  IndexedMesh rep = fx::icosphere(1);
  rep.faces[3][1] = rep.faces[3][0];
  EXPECT_EQ(check(rep).status.code, ErrorCode::DegenerateFace);
}

TEST(ValidateMesh, DuplicateFace) {
  IndexedMesh m = fx::icosphere(1);
  m.faces.push_back(m.faces[5]);
  EXPECT_EQ(check(m).status.code, ErrorCode::DuplicateFace);
}

TEST(ValidateMesh, InconsistentOrientation) {
  IndexedMesh m = fx::icosphere(1);
  std::swap(m.faces[4][1], m.faces[4][2]);
  const MeshReport r = check(m);
  EXPECT_EQ(r.status.code, ErrorCode::InconsistentOrientation);
  EXPECT_NE(r.status.message.find("3 edges"), std::string::npos) << r.status.message;
}

TEST(ValidateMesh, InvalidCoordinates) {
  IndexedMesh m = fx::icosphere(1);
  m.positions[9].x() = std::numeric_limits<double>::quiet_NaN();
  MeshReport r = check(m);
  EXPECT_EQ(r.status.code, ErrorCode::InvalidCoordinates);
  EXPECT_NE(r.status.message.find("vertex 9"), std::string::npos);
  m.positions[9].x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(check(m).status.code, ErrorCode::InvalidCoordinates);
}

TEST(ValidateMesh, FaceIndexOutOfRange) {
  IndexedMesh m = fx::tetrahedron();
  m.faces[0][2] = 17;
  EXPECT_EQ(check(m).status.code, ErrorCode::MalformedMesh);
}

TEST(ValidateMesh, UnreferencedVerticesOnlyWarn) {
  IndexedMesh m = fx::icosphere(1);
  m.positions.push_back(Vec3(5, 5, 5));
  m.positions.push_back(Vec3(std::nan(""), 0, 0));  // unreferenced: ignored even if not finite
  const MeshReport r = check(m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.unreferencedVertices, 2);
  EXPECT_EQ(r.genus, 0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("2 unreferenced"), std::string::npos);
}

// Front ends name the file: in the first problem and in every warning, and "mesh 'PATH'" for a
// mesh validated without a role.
TEST(ValidateMesh, NameMeshFileNamesTheFileInStatusAndWarnings) {
  IndexedMesh m = fx::icosphere(1);
  m.positions.push_back(Vec3(5, 5, 5));
  MeshReport ok = validateMesh(m, "source");
  nameMeshFile(ok, "dir/cow.off");
  ASSERT_TRUE(ok.status.ok());
  ASSERT_EQ(ok.warnings.size(), 1u);
  EXPECT_EQ(ok.warnings[0].rfind("source mesh 'dir/cow.off': 1 unreferenced vertex ignored", 0), 0u) << ok.warnings[0];
  m.positions[0] = Vec3(std::nan(""), 0, 0);
  MeshReport bad = validateMesh(m, "");
  nameMeshFile(bad, "x.off");
  EXPECT_EQ(bad.status.code, ErrorCode::InvalidCoordinates);
  EXPECT_EQ(bad.status.message.rfind("mesh 'x.off': 1 vertex with NaN", 0), 0u) << bad.status.message;
  EXPECT_EQ(bad.warnings.at(0).rfind("mesh 'x.off': 1 unreferenced vertex", 0), 0u) << bad.warnings[0];
}

// --- validateInput: the pair and its anchors -------------------------------------------

namespace {
AnchorSet namedAt(const IndexedMesh& m, const std::vector<int>& verts, const std::string& label) {
  AnchorSet s;
  s.source = label;
  for (size_t k = 0; k < verts.size(); ++k) {
    Anchor a;
    a.name = "a" + std::to_string(k);
    a.position = m.positions[verts[k]];
    a.hasPosition = true;
    a.line = static_cast<int>(k) + 1;
    s.anchors.push_back(a);
  }
  return s;
}
}  // namespace

TEST(ValidateInput, AcceptsAMatchingPair) {
  const IndexedMesh s = fx::icosphere(2), t = fx::icosphere(3);
  AnchorSet sa = namedAt(s, {0, 1, 2, 3, 4, 5}, "src"), ta = namedAt(t, {0, 1, 2, 3, 4, 5}, "tgt");
  std::reverse(ta.anchors.begin(), ta.anchors.end());  // order does not matter, names do
  const InputReport r = validateInput(s, t, sa, ta);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.anchors.size(), 6);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(r.anchors.names[k], "a" + std::to_string(k));
    EXPECT_EQ(r.anchors.source[k].vertex, k);
    EXPECT_EQ(r.anchors.target[k].vertex, k);  // icosphere levels share the first vertices
    EXPECT_LT(r.anchors.source[k].snapDistance, 1e-12);
  }
}

TEST(ValidateInput, GenusMismatch) {
  const IndexedMesh s = fx::icosphere(2), t = fx::torus(2, 0.5, 20, 10);
  const InputReport r = validateInput(s, t, namedAt(s, {0, 1, 2}, "s"), namedAt(t, {0, 5, 9}, "t"));
  EXPECT_EQ(r.status.code, ErrorCode::GenusMismatch);
  EXPECT_NE(r.status.message.find("genus 0"), std::string::npos);
  EXPECT_NE(r.status.message.find("genus 1"), std::string::npos);
}

static IndexedMesh reversed(IndexedMesh m) {
  for (auto& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

TEST(ValidateInput, OneSurfaceInsideOutIsAnOrientationMismatch) {
  // The enclosed volume, signed by the faces' orientation: a unit icosphere's is just under
  // 4/3 pi (its flat faces lie inside the sphere), the reversed one's its negative.
  const IndexedMesh s = fx::icosphere(3), in = reversed(s);
  const MeshReport out = validateMesh(s, "s"), inv = validateMesh(in, "in");
  ASSERT_TRUE(out.status.ok() && inv.status.ok());
  EXPECT_LT(out.enclosedVolume, 4.0 / 3.0 * M_PI);
  EXPECT_GT(out.enclosedVolume, 0.97 * 4.0 / 3.0 * M_PI);
  EXPECT_NEAR(inv.enclosedVolume, -out.enclosedVolume, 1e-9);
  // A torus of radii 2 and 0.5: 2 pi^2 R r^2 = pi^2, less by the facets.
  const MeshReport torus = validateMesh(fx::torus(2, 0.5, 60, 30), "torus");
  EXPECT_GT(torus.enclosedVolume, 0.97 * M_PI * M_PI);
  EXPECT_LT(torus.enclosedVolume, M_PI * M_PI);
  const MeshReport plate = validateMesh(fx::holedPlate(3, 2, 5), "plate");
  EXPECT_GT(plate.enclosedVolume, 0);

  const InputReport r = validateInput(in, s, namedAt(in, {0, 1, 2}, "a"), namedAt(s, {0, 1, 2}, "a"));
  EXPECT_EQ(r.status.code, ErrorCode::OrientationMismatch);
  EXPECT_NE(r.status.message.find("the source mesh's faces point inward"), std::string::npos) << r.status.message;
  EXPECT_NE(r.status.message.find("Invert Faces Orientation"), std::string::npos) << r.status.message;
  const InputReport t = validateInput(s, in, namedAt(s, {0, 1, 2}, "a"), namedAt(in, {0, 1, 2}, "a"));
  EXPECT_EQ(t.status.code, ErrorCode::OrientationMismatch);
  EXPECT_NE(t.status.message.find("the target mesh's faces point inward"), std::string::npos) << t.status.message;
  // Both inside out: the orientations agree, and the pair is processed.
  const InputReport both = validateInput(in, in, namedAt(in, {0, 1, 2}, "a"), namedAt(in, {0, 1, 2}, "a"));
  EXPECT_TRUE(both.status.ok()) << both.status.message;
}

TEST(ValidateInput, TooFewAnchors) {
  const IndexedMesh s = fx::icosphere(2);
  const InputReport r = validateInput(s, s, namedAt(s, {0, 1}, "s"), namedAt(s, {0, 1}, "t"));
  EXPECT_EQ(r.status.code, ErrorCode::TooFewAnchors);
}

TEST(ValidateInput, OneAnchorIsCountedInTheSingular) {
  const IndexedMesh s = fx::icosphere(2);
  const InputReport r = validateInput(s, s, namedAt(s, {0}, "s"), namedAt(s, {0}, "t"));
  EXPECT_EQ(r.status.code, ErrorCode::TooFewAnchors);
  EXPECT_EQ(r.status.message.rfind("1 corresponding anchor given; at least 3", 0), 0u) << r.status.message;
}

TEST(ValidateInput, SnapToleranceOutsideZeroToOneIsRefused) {
  const IndexedMesh s = fx::icosphere(2);
  ValidationOptions o;
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -0.01, 1.5}) {
    o.snapTolerance = bad;
    const InputReport r = validateInput(s, s, namedAt(s, {0, 1, 2}, "s"), namedAt(s, {0, 1, 2}, "t"), o);
    EXPECT_EQ(r.status.code, ErrorCode::InvalidArgument);
    EXPECT_NE(r.status.message.find("snap tolerance must be a number in [0, 1]"), std::string::npos) << r.status.message;
  }
  o.snapTolerance = 0.01;
  o.degenerateAreaRelative = -1;
  EXPECT_EQ(validateInput(s, s, namedAt(s, {0, 1, 2}, "s"), namedAt(s, {0, 1, 2}, "t"), o).status.code,
            ErrorCode::InvalidArgument);
}

TEST(ValidateInput, BadSourceMeshIsReportedFirst) {
  const IndexedMesh s = fx::openCone(8), t = fx::icosphere(1);
  const InputReport r = validateInput(s, t, namedAt(s, {0, 1, 2}, "s"), namedAt(t, {0, 1, 2}, "t"));
  EXPECT_EQ(r.status.code, ErrorCode::OpenBoundary);
  EXPECT_EQ(r.status.message.rfind("source mesh", 0), 0u) << r.status.message;
}

TEST(ValidateInput, TooManyAnchors) {
  const IndexedMesh s = fx::icosphere(1);  // 42 vertices: every vertex may be an anchor
  std::vector<int> all;
  for (int v = 0; v < 42; ++v) all.push_back(v);
  EXPECT_TRUE(validateInput(s, s, namedAt(s, all, "s"), namedAt(s, all, "t")).status.ok());
  all.push_back(0);  // one more anchor than vertices
  const AnchorSet a = namedAt(s, all, "s");
  EXPECT_EQ(validateInput(s, s, a, a).status.code, ErrorCode::TooManyAnchors);
}
