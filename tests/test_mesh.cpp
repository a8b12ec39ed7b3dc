// Loading PLY/OFF/COFF/OBJ/STL through vcglib and writing PLY with colour and quality.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "cbd/map_io.h"
#include "cbd/mesh.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;
namespace fs = std::filesystem;

namespace {
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("cbd_test_io_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& n) const { return (path / n).string(); }
};
void write(const std::string& p, const std::string& text) { std::ofstream(p) << text; }
}  // namespace

TEST(MeshIO, OffRoundTripThroughPly) {
  TempDir d;
  const IndexedMesh sphere = fx::icosphere(2);
  ASSERT_TRUE(fx::writeOff(d.file("s.off"), sphere));
  Mesh m;
  LoadResult r = loadMesh(d.file("s.off"), m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_FALSE(r.hadPolygons);
  IndexedMesh back = toIndexed(m);
  ASSERT_EQ(back.vertexCount(), sphere.vertexCount());
  ASSERT_EQ(back.faceCount(), sphere.faceCount());
  EXPECT_EQ(back.faces, sphere.faces);
  for (int v = 0; v < sphere.vertexCount(); ++v) EXPECT_LT((back.positions[v] - sphere.positions[v]).norm(), 1e-6);

  for (size_t f = 0; f < m.face.size(); ++f) {
    m.face[f].C() = vcg::Color4b(static_cast<unsigned char>(f % 256), 10, 20, 255);
    m.face[f].Q() = 0.5 * static_cast<double>(f);
  }
  for (size_t v = 0; v < m.vert.size(); ++v) m.vert[v].C() = vcg::Color4b(1, 2, static_cast<unsigned char>(v % 256), 255);
  SavePlyOptions opt;
  opt.faceColor = opt.faceQuality = opt.vertexColor = true;
  ASSERT_TRUE(savePly(d.file("s.ply"), m, opt).ok());
  EXPECT_FALSE(fs::exists(d.file(".s.ply.tmp")));
  Mesh m2;
  r = loadMesh(d.file("s.ply"), m2);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.hasVertexColor);
  ASSERT_EQ(m2.FN(), m.FN());
  for (size_t f = 0; f < m.face.size(); ++f) {
    EXPECT_EQ(m2.face[f].C(), m.face[f].C());
    EXPECT_DOUBLE_EQ(m2.face[f].Q(), m.face[f].Q());
  }
  EXPECT_EQ(m2.vert[42].C(), m.vert[42].C());
  // Positions survive a PLY round trip in double precision.
  EXPECT_EQ(toIndexed(m2).positions[5], toIndexed(m).positions[5]);
}

