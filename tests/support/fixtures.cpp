#include "support/fixtures.h"

#include "cbd/anchor_sampling.h"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

namespace cbd::fixtures {

IndexedMesh tetrahedron(const Vec3& offset, double scale) {
  IndexedMesh m;
  m.positions = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  for (auto& p : m.positions) p = offset + scale * p;
  m.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return m;
}

IndexedMesh cube() {
  IndexedMesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  // Each side as a quad counter-clockwise seen from outside, split along its diagonal.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.faces.push_back({q[0], q[1], q[2]});
    m.faces.push_back({q[0], q[2], q[3]});
  }
  return m;
}

IndexedMesh octahedron() {
  IndexedMesh m;
  m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

IndexedMesh icosphere(int levels) {
  IndexedMesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  m.positions = {Vec3(-1, t, 0), Vec3(1, t, 0),  Vec3(-1, -t, 0), Vec3(1, -t, 0),
                 Vec3(0, -1, t), Vec3(0, 1, t),  Vec3(0, -1, -t), Vec3(0, 1, -t),
                 Vec3(t, 0, -1), Vec3(t, 0, 1),  Vec3(-t, 0, -1), Vec3(-t, 0, 1)};
  m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : m.positions) p.normalize();
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.positions.push_back((m.positions[a] + m.positions[b]).normalized());
      const int id = static_cast<int>(m.positions.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> faces;
    for (const auto& f : m.faces) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      faces.push_back({f[0], a, c});
      faces.push_back({f[1], b, a});
      faces.push_back({f[2], c, b});
      faces.push_back({a, b, c});
    }
    m.faces = std::move(faces);
  }
  return m;
}

IndexedMesh uvSphere(int lon, int lat) {
  IndexedMesh m;
  m.positions.emplace_back(0, 0, 1);
  for (int i = 1; i < lat; ++i)
    for (int j = 0; j < lon; ++j) {
      const double th = M_PI * i / lat, ph = 2 * M_PI * j / lon;
      m.positions.emplace_back(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    }
  m.positions.emplace_back(0, 0, -1);
  const int south = static_cast<int>(m.positions.size()) - 1;
  auto id = [&](int i, int j) { return 1 + (i - 1) * lon + (j % lon); };
  for (int j = 0; j < lon; ++j) {
    m.faces.push_back({0, id(1, j), id(1, j + 1)});
    m.faces.push_back({south, id(lat - 1, j + 1), id(lat - 1, j)});
  }
  for (int i = 1; i + 1 < lat; ++i)
    for (int j = 0; j < lon; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

IndexedMesh torus(double R, double r, int nu, int nv) {
  IndexedMesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                               r * std::sin(v));
    }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

IndexedMesh holedPlate(int holes, int res, int smooth) {
  // Cells of a 3 x (2*holes+1) x 1 plate; the cells (1, 2k+1) are the tunnels.
  const int cx = 3, cy = 2 * holes + 1;
  const int nx = cx * res, ny = cy * res, nz = res;
  auto filled = [&](int x, int y, int z) {
    if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) return false;
    const int gx = x / res, gy = y / res;
    return !(gx == 1 && gy % 2 == 1);
  };
  std::map<std::tuple<int, int, int>, int> index;
  IndexedMesh m;
  auto vert = [&](int x, int y, int z) {
    auto key = std::make_tuple(x, y, z);
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const double s = 1.0 / res;
    m.positions.emplace_back(x * s, y * s, z * s);
    const int id = static_cast<int>(m.positions.size()) - 1;
    index.emplace(key, id);
    return id;
  };
  auto quad = [&](int a, int b, int c, int d) {
    m.faces.push_back({a, b, c});
    m.faces.push_back({a, c, d});
  };
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y)
      for (int z = 0; z < nz; ++z) {
        if (!filled(x, y, z)) continue;
        // One outward quad per exposed side, counter-clockwise seen from outside.
        if (!filled(x + 1, y, z)) quad(vert(x + 1, y, z), vert(x + 1, y + 1, z), vert(x + 1, y + 1, z + 1), vert(x + 1, y, z + 1));
        if (!filled(x - 1, y, z)) quad(vert(x, y, z), vert(x, y, z + 1), vert(x, y + 1, z + 1), vert(x, y + 1, z));
        if (!filled(x, y + 1, z)) quad(vert(x, y + 1, z), vert(x, y + 1, z + 1), vert(x + 1, y + 1, z + 1), vert(x + 1, y + 1, z));
        if (!filled(x, y - 1, z)) quad(vert(x, y, z), vert(x + 1, y, z), vert(x + 1, y, z + 1), vert(x, y, z + 1));
        if (!filled(x, y, z + 1)) quad(vert(x, y, z + 1), vert(x + 1, y, z + 1), vert(x + 1, y + 1, z + 1), vert(x, y + 1, z + 1));
        if (!filled(x, y, z - 1)) quad(vert(x, y, z), vert(x, y + 1, z), vert(x + 1, y + 1, z), vert(x + 1, y, z));
      }
  // Laplacian smoothing rounds the blocky surface without changing its topology.
  std::vector<std::set<int>> nbr(m.positions.size());
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) nbr[f[k]].insert(f[(k + 1) % 3]), nbr[f[k]].insert(f[(k + 2) % 3]);
  for (int it = 0; it < smooth; ++it) {
    std::vector<Vec3> next(m.positions.size());
    for (size_t v = 0; v < m.positions.size(); ++v) {
      Vec3 c = Vec3::Zero();
      for (int w : nbr[v]) c += m.positions[w];
      next[v] = 0.5 * m.positions[v] + 0.5 * c / static_cast<double>(nbr[v].size());
    }
    m.positions = std::move(next);
  }
  return m;
}

