#include "cbd/validate_input.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>
#include <sstream>

namespace cbd {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::string str(int v) { return std::to_string(v); }

// How messages name a mesh: "source mesh", or "mesh" when it has no name.
std::string meshLabel(const std::string& name) { return name.empty() ? "mesh" : name + " mesh"; }

Status fail(ErrorCode code, const std::string& name, const std::string& what, const std::string& fix) {
  return Status::error(code, meshLabel(name) + ": " + what + "; " + fix);
}

}  // namespace

MeshReport validateMesh(const IndexedMesh& mesh, const std::string& name, bool hadPolygons,
                        const ValidationOptions& options) {
  MeshReport r;
  r.name = name;
  const int nv = mesh.vertexCount();
  const int nf = mesh.faceCount();
  r.faces = nf;
  if (hadPolygons) {
    r.status = fail(ErrorCode::NotTriangles, name, "the file has faces with more than three vertices",
                    "triangulate it first (MeshLab: Filters > Polygonal and Quad Mesh > Turn into a Pure-Triangular mesh)");
    return r;
  }
  if (nv == 0 || nf == 0) {
    r.status = fail(ErrorCode::EmptyMesh, name, counted(nv, "vertex", "vertices") + " and " + counted(nf, "face", "faces"),
                    "a closed triangle surface is needed");
    return r;
  }
  std::vector<char> referenced(nv, 0);
  for (int f = 0; f < nf; ++f) {
    for (int v : mesh.faces[f]) {
      if (v < 0 || v >= nv) {
        r.status = Status::error(ErrorCode::MalformedMesh, meshLabel(name) + ": face " + str(f) +
                                                               " refers to vertex " + str(v) +
                                                               " which does not exist");
        return r;
      }
      referenced[v] = 1;
    }
  }
  r.vertices = static_cast<int>(std::count(referenced.begin(), referenced.end(), 1));
  r.unreferencedVertices = nv - r.vertices;
  if (r.unreferencedVertices > 0) {
    int example = static_cast<int>(std::find(referenced.begin(), referenced.end(), 0) - referenced.begin());
    r.warnings.push_back(meshLabel(name) + ": " +
                         counted(r.unreferencedVertices, "unreferenced vertex", "unreferenced vertices") +
                         " ignored (e.g. vertex " + str(example) + ")");
  }

  // Finite coordinates.
  {
    int bad = 0, example = -1;
    for (int v = 0; v < nv; ++v)
      if (referenced[v] && !mesh.positions[v].allFinite()) {
        if (example < 0) example = v;
        ++bad;
      }
    if (bad) {
      r.status = fail(ErrorCode::InvalidCoordinates, name,
                      counted(bad, "vertex", "vertices") + " with NaN or infinite coordinates (e.g. vertex " + str(example) + ")",
                      "repair or re-export the mesh");
      return r;
    }
  }
  {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int v = 0; v < nv; ++v)
      if (referenced[v]) lo = lo.cwiseMin(mesh.positions[v]), hi = hi.cwiseMax(mesh.positions[v]);
    r.bboxDiagonal = (hi - lo).norm();
  }

  // Degenerate faces: repeated vertex or (near) zero area.
  {
    const double minArea2 = std::pow(options.degenerateAreaRelative * r.bboxDiagonal * r.bboxDiagonal, 2);
    int bad = 0, example = -1;
    for (int f = 0; f < nf; ++f) {
      const auto& t = mesh.faces[f];
      bool degenerate = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
      if (!degenerate) {
        const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
        degenerate = 0.25 * n.squaredNorm() <= minArea2;
      }
      if (degenerate) {
        if (example < 0) example = f;
        ++bad;
      }
    }
    if (bad) {
      const auto& t = mesh.faces[example];
      r.status = fail(ErrorCode::DegenerateFace, name,
                      counted(bad, "degenerate (zero-area) face", "degenerate (zero-area) faces") + " (e.g. face " + str(example) + " on vertices " +
                          str(t[0]) + ", " + str(t[1]) + ", " + str(t[2]) + ")",
                      "remove them first (MeshLab: Filters > Cleaning and Repairing > Remove Zero Area Faces)");
      return r;
    }
  }

  // Duplicate faces.
  {
    std::vector<std::pair<std::array<int, 3>, int>> sorted(nf);
    for (int f = 0; f < nf; ++f) {
      auto t = mesh.faces[f];
      std::sort(t.begin(), t.end());
      sorted[f] = {t, f};
    }
    std::sort(sorted.begin(), sorted.end());
    int bad = 0, exA = -1, exB = -1;
    for (int i = 1; i < nf; ++i)
      if (sorted[i].first == sorted[i - 1].first) {
        if (exA < 0) exA = sorted[i - 1].second, exB = sorted[i].second;
        ++bad;
      }
    if (bad) {
      r.status = fail(ErrorCode::DuplicateFace, name,
                      counted(bad, "duplicate face", "duplicate faces") + " (e.g. faces " + str(exA) + " and " + str(exB) +
                          " use the same three vertices)",
                      "remove them first (MeshLab: Filters > Cleaning and Repairing > Remove Duplicate Faces)");
      return r;
    }
  }

  // Edges: every undirected edge used by exactly two faces, in opposite directions.
  struct HalfEdge {
    int lo, hi, face;
    bool forward;  // traversed lo -> hi
    bool operator<(const HalfEdge& o) const {
      return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : face < o.face;
    }
  };
  std::vector<HalfEdge> he;
  he.reserve(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      he.push_back({std::min(a, b), std::max(a, b), f, a < b});
    }
  std::sort(he.begin(), he.end());
  {
    int boundary = 0, nonManifold = 0, flipped = 0;
    const HalfEdge *exBoundary = nullptr, *exNonManifold = nullptr, *exFlipped = nullptr;
    int edges = 0;
    std::vector<char> onBoundary(nv, 0);  // for the unwelded-mesh advice below
    for (size_t i = 0; i < he.size();) {
      size_t j = i;
      while (j < he.size() && he[j].lo == he[i].lo && he[j].hi == he[i].hi) ++j;
      const size_t count = j - i;
      ++edges;
      if (count == 1) {
        ++boundary;
        if (!exBoundary) exBoundary = &he[i];
        onBoundary[he[i].lo] = onBoundary[he[i].hi] = 1;
      } else if (count > 2) {
        ++nonManifold;
        if (!exNonManifold) exNonManifold = &he[i];
      } else if (he[i].forward == he[i + 1].forward) {
        ++flipped;
        if (!exFlipped) exFlipped = &he[i];
      }
      i = j;
    }
    r.edges = edges;
    if (nonManifold) {
      r.status = fail(ErrorCode::NonManifoldEdge, name,
                      counted(nonManifold, "non-manifold edge", "non-manifold edges") + " shared by more than two faces (e.g. edge " +
                          str(exNonManifold->lo) + "-" + str(exNonManifold->hi) + ")",
                      "repair it first (MeshLab: Filters > Cleaning and Repairing > Repair non Manifold Edges)");
      return r;
    }
    if (boundary) {
      // Boundary vertices at the very position of another vertex: an unwelded mesh (a triangle
      // soup, as some OBJ and STL exporters write), whose fix is merging vertices, not closing holes.
      auto key = [&](int v) { return std::array<double, 3>{mesh.positions[v].x(), mesh.positions[v].y(), mesh.positions[v].z()}; };
      std::map<std::array<double, 3>, int> verticesAt;
      for (int v = 0; v < mesh.vertexCount(); ++v)
        if (referenced[v]) ++verticesAt[key(v)];
      int boundaryVertices = 0, unwelded = 0;
      for (int v = 0; v < mesh.vertexCount(); ++v)
        if (onBoundary[v]) ++boundaryVertices, unwelded += verticesAt[key(v)] > 1;
      const std::string what = counted(boundary, "boundary edge", "boundary edges") + ": the surface is not closed (e.g. edge " +
                               str(exBoundary->lo) + "-" + str(exBoundary->hi) + " of face " + str(exBoundary->face) + ")";
      if (2 * unwelded > boundaryVertices)
        r.status = fail(ErrorCode::OpenBoundary, name,
                        what + "; " + str(unwelded) + " of its " + str(boundaryVertices) +
                            " boundary vertices lie at the position of another vertex: the faces are not joined (an "
                            "unwelded mesh, or triangle soup)",
                        "merge the vertices first (MeshLab: Filters > Cleaning and Repairing > Merge Close Vertices)");
      else
        r.status = fail(ErrorCode::OpenBoundary, name, what,
                        "close the holes first (MeshLab: Filters > Remeshing, Simplification and Reconstruction > Close Holes)");
      return r;
    }
    if (flipped) {
      r.status = fail(ErrorCode::InconsistentOrientation, name,
                      counted(flipped, "edge", "edges") + " whose two faces are inconsistently oriented (e.g. edge " +
                          str(exFlipped->lo) + "-" + str(exFlipped->hi) + ")",
                      "re-orient the faces first (MeshLab: Filters > Normals, Curvatures and Orientation > Re-Orient all faces coherentely)");
      return r;
    }
  }

  // Vertex manifoldness: the faces around each vertex form one fan (one cycle in the link).
  {
    std::vector<int> start(nv + 1, 0);
    for (const auto& t : mesh.faces)
      for (int v : t) ++start[v + 1];
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<std::pair<int, int>> link(start[nv]);  // (next, prev) neighbour per corner
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& t : mesh.faces)
      for (int k = 0; k < 3; ++k) link[fill[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
    int bad = 0, example = -1;
    for (int v = 0; v < nv; ++v) {
      const int n = start[v + 1] - start[v];
      if (n == 0) continue;
      // Walk the link cycle from the first corner; a manifold vertex visits every corner.
      int visited = 1, cur = 0;
      std::vector<char> seen(n, 0);
      seen[0] = 1;
      for (;;) {
        const int want = link[start[v] + cur].first;  // the next corner has `want` as its prev
        int next = -1;
        for (int c = 0; c < n; ++c)
          if (link[start[v] + c].second == want) { next = c; break; }
        if (next < 0 || seen[next]) break;
        seen[next] = 1;
        ++visited;
        cur = next;
      }
      if (visited != n) {
        if (example < 0) example = v;
        ++bad;
      }
    }
    if (bad) {
      r.status = fail(ErrorCode::NonManifoldVertex, name,
                      counted(bad, "non-manifold vertex", "non-manifold vertices") + " where several fans of faces meet (e.g. vertex " +
                          str(example) + ")",
                      "split them first (MeshLab: Filters > Cleaning and Repairing > Split Vertices on Non Manifold Faces)");
      return r;
    }
  }

  // Connected components.
  {
    UnionFind uf(nv);
    for (const auto& t : mesh.faces) uf.unite(t[0], t[1]), uf.unite(t[1], t[2]);
    std::vector<int> roots;
    for (int v = 0; v < nv; ++v)
      if (referenced[v] && uf.find(v) == v) roots.push_back(v);
    r.components = static_cast<int>(roots.size());
    if (r.components > 1) {
      r.status = fail(ErrorCode::MultipleComponents, name,
                      str(r.components) + " connected components (e.g. one contains vertex " + str(roots[0]) +
                          ", another vertex " + str(roots[1]) + ")",
                      "keep one surface (MeshLab: Filters > Cleaning and Repairing > Remove Isolated pieces)");
      return r;
    }
  }

  r.eulerCharacteristic = r.vertices - r.edges + r.faces;
  r.genus = (2 - r.eulerCharacteristic) / 2;
  // Signed enclosed volume (divergence theorem), about the first vertex for less cancellation.
  {
    const Vec3 o = mesh.positions[mesh.faces[0][0]];
    double v6 = 0;
    for (const auto& f : mesh.faces)
      v6 += (mesh.positions[f[0]] - o).dot((mesh.positions[f[1]] - o).cross(mesh.positions[f[2]] - o));
    r.enclosedVolume = v6 / 6.0;
  }
  return r;
}