// Face index lists of every integer type, binary (both byte orders) and ASCII, with a double
// coordinate, a vertex colour, a face property and a second face list (texture coordinates,
// whose count has the same type: vcglib crashed on some): the same mesh each time, with 42 vertices (indices
// fit every type) and 642 (indices past 255 and 127, for the types wider than a byte). vcglib
// 2020.09 misreads many of these (ushort/short/uint counts, uchar/char/ushort indices: faces
// lost, or wrong indices loaded silently); loadMesh hands it a copy with an `int int` list.
TEST(MeshIO, FaceListsOfEveryIntegerTypeGiveTheSameMesh) {
  TempDir d;
  auto temporaries = [] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
      n += e.path().filename().string().rfind("cbd-ply-", 0) == 0;
    return n;
  };
  const int temporariesBefore = temporaries();
  int files = 0;
  const std::vector<std::pair<std::string, int>> types = {{"uchar", 1}, {"char", 1},   {"ushort", 2}, {"short", 2},
                                                          {"uint", 4},  {"int", 4},    {"uint8", 1},  {"int16", 2},
                                                          {"uint16", 2}, {"uint32", 4}, {"int32", 4}};
  auto encode = [](std::string& out, std::int64_t v, int size, bool little) {
    for (int k = 0; k < size; ++k) {
      const char byte = static_cast<char>(v >> (8 * (little ? k : size - 1 - k)));
      out += byte;
    }
  };
  for (const int levels : {1, 3}) {
    const IndexedMesh sphere = fx::icosphere(levels);
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"})
      for (const auto& [countType, countSize] : types)
        for (const auto& [indexType, indexSize] : types) {
          if (sphere.vertexCount() > 127 && indexSize == 1) continue;
          const bool little = format == "binary_little_endian";
          std::string ply = "ply\nformat " + format + " 1.0\ncomment list " + countType + " " + indexType +
                            "\nelement vertex " + std::to_string(sphere.vertexCount()) +
                            "\nproperty double x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar "
                            "green\nproperty uchar blue\nelement face " + std::to_string(sphere.faceCount()) +
                            "\nproperty list " + countType + " " + indexType + " vertex_indices\nproperty float quality\n"
                            "property list " + countType + " float texcoord\nend_header\n";
          for (int v = 0; v < sphere.vertexCount(); ++v) {
            const Vec3& p = sphere.positions[v];
            if (format == "ascii") {
              ply += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + " 7 8 " +
                     std::to_string(v % 256) + "\n";
              continue;
            }
            const double x = std::stod(std::to_string(p.x()));  // a double, the others floats
            std::uint64_t xbits;
            std::memcpy(&xbits, &x, 8);
            encode(ply, static_cast<std::int64_t>(xbits), 8, little);
            for (int k = 1; k < 3; ++k) {
              const float c = static_cast<float>(std::stod(std::to_string(p[k])));
              std::uint32_t bits;
              std::memcpy(&bits, &c, 4);
              encode(ply, bits, 4, little);
            }
            ply += '\x07', ply += '\x08', ply += static_cast<char>(v % 256);
          }
          for (int f = 0; f < sphere.faceCount(); ++f) {
            const auto& t = sphere.faces[f];
            if (format == "ascii") {
              ply += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
                     " 0.5 6 0 0 1 0 0 1\n";
              continue;
            }
            encode(ply, 3, countSize, little);
            for (int k = 0; k < 3; ++k) encode(ply, t[k], indexSize, little);
            const float q = 0.5f;
            std::uint32_t bits;
            std::memcpy(&bits, &q, 4);
            encode(ply, bits, 4, little);
            // A second face list (per-corner texture coordinates) of the same count type.
            encode(ply, 6, countSize, little);
            for (const float c : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f}) {
              std::memcpy(&bits, &c, 4);
              encode(ply, bits, 4, little);
            }
          }
          const std::string name =
              d.file(std::to_string(sphere.vertexCount()) + "_" + format + "_" + countType + "_" + indexType + ".ply");
          std::ofstream(name, std::ios::binary) << ply;
          Mesh m;
          const LoadResult r = loadMesh(name, m);
          ASSERT_TRUE(r.status.ok()) << name << ": " << r.status.message;
          const IndexedMesh back = toIndexed(m);
          ASSERT_EQ(back.faces, sphere.faces) << name;
          ASSERT_EQ(back.vertexCount(), sphere.vertexCount()) << name;
          for (int v = 0; v < sphere.vertexCount(); ++v) {
            ASSERT_LT((back.positions[v] - sphere.positions[v]).norm(), 1e-5) << name << " vertex " << v;
            ASSERT_EQ(m.vert[v].C(), vcg::Color4b(7, 8, static_cast<unsigned char>(v % 256), 255))
                << name << " vertex " << v;
          }
          ++files;
        }
  }
  EXPECT_EQ(files, 3 * 11 * 11 + 3 * 11 * 8);  // 8 types wider than a byte for 642 vertices
  EXPECT_EQ(temporaries(), temporariesBefore);  // no temporary copy left behind
}