static IndexedMesh tube(double r, double h, int around, int along, bool caps) {
  IndexedMesh m;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around;
      m.positions.emplace_back(r * std::cos(a), r * std::sin(a), h * j / along);
    }
  auto id = [&](int i, int j) { return j * around + (i % around); };
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  if (caps) {
    const int bottom = static_cast<int>(m.positions.size());
    m.positions.emplace_back(0, 0, 0);
    const int top = bottom + 1;
    m.positions.emplace_back(0, 0, h);
    for (int i = 0; i < around; ++i) {
      m.faces.push_back({bottom, id(i + 1, 0), id(i, 0)});
      m.faces.push_back({top, id(i, along), id(i + 1, along)});
    }
  }
  return m;
}

IndexedMesh cappedCylinder(double r, double h, int around, int along) { return tube(r, h, around, along, true); }
IndexedMesh openCylinder(double r, double h, int around, int along) { return tube(r, h, around, along, false); }

IndexedMesh openCone(int around) {
  IndexedMesh m;
  m.positions.emplace_back(0, 0, 1);
  for (int i = 0; i < around; ++i) {
    const double a = 2 * M_PI * i / around;
    m.positions.emplace_back(std::cos(a), std::sin(a), 0);
  }
  for (int i = 0; i < around; ++i) m.faces.push_back({0, 1 + i, 1 + (i + 1) % around});
  return m;
}

IndexedMesh nonManifoldFan() {
  IndexedMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0.5), Vec3(-0.5, 0.8, 0.5), Vec3(-0.5, -0.8, 0.5)};
  m.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  return m;
}

IndexedMesh twoTetrahedraAtVertex() {
  // A tetrahedron and its point reflection through its vertex 0: they share only that vertex.
  IndexedMesh m = tetrahedron();
  const Vec3 c = m.positions[0];
  const int base = static_cast<int>(m.positions.size());
  for (int v = 1; v < 4; ++v) m.positions.push_back(2.0 * c - m.positions[v]);
  auto map = [&](int v) { return v == 0 ? 0 : base + v - 1; };
  // A point reflection reverses orientation: swap two corners to keep the faces outward.
  for (const auto& f : tetrahedron().faces) m.faces.push_back({map(f[0]), map(f[2]), map(f[1])});
  return m;
}

IndexedMesh twoComponents() {
  IndexedMesh m = tetrahedron();
  IndexedMesh b = tetrahedron(Vec3(5, 0, 0));
  const int base = static_cast<int>(m.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (auto f : b.faces) m.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  return m;
}

int nearestVertex(const IndexedMesh& m, const Vec3& p) {
  int best = 0;
  for (int v = 1; v < m.vertexCount(); ++v)
    if ((m.positions[v] - p).squaredNorm() < (m.positions[best] - p).squaredNorm()) best = v;
  return best;
}

bool writeOff(const std::string& path, const IndexedMesh& mesh) {
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << mesh.positions.size() << " " << mesh.faces.size() << " 0\n";
  for (const auto& p : mesh.positions) out << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& f : mesh.faces) out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  return out.good();
}

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

Vec3 pointOn(const IndexedMesh& m, const FacePoint& p) {
  const auto& t = m.faces[p.face];
  return p.bary[0] * m.positions[t[0]] + p.bary[1] * m.positions[t[1]] + p.bary[2] * m.positions[t[2]];
}

Vec3 warpedCopyPoint(const Vec3& x) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3::UnitZ()).toRotationMatrix();
  const double bump = 1.0 + 0.03 * std::sin(10 * x.x()) * std::cos(6.7 * x.y());
  return 1.5 * bump * (R * x);
}

IndexedMesh warpedCopy(const IndexedMesh& mesh) {
  IndexedMesh t = mesh;
  for (Vec3& x : t.positions) x = warpedCopyPoint(x);
  return t;
}

IndexedMesh readMeshOrEmpty(const std::string& path) {
  Mesh loaded;
  if (!std::ifstream(path) || !loadMesh(path, loaded).status.ok()) return {};
  return toIndexed(loaded);
}

int eulerCharacteristic(const IndexedMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  std::set<int> verts;
  for (const auto& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      verts.insert(f[k]);
      edges.insert(std::minmax(f[k], f[(k + 1) % 3]));
    }
  return static_cast<int>(verts.size()) - static_cast<int>(edges.size()) + mesh.faceCount();
}

std::vector<LayoutCase> genusZeroToTwoLayouts() {
  std::vector<LayoutCase> cases;
  cases.push_back({icosphere(3), 14});
  cases.push_back({torus(2.0, 0.7, 48, 20), 9});
  cases.push_back({holedPlate(2, 4, 20), 16});
  return cases;
}

AnchoredPair anchoredSpheres(int count, const std::function<Vec3(const Vec3&)>& deform) {
  AnchoredPair p{icosphere(3), icosphere(4), {}, {}};
  p.sourceAnchors = farthestPointSampling(p.source, count);
  for (int v : p.sourceAnchors) p.targetAnchors.push_back(nearestVertex(p.target, p.source.positions[v]));
  for (auto& x : p.target.positions) x = deform(x);
  return p;
}

}  // namespace cbd::fixtures
