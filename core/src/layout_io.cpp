#include "cbd/layout_io.h"

#include <cmath>
#include <filesystem>

namespace cbd {

std::array<unsigned char, 3> paletteColor(int k) {
  // Hue by the golden ratio, alternating saturation/value bands so neighbours differ.
  const double h = std::fmod(0.13 + 0.618033988749895 * k, 1.0) * 6.0;
  const double s = (k / 7) % 2 ? 0.55 : 0.75, v = (k / 3) % 2 ? 0.80 : 0.95;
  const int i = static_cast<int>(h);
  const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r, g, b;
  switch (i % 6) {
    case 0: r = v, g = t, b = p; break;
    case 1: r = q, g = v, b = p; break;
    case 2: r = p, g = v, b = t; break;
    case 3: r = p, g = q, b = v; break;
    case 4: r = t, g = p, b = v; break;
    default: r = v, g = p, b = q; break;
  }
  auto c = [](double x) { return static_cast<unsigned char>(std::lround(255 * x)); };
  return {c(r), c(g), c(b)};
}

namespace {
void colourFaces(Mesh& m, const std::vector<int>& label) {
  for (size_t f = 0; f < m.face.size(); ++f) {
    const auto c = paletteColor(label[f]);
    m.face[f].C() = vcg::Color4b(c[0], c[1], c[2], 255);
    m.face[f].Q() = label[f];
  }
}
}  // namespace

Status writeLayout(const Layout& layout, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir)) return Status::error(ErrorCode::OutputError, "cannot create output folder '" + dir + "'");
  Mesh m;
  fromIndexed(layout.mesh.toIndexed(), m);
  vcg::tri::Allocator<Mesh>::CompactVertexVector(m);
  SavePlyOptions faceOpt;
  faceOpt.faceColor = faceOpt.faceQuality = true;
  colourFaces(m, layout.facePatch);
  if (Status s = savePly((fs::path(dir) / kLayoutFile).string(), m, faceOpt); !s) return s;
  if (!layout.faceCluster.empty()) {
    colourFaces(m, layout.faceCluster);
    if (Status s = savePly((fs::path(dir) / kClustersFile).string(), m, faceOpt); !s) return s;
  } else {
    // A clusters.ply of an earlier run (another method) would read as this layout's clusters.
    std::error_code ec;
    const fs::path stale = fs::path(dir) / kClustersFile;
    if (fs::is_regular_file(stale, ec) && !fs::remove(stale, ec))
      return Status::error(ErrorCode::OutputError, "cannot remove the earlier run's '" + stale.string() + "'");
  }
  Mesh paths;
  for (size_t p = 0; p < layout.edges.size(); ++p) {
    const auto& chain = layout.edges[p].vertices;
    auto vi = vcg::tri::Allocator<Mesh>::AddVertices(paths, chain.size());
    const size_t base = paths.vert.size() - chain.size();
    const auto c = paletteColor(static_cast<int>(p));
    for (int v : chain) {
      const Vec3& x = layout.mesh.position(v);
      vi->P() = vcg::Point3d(x.x(), x.y(), x.z());
      vi->C() = vcg::Color4b(c[0], c[1], c[2], 255);
      vi->Q() = static_cast<double>(p);
      ++vi;
    }
    auto ei = vcg::tri::Allocator<Mesh>::AddEdges(paths, chain.size() - 1);
    for (size_t k = 0; k + 1 < chain.size(); ++k, ++ei) {
      ei->V(0) = &paths.vert[base + k];
      ei->V(1) = &paths.vert[base + k + 1];
    }
  }
  SavePlyOptions edgeOpt;
  edgeOpt.edges = edgeOpt.vertexColor = edgeOpt.vertexQuality = true;
  return savePly((fs::path(dir) / kPathsFile).string(), paths, edgeOpt);
}

}  // namespace cbd