InputReport validateInput(const IndexedMesh& source, const IndexedMesh& target,
                          const AnchorSet& sourceAnchors, const AnchorSet& targetAnchors,
                          const ValidationOptions& options, bool sourceHadPolygons, bool targetHadPolygons) {
  InputReport r;
  if (!(options.snapTolerance >= 0) || !(options.snapTolerance <= kMaxSnapTolerance)) {
    r.status = Status::error(ErrorCode::InvalidArgument,
                             "the anchor snap tolerance must be a number in [0, 1] (a fraction of the bounding-box "
                             "diagonal), got " + std::to_string(options.snapTolerance));
    return r;
  }
  if (!(options.degenerateAreaRelative >= 0) || !std::isfinite(options.degenerateAreaRelative)) {
    r.status = Status::error(ErrorCode::InvalidArgument, "the degenerate-area threshold must be a finite number >= 0 (got " +
                                                             std::to_string(options.degenerateAreaRelative) + ")");
    return r;
  }
  r.source = validateMesh(source, "source", sourceHadPolygons, options);
  if (!r.source.status) return r.status = r.source.status, r;
  r.target = validateMesh(target, "target", targetHadPolygons, options);
  if (!r.target.status) return r.status = r.target.status, r;
  if (r.source.genus != r.target.genus) {
    r.status = Status::error(ErrorCode::GenusMismatch,
                             "the source mesh has genus " + std::to_string(r.source.genus) +
                                 " and the target mesh genus " + std::to_string(r.target.genus) +
                                 "; a cross-parameterization needs surfaces of the same topology");
    return r;
  }
  // Faces outward on one surface and inward on the other (an inside-out export): the layouts'
  // cyclic orders around the anchors disagree everywhere and the map folds over everywhere, which
  // no later stage can undo. A volume within rounding of 0 says nothing and is let through.
  {
    auto sign = [](const MeshReport& m) {
      const double scale = m.bboxDiagonal * m.bboxDiagonal * m.bboxDiagonal;
      return std::abs(m.enclosedVolume) <= 1e-9 * scale ? 0 : (m.enclosedVolume > 0 ? 1 : -1);
    };
    const int s = sign(r.source), t = sign(r.target);
    if (s * t < 0) {
      const std::string inward = s < 0 ? "source" : "target", outward = s < 0 ? "target" : "source";
      r.status = Status::error(ErrorCode::OrientationMismatch,
                               "the " + inward + " mesh's faces point inward (it encloses a negative volume) and the " +
                                   outward + " mesh's outward; invert the " + inward +
                                   "'s faces (MeshLab: Filters > Normals, Curvatures and Orientation > Invert Faces "
                                   "Orientation)");
      return r;
    }
  }
  if (!sourceAnchors.status) return r.status = sourceAnchors.status, r;
  if (!targetAnchors.status) return r.status = targetAnchors.status, r;
  std::vector<int> si, ti;
  if (Status s = matchAnchors(sourceAnchors, targetAnchors, si, ti); !s) return r.status = s, r;
  if (si.size() < 3) {
    r.status = Status::error(ErrorCode::TooFewAnchors,
                             counted(static_cast<long long>(si.size()), "corresponding anchor given",
                                     "corresponding anchors given") +
                                 "; at least 3 are needed (more for a good map)");
    return r;
  }
  // Every anchor needs a vertex of its own (a layout can use every vertex as an anchor).
  const int capacity = std::min(r.source.vertices, r.target.vertices);
  if (static_cast<int>(si.size()) > capacity) {
    r.status = Status::error(ErrorCode::TooManyAnchors,
                             std::to_string(si.size()) + " anchors on meshes of " + std::to_string(r.source.vertices) +
                                 " and " + std::to_string(r.target.vertices) +
                                 " vertices: each anchor needs a vertex of its own (at most " +
                                 std::to_string(capacity) + " here); remove anchors or refine the meshes");
    return r;
  }
  std::vector<SnappedAnchor> ss, ts;
  if (Status s = snapAnchors(source, sourceAnchors, options.snapTolerance, "source", ss); !s) return r.status = s, r;
  if (Status s = snapAnchors(target, targetAnchors, options.snapTolerance, "target", ts); !s) return r.status = s, r;
  for (size_t k = 0; k < si.size(); ++k) {
    r.anchors.names.push_back(sourceAnchors.anchors[si[k]].name);
    r.anchors.source.push_back(ss[si[k]]);
    r.anchors.target.push_back(ts[ti[k]]);
  }
  return r;
}