// M_st carries the target's per-vertex texture coordinates (interpolated at each image), and
// mst.ply must keep them: written as texture_u/texture_v, read back as the same numbers.
TEST(MeshIO, TransferredTextureCoordinatesAreWrittenAndReadBack) {
  TempDir d;
  const IndexedMesh sphere = fx::icosphere(2);
  Mesh onto;
  fromIndexed(sphere, onto);
  for (auto& v : onto.vert) v.T() = vcg::TexCoord2d(0.5 + 0.5 * v.P()[0], 0.25 + 0.5 * v.P()[1]);
  // Every vertex of the mapped mesh at the centroid of a face of `onto` (vertex v on face v), so
  // each must get the mean of that face's corners' coordinates.
  const int n = sphere.vertexCount();
  ASSERT_LE(n, sphere.faceCount());
  std::vector<FacePoint> points(n);
  std::vector<Vec3> image(n);
  for (int v = 0; v < n; ++v) {
    points[v].face = v;
    points[v].bary = Vec3::Constant(1.0 / 3.0);
    const auto& t = sphere.faces[v];
    image[v] = (sphere.positions[t[0]] + sphere.positions[t[1]] + sphere.positions[t[2]]) / 3.0;
  }
  Mesh out;
  buildMappedMesh(onto, image, points, onto, TransferOptions{false, false, true},
                  std::vector<double>(sphere.faceCount(), 1.0), out);
  SavePlyOptions opt;
  opt.vertexTexCoord = true;
  ASSERT_TRUE(savePly(d.file("mst.ply"), out, opt).ok());
  Mesh back;
  const LoadResult r = loadMesh(d.file("mst.ply"), back);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.hasVertexTexCoord);
  ASSERT_EQ(back.VN(), n);
  double spread = 0;
  for (int v = 0; v < n; ++v) {
    const auto& t = sphere.faces[v];
    double u = 0, w = 0;
    for (int k = 0; k < 3; ++k) u += onto.vert[t[k]].T().U() / 3.0, w += onto.vert[t[k]].T().V() / 3.0;
    EXPECT_NEAR(back.vert[v].T().U(), u, 1e-6) << v;  // PLY stores them as float
    EXPECT_NEAR(back.vert[v].T().V(), w, 1e-6) << v;
    EXPECT_LT((toIndexed(back).positions[v] - image[v]).norm(), 1e-6);
    spread = std::max(spread, std::abs(back.vert[v].T().U() - back.vert[0].T().U()));
  }
  EXPECT_GT(spread, 0.1);  // the coordinates vary over the sphere: not one value everywhere
  // Without the option the file has none.
  ASSERT_TRUE(savePly(d.file("plain.ply"), out, SavePlyOptions{}).ok());
  Mesh plain;
  EXPECT_FALSE(loadMesh(d.file("plain.ply"), plain).hasVertexTexCoord);
}

