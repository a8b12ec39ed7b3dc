// Writing layouts for MeshLab (layout_io.h): layout.ply, clusters.ply and paths.ply load back with
// the layout's geometry, counts, per-patch / per-cluster / per-path colours and qualities; the folder
// is created; an unwritable folder is an OutputError.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "cbd/anchor_sampling.h"
#include "cbd/layout_io.h"
#include "cbd/source_layout.h"
#include "cbd/validate_input.h"
#include "support/fixtures.h"

// After cbd/mesh.h: vcglib's importer needs the mesh headers first.
#include <wrap/io_trimesh/import_ply.h>

using namespace cbd;
namespace fx = cbd::fixtures;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / ("cbd_test_layout_io_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

Layout sphereLayout() {
  const IndexedMesh m = fx::icosphere(2);
  SourceLayoutResult r = buildSourceLayout(m, farthestPointSampling(m, 8));
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return std::move(r.layout);
}

bool sameColour(const vcg::Color4b& c, const std::array<unsigned char, 3>& rgb) {
  return c[0] == rgb[0] && c[1] == rgb[1] && c[2] == rgb[2] && c[3] == 255;
}

/// A face mesh written by writeLayout: the layout's refined mesh, face by face, with the label of
/// every face as its quality and its palette colour.
void expectLabelledMesh(const std::string& path, const Layout& L, const std::vector<int>& label) {
  Mesh m;
  const LoadResult r = loadMesh(path, m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(m.VN(), L.mesh.vertexCount());
  ASSERT_EQ(m.FN(), L.mesh.faceCount());
  for (int v = 0; v < m.VN(); ++v) {
    const auto& p = m.vert[v].cP();
    EXPECT_LT((Vec3(p[0], p[1], p[2]) - L.mesh.position(v)).norm(), 1e-12) << path << ": vertex " << v;
  }
  for (int f = 0; f < m.FN(); ++f) {
    const auto corners = L.mesh.faceVertices(f);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.face[f].cV(k) - &m.vert[0], corners[k]) << path << ": face " << f;
    EXPECT_EQ(m.face[f].cQ(), label[f]) << path << ": face " << f;
    EXPECT_TRUE(sameColour(m.face[f].cC(), paletteColor(label[f]))) << path << ": face " << f;
  }
  // What MeshLab opens is the closed surface the layout is on.
  const MeshReport rep = validateMesh(toIndexed(m), path);
  EXPECT_TRUE(rep.status.ok()) << rep.status.message;
}

}  // namespace

TEST(LayoutIO, WritesTheLayoutItsClustersAndItsPathsIntoANewFolder) {
  const Layout L = sphereLayout();
  ASSERT_FALSE(L.faceCluster.empty());
  TempDir tmp("write");
  const fs::path dir = tmp.path / "source" / "layout";  // created, parents too
  const Status s = writeLayout(L, dir.string());
  ASSERT_TRUE(s.ok()) << s.message;
  expectLabelledMesh((dir / kLayoutFile).string(), L, L.facePatch);
  expectLabelledMesh((dir / kClustersFile).string(), L, L.faceCluster);

  // paths.ply: every layout edge as a polyline of its own vertices, quality = edge index.
  Mesh paths;
  int mask = 0;
  ASSERT_EQ(vcg::tri::io::ImporterPLY<Mesh>::Open(paths, (dir / kPathsFile).string().c_str(), mask), 0);
  EXPECT_EQ(paths.FN(), 0);
  size_t vertices = 0, edges = 0;
  for (const LayoutEdge& e : L.edges) vertices += e.vertices.size(), edges += e.vertices.size() - 1;
  ASSERT_EQ(static_cast<size_t>(paths.VN()), vertices);
  ASSERT_EQ(static_cast<size_t>(paths.EN()), edges);
  size_t at = 0, edge = 0;
  for (size_t p = 0; p < L.edges.size(); ++p) {
    const std::vector<int>& chain = L.edges[p].vertices;
    for (size_t k = 0; k < chain.size(); ++k, ++at) {
      const auto& x = paths.vert[at].cP();
      EXPECT_LT((Vec3(x[0], x[1], x[2]) - L.mesh.position(chain[k])).norm(), 1e-12) << "path " << p;
      EXPECT_EQ(paths.vert[at].cQ(), static_cast<double>(p));
      EXPECT_TRUE(sameColour(paths.vert[at].cC(), paletteColor(static_cast<int>(p)))) << "path " << p;
    }
    for (size_t k = 0; k + 1 < chain.size(); ++k, ++edge) {
      const size_t first = at - chain.size() + k;
      EXPECT_EQ(static_cast<size_t>(paths.edge[edge].cV(0) - &paths.vert[0]), first) << "path " << p;
      EXPECT_EQ(static_cast<size_t>(paths.edge[edge].cV(1) - &paths.vert[0]), first + 1) << "path " << p;
    }
  }
  // Nothing else: no temporary left behind.
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.insert(entry.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{kLayoutFile, kPathsFile, kClustersFile}));
}

TEST(LayoutIO, ALayoutWithoutClustersWritesNoClusterFile) {
  Layout L = sphereLayout();
  L.faceCluster.clear();
  TempDir tmp("noclusters");
  ASSERT_TRUE(writeLayout(L, tmp.path.string()).ok());
  EXPECT_TRUE(fs::exists(tmp.path / kLayoutFile));
  EXPECT_TRUE(fs::exists(tmp.path / kPathsFile));
  EXPECT_FALSE(fs::exists(tmp.path / kClustersFile));
  // Over an earlier layout with clusters, its clusters.ply goes too: one layout per folder.
  const Layout withClusters = sphereLayout();
  ASSERT_TRUE(writeLayout(withClusters, tmp.path.string()).ok());
  ASSERT_TRUE(fs::exists(tmp.path / kClustersFile));
  ASSERT_TRUE(writeLayout(L, tmp.path.string()).ok());
  EXPECT_FALSE(fs::exists(tmp.path / kClustersFile));
}

TEST(LayoutIO, AFolderThatCannotBeMadeOrWrittenIsAnOutputError) {
  const Layout L = sphereLayout();
  TempDir tmp("unwritable");
  // A regular file where a folder on the path should be (root may write anywhere else).
  const fs::path file = tmp.path / "file";
  std::ofstream(file) << "x";
  const Status s = writeLayout(L, (file / "layout").string());
  EXPECT_EQ(s.code, ErrorCode::OutputError);
  EXPECT_NE(s.message.find((file / "layout").string()), std::string::npos) << s.message;
  // The folder exists, but a folder squats where layout.ply goes.
  const fs::path dir = tmp.path / "squatted";
  fs::create_directories(dir / kLayoutFile / "inside");
  EXPECT_EQ(writeLayout(L, dir.string()).code, ErrorCode::OutputError);
}

TEST(LayoutIO, PaletteColoursAreDistinctAndTheSameOnEverySurface) {
  std::set<std::array<unsigned char, 3>> seen;
  for (int k = 0; k < 64; ++k) {
    const auto c = paletteColor(k);
    EXPECT_TRUE(seen.insert(c).second) << "colour " << k << " repeats an earlier one";
    EXPECT_EQ(paletteColor(k), c);
    // Consecutive indices (neighbouring patches are often consecutive) visibly apart.
    if (k > 0) {
      const auto p = paletteColor(k - 1);
      const int d = std::abs(c[0] - p[0]) + std::abs(c[1] - p[1]) + std::abs(c[2] - p[2]);
      EXPECT_GT(d, 60) << "colours " << k - 1 << " and " << k;
    }
  }
}