void nameMeshFile(MeshReport& report, const std::string& path) {
  const std::string label = meshLabel(report.name);
  auto rename = [&](std::string& message) {
    if (message.compare(0, label.size() + 1, label + ":") == 0) message.insert(label.size(), " '" + path + "'");
  };
  rename(report.status.message);
  for (std::string& w : report.warnings) rename(w);
}

void loadSurface(const std::string& meshPath, const std::string& anchorsPath, const std::string& role,
                 const ValidationOptions& options, LoadedSurface& out, int minAnchors) {
  out.status = Status::success();
  out.report = MeshReport{};
  out.indexed = IndexedMesh{};
  out.anchors.clear();
  out.load = loadMesh(meshPath, out.mesh);  // clears the mesh first
  if (!out.load.status) return void(out.status = out.load.status);
  out.indexed = toIndexed(out.mesh);
  out.report = validateMesh(out.indexed, role, out.load.hadPolygons, options);
  nameMeshFile(out.report, meshPath);
  out.report.warnings.insert(out.report.warnings.end(), out.load.warnings.begin(), out.load.warnings.end());
  if (!out.report.status) return void(out.status = out.report.status);
  if (anchorsPath.empty()) return;
  if (!(options.snapTolerance >= 0) || !(options.snapTolerance <= kMaxSnapTolerance))
    return void(out.status = Status::error(ErrorCode::InvalidArgument,
                                           "the anchor snap tolerance must be a number in [0, 1] (a fraction of the "
                                           "bounding-box diagonal), got " + std::to_string(options.snapTolerance)));
  const AnchorSet set = readAnchors(anchorsPath);
  if (!set.status) return void(out.status = set.status);
  if (Status s = snapAnchors(out.indexed, set, options.snapTolerance, role, out.anchors); !s)
    return void(out.status = s);
  if (static_cast<int>(out.anchors.size()) < minAnchors)
    out.status = Status::error(
        ErrorCode::TooFewAnchors,
        anchorsPath + ": " + std::to_string(out.anchors.size()) + " anchors" +
            (set.skippedInactive > 0
                 ? " (and " + std::to_string(set.skippedInactive) + " inactive points, active=\"0\", left out)"
                 : std::string()) +
            "; a layout needs at least " + std::to_string(minAnchors));
}