TEST(MeshIO, ColouredOff) {
  TempDir d;
  write(d.file("c.off"),
        "COFF\n4 4 0\n1 1 1 255 0 0 255\n1 -1 -1 0 255 0 255\n-1 1 -1 0 0 255 255\n-1 -1 1 9 9 9 255\n"
        "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  Mesh m;
  const LoadResult r = loadMesh(d.file("c.off"), m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.hasVertexColor);
  EXPECT_EQ(m.VN(), 4);
  EXPECT_EQ(m.vert[0].C(), vcg::Color4b(255, 0, 0, 255));
  EXPECT_EQ(m.vert[2].C(), vcg::Color4b(0, 0, 255, 255));
}

TEST(MeshIO, PolygonsAreReported) {
  TempDir d;
  write(d.file("cube.off"),
        "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
        "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  Mesh m;
  const LoadResult r = loadMesh(d.file("cube.off"), m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.hadPolygons);
  EXPECT_EQ(m.FN(), 12);
}

TEST(MeshIO, ObjAndStl) {
  TempDir d;
  write(d.file("t.obj"), "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  Mesh m;
  LoadResult r = loadMesh(d.file("t.obj"), m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(m.VN(), 4);
  EXPECT_EQ(m.FN(), 4);
  const IndexedMesh tet = fx::tetrahedron();
  std::string stl = "solid t\n";
  for (const auto& f : tet.faces) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int v : f) {
      const Vec3& p = tet.positions[v];
      stl += "vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
    }
    stl += "endloop\nendfacet\n";
  }
  stl += "endsolid t\n";
  write(d.file("t.stl"), stl);
  Mesh s;
  r = loadMesh(d.file("t.stl"), s);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(s.FN(), 4);
  EXPECT_EQ(s.VN(), 4);  // the triangle soup is welded
}

// An STL soup is welded by exact coordinates (-0 as +0): vertex i is the file's i-th distinct
// corner (anchors given as vertex indices keep their meaning), a facet left with a repeated
// corner is dropped, and corners at a NaN point ('nan' or '-nan') weld too, so validation counts
// the bad vertex once, in ASCII and binary files alike.
TEST(MeshIO, StlWeldKeepsFileOrderAndWeldsNaNCorners) {
  TempDir d;
  const IndexedMesh tet = fx::tetrahedron();
  for (const bool nanCorner : {false, true}) {
    std::vector<Vec3> p = tet.positions;
    if (nanCorner) p[3].y() = std::nan("");
    p[1].z() = 0.0;  // written as -0 at every other appearance: -0 and +0 are one coordinate
    int appearances = 0, nanAppearances = 0;
    std::string ascii = "solid t\n", bin(80, ' ');
    // The tetrahedron's facets, then a sliver on two of its corners (vertex 0 twice).
    std::vector<std::array<int, 3>> facets(tet.faces.begin(), tet.faces.end());
    facets.push_back({0, 1, 0});
    const std::uint32_t nf = static_cast<std::uint32_t>(facets.size());
    bin.append(reinterpret_cast<const char*>(&nf), 4);
    for (const auto& f : facets) {
      ascii += "facet normal 0 0 0\nouter loop\n";
      bin.append(12, '\0');
      for (int v : f) {
        ascii += "vertex";
        const bool negativeZero = v == 1 && appearances++ % 2 == 1;
        for (int c = 0; c < 3; ++c) {
          double value = negativeZero && c == 2 ? -0.0 : p[v][c];
          if (std::isnan(value)) value = std::copysign(value, nanAppearances++ % 2 ? -1.0 : 1.0);  // nan, -nan
          char num[64];
          std::snprintf(num, sizeof num, " %.17g", value);
          ascii += num;
          const float x = static_cast<float>(value);
          bin.append(reinterpret_cast<const char*>(&x), 4);
        }
        ascii += "\n";
      }
      ascii += "endloop\nendfacet\n";
      bin.append(2, '\0');
    }
    ascii += "endsolid t\n";
    write(d.file("a.stl"), ascii);
    write(d.file("b.stl"), bin);
    for (const char* name : {"a.stl", "b.stl"}) {
      Mesh m;
      const LoadResult r = loadMesh(d.file(name), m);
      ASSERT_TRUE(r.status.ok()) << name << ": " << r.status.message;
      ASSERT_EQ(m.VN(), 4) << name << (nanCorner ? " with a NaN corner" : "");
      ASSERT_EQ(m.FN(), 4) << name;
      // First appearances in the file: the first face's corners, then the one vertex it lacks.
      std::vector<int> order(tet.faces[0].begin(), tet.faces[0].end());
      for (int v = 0; v < 4; ++v)
        if (std::find(order.begin(), order.end(), v) == order.end()) order.push_back(v);
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) {
          const double want = static_cast<float>(p[order[i]][c]), got = m.vert[i].cP()[c];
          if (std::isnan(want)) EXPECT_TRUE(std::isnan(got)) << name << " vertex " << i;
          else EXPECT_NEAR(got, want, 1e-6) << name << " vertex " << i;
        }
      // The faces are the tetrahedron's, in its vertex numbering mapped through that order.
      for (size_t f = 0; f < tet.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
          const int idx = static_cast<int>(m.face[f].cV(k) - &m.vert[0]);
          EXPECT_EQ(order[idx], tet.faces[f][k]) << name << " face " << f;
        }
      const MeshReport rep = validateMesh(toIndexed(m), "source", r.hadPolygons);
      if (nanCorner) {
        EXPECT_EQ(rep.status.code, ErrorCode::InvalidCoordinates) << name;
        EXPECT_NE(rep.status.message.find("1 vertex with NaN"), std::string::npos) << rep.status.message;
      } else {
        EXPECT_TRUE(rep.status.ok()) << name << ": " << rep.status.message;
      }
    }
  }
}

// A NaN or infinite coordinate is read in every text format (as MeshLab reads it) and left to
// validation, which names the vertex (InvalidCoordinates), rather than a parse error naming a
// line; in an integer PLY property it is no number and the file is malformed.
TEST(MeshIO, NonFiniteCoordinatesAreReadForValidationToReport) {
  TempDir d;
  const std::string plyHead =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string plyFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  write(d.file("n.ply"), plyHead + "1 1 1\n1 -1 -1\n-1 1 -1\nnan -1 1\n" + plyFaces);
  write(d.file("n.obj"), "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 inf\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  write(d.file("n.off"), "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 NaN 1\n" + plyFaces);
  write(d.file("n.stl"), "solid n\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 -inf 0\n"
                         "endloop\nendfacet\nendsolid n\n");
  for (const char* name : {"n.ply", "n.obj", "n.off", "n.stl"}) {
    Mesh m;
    const LoadResult r = loadMesh(d.file(name), m);
    ASSERT_TRUE(r.status.ok()) << name << ": " << r.status.message;
    int nonFinite = 0;
    for (const auto& v : m.vert) nonFinite += !(std::isfinite(v.cP()[0]) && std::isfinite(v.cP()[1]) && std::isfinite(v.cP()[2]));
    EXPECT_EQ(nonFinite, 1) << name;
    const MeshReport rep = validateMesh(toIndexed(m), "source", r.hadPolygons);
    EXPECT_EQ(rep.status.code, ErrorCode::InvalidCoordinates) << name << ": " << rep.status.message;
  }
  // An integer property holds no NaN.
  write(d.file("i.ply"), "ply\nformat ascii 1.0\nelement vertex 4\nproperty int x\nproperty int y\nproperty int z\n"
                         "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                         "1 1 1\n1 -1 -1\n-1 1 -1\nnan -1 1\n" + plyFaces);
  Mesh m;
  EXPECT_EQ(loadMesh(d.file("i.ply"), m).status.code, ErrorCode::MalformedMesh);
}

TEST(MeshIO, Errors) {
  TempDir d;
  Mesh m;
  EXPECT_EQ(loadMesh(d.file("missing.off"), m).status.code, ErrorCode::FileNotFound);
  write(d.file("x.xyz"), "1 2 3\n");
  EXPECT_EQ(loadMesh(d.file("x.xyz"), m).status.code, ErrorCode::UnsupportedFormat);
  write(d.file("empty.off"), "");
  EXPECT_EQ(loadMesh(d.file("empty.off"), m).status.code, ErrorCode::MalformedMesh);
  write(d.file("trunc.off"), "OFF\n4 4 0\n1 1 1\n1 -1 -1\n");
  EXPECT_EQ(loadMesh(d.file("trunc.off"), m).status.code, ErrorCode::MalformedMesh);
  write(d.file("trunc.ply"), "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n");
  EXPECT_EQ(loadMesh(d.file("trunc.ply"), m).status.code, ErrorCode::MalformedMesh);
  // More faces in the file than its header counts (CGAL's prim.off): read as counted, as MeshLab
  // does, with a warning.
  write(d.file("long.off"), "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const LoadResult longOff = loadMesh(d.file("long.off"), m);
  ASSERT_TRUE(longOff.status.ok()) << longOff.status.message;
  EXPECT_EQ(m.FN(), 3);
  ASSERT_EQ(longOff.warnings.size(), 1u);
  EXPECT_NE(longOff.warnings[0].find("1 line after the header's 4 vertices and 3 faces"), std::string::npos)
      << longOff.warnings[0];
  // The warning names the file, once (callers pass it on as it is).
  const std::string named = "'" + d.file("long.off") + "': ";
  EXPECT_EQ(longOff.warnings[0].rfind(named, 0), 0u) << longOff.warnings[0];
  EXPECT_EQ(longOff.warnings[0].find(named, 1), std::string::npos) << longOff.warnings[0];
  EXPECT_TRUE(loadMesh(d.file("missing.off"), m).warnings.empty());
  // A folder or a device is named as such.
  const Status folder = loadMesh(d.path.string(), m).status;
  EXPECT_EQ(folder.code, ErrorCode::FileNotFound);
  EXPECT_NE(folder.message.find("is a folder"), std::string::npos) << folder.message;
  const Status device = loadMesh("/dev/null", m).status;
  EXPECT_EQ(device.code, ErrorCode::FileNotFound);
  EXPECT_NE(device.message.find("not a regular file"), std::string::npos) << device.message;
  write(d.file("novert.off"), "OFF\n0 0 0\n");
  const auto code = loadMesh(d.file("novert.off"), m).status.code;
  EXPECT_TRUE(code == ErrorCode::EmptyMesh || code == ErrorCode::MalformedMesh);
  SavePlyOptions opt;
  EXPECT_EQ(savePly(d.file("nodir/x.ply"), m, opt).code, ErrorCode::OutputError);
}

TEST(MeshIO, FuzzRegressions) {
  // Found by tests/fuzz/fuzz_mesh: an OFF face with a negative or too-large vertex index made
  // vcglib index out of bounds; a short ASCII STL was sometimes read as binary.
  TempDir d;
  Mesh m;
  write(d.file("neg.off"), "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 -2\n3 0 2 3\n3 1 3 2\n");
  EXPECT_EQ(loadMesh(d.file("neg.off"), m).status.code, ErrorCode::MalformedMesh);
  write(d.file("big.off"), "OFF\n4 1 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 99\n");
  EXPECT_EQ(loadMesh(d.file("big.off"), m).status.code, ErrorCode::MalformedMesh);
  write(d.file("short.off"), "OFF\n4 4 0\n1 1 1\n");
  EXPECT_EQ(loadMesh(d.file("short.off"), m).status.code, ErrorCode::MalformedMesh);
  write(d.file("junk.stl"), "this is not an stl file at all, just text long enough to look like a header......\n");
  EXPECT_EQ(loadMesh(d.file("junk.stl"), m).status.code, ErrorCode::MalformedMesh);
  // A binary STL claiming a billion faces in a tiny file.
  std::string bin(80, ' ');
  const uint32_t n = 1000000000u;
  bin.append(reinterpret_cast<const char*>(&n), 4);
  bin.append(50, '\0');
  write(d.file("lie.stl"), bin);
  EXPECT_EQ(loadMesh(d.file("lie.stl"), m).status.code, ErrorCode::MalformedMesh);
}

TEST(Mesh, ClosedEulerCharacteristicIsTwoMinusTwiceTheGenusOverUsedVertices) {
  EXPECT_EQ(closedEulerCharacteristic(fx::icosphere(2)), 2);
  EXPECT_EQ(closedEulerCharacteristic(fx::torus(2.0, 0.7, 30, 12)), 0);
  const IndexedMesh plate = fx::holedPlate(3, 2, 5);
  EXPECT_EQ(closedEulerCharacteristic(plate), validateMesh(plate, "plate").eulerCharacteristic);
  EXPECT_EQ(closedEulerCharacteristic(plate), -4);
  // A vertex no face uses does not count.
  IndexedMesh extra = fx::icosphere(1);
  extra.positions.push_back(Vec3(5, 5, 5));
  EXPECT_EQ(closedEulerCharacteristic(extra), 2);
}