void loadAndValidate(const InputFiles& files, const ValidationOptions& options, LoadedInput& out) {
  out.report = InputReport{};
  out.source = IndexedMesh{};
  out.target = IndexedMesh{};
  out.sourceLoad = loadMesh(files.sourceMesh, out.sourceMesh);
  if (!out.sourceLoad.status) return void(out.report.status = out.sourceLoad.status);
  out.targetLoad = loadMesh(files.targetMesh, out.targetMesh);
  if (!out.targetLoad.status) return void(out.report.status = out.targetLoad.status);
  out.source = toIndexed(out.sourceMesh);
  out.target = toIndexed(out.targetMesh);
  const AnchorSet sa = readAnchors(files.sourceAnchors);
  const AnchorSet ta = readAnchors(files.targetAnchors);
  out.report = validateInput(out.source, out.target, sa, ta, options, out.sourceLoad.hadPolygons,
                             out.targetLoad.hadPolygons);
  // Name the files, not only the roles.
  nameMeshFile(out.report.source, files.sourceMesh);
  nameMeshFile(out.report.target, files.targetMesh);
  // The loaders' warnings (they name the file).
  for (const auto& [load, m] : {std::pair{&out.sourceLoad, &out.report.source},
                                std::pair{&out.targetLoad, &out.report.target}})
    m->warnings.insert(m->warnings.end(), load->warnings.begin(), load->warnings.end());
  if (!out.report.source.status) out.report.status = out.report.source.status;
  else if (!out.report.target.status) out.report.status = out.report.target.status;
}

}  // namespace cbd
