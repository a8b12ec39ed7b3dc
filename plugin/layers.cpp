#include "layers.h"

#include <algorithm>
#include <stdexcept>

#include <QFile>
#include <QFileInfo>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include "cbd/layout_io.h"
#include "cbd/map_io.h"
#include "pickedPoints.h"

namespace cbdplugin {
namespace {

std::string str(const QString& s) { return s.toStdString(); }
std::string quoted(const QString& s) { return "'" + str(s) + "'"; }
std::string layerName(const MeshModel& m) { return "layer " + quoted(panelName(m)); }

std::array<unsigned char, 3> labelColour(int label) {
  return label < 0 ? std::array<unsigned char, 3>{128, 128, 128} : cbd::paletteColor(label);
}

/// The layer's PickPoints attribute, or null. Never creates it.
PickedPoints* pickedPointsOf(MeshModel& layer) {
  auto h = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<PickedPoints*>(layer.cm, PickedPoints::Key);
  if (!vcg::tri::Allocator<CMeshO>::IsValidHandle<PickedPoints*>(layer.cm, h)) return nullptr;
  return h();
}

Point3m point(const cbd::Vec3& p) { return Point3m(Scalarm(p.x()), Scalarm(p.y()), Scalarm(p.z())); }

MeshModel* newLayer(MeshDocument& md, const QString& label, bool current) {
  MeshModel* m = md.addNewMesh("", label, current);
  if (m == nullptr) throw std::runtime_error("MeshLab could not add the layer '" + str(label) + "'");
  return m;
}

}  // namespace

QString panelName(const MeshModel& layer) {
  const QString name = QFileInfo(layer.label()).completeBaseName();
  return name.isEmpty() ? layer.label() : name;
}

QString stem(const MeshModel& layer) { return panelName(layer).replace('.', '_'); }

cbd::Status toIndexed(const MeshModel& layer, cbd::IndexedMesh& out, LayerIndex& where, int& deletedVertices) {
  const CMeshO& cm = layer.cm;
  out = cbd::IndexedMesh{};
  where = LayerIndex{};
  std::vector<int> index(cm.vert.size(), -1);
  deletedVertices = 0;
  for (size_t i = 0; i < cm.vert.size(); ++i) {
    const CVertexO& v = cm.vert[i];
    if (v.IsD()) {
      ++deletedVertices;
      continue;
    }
    index[i] = static_cast<int>(out.positions.size());
    where.vertex.push_back(static_cast<int>(i));
    out.positions.emplace_back(double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2]));
  }
  const CVertexO* base = cm.vert.empty() ? nullptr : &cm.vert[0];
  for (size_t f = 0; f < cm.face.size(); ++f) {
    const CFaceO& face = cm.face[f];
    if (face.IsD()) continue;
    std::array<int, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const CVertexO* vp = face.cV(k);
      const std::ptrdiff_t i = (vp && base) ? vp - base : -1;
      if (i < 0 || i >= static_cast<std::ptrdiff_t>(index.size()) || index[static_cast<size_t>(i)] < 0)
        return cbd::Status::error(cbd::ErrorCode::MalformedMesh,
                                  layerName(layer) + ": face " + std::to_string(f) +
                                      " refers to a deleted or foreign vertex (save and reload the layer, or run "
                                      "Filters > Cleaning and Repairing > Remove Unreferenced Vertices)");
      t[static_cast<size_t>(k)] = index[static_cast<size_t>(i)];
    }
    out.faces.push_back(t);
    where.face.push_back(static_cast<int>(f));
  }
  return cbd::Status::success();
}

GatheredAnchors gatherAnchors(MeshModel& layer, const QString& explicitPath, const std::string& role) {
  GatheredAnchors g;
  if (!explicitPath.isEmpty()) {
    g.set = cbd::readAnchors(QFile::encodeName(explicitPath).toStdString());
    g.origin = "file " + quoted(explicitPath);
    return g;
  }
  if (PickedPoints* pp = pickedPointsOf(layer)) {
    g.set.source = "PickPoints of " + layerName(layer);
    g.set.format = cbd::AnchorFormat::PickedPoints;
    int line = 0;
    for (const PickedPoint* p : pp->getPickedPointVector()) {
      ++line;
      if (p == nullptr) continue;
      if (!p->present) {
        ++g.set.skippedInactive;
        continue;
      }
      cbd::Anchor a;
      a.name = str(p->name);
      if (a.name.empty()) a.name = std::to_string(line);  // as cbd::parseAnchors names unnamed points
      a.position = cbd::Vec3(double(p->point[0]), double(p->point[1]), double(p->point[2]));
      a.hasPosition = true;
      a.line = line;
      g.set.anchors.push_back(a);
    }
    g.origin = "PickPoints of " + layerName(layer);
    return g;
  }
  const std::string fix = "pick points (Edit > PickPoints) or set the '" + role + " anchors file' parameter";
  if (layer.fullName().isEmpty()) {
    g.set.source = layerName(layer);
    g.set.status = cbd::Status::error(cbd::ErrorCode::FileNotFound, "no " + role + " anchors: " + layerName(layer) +
                                                                        " has no picked points and no file name; " + fix);
    return g;
  }
  const QString suggested =
      QFileInfo(layer.fullName()).absolutePath() + "/" + PickedPoints::getSuggestedPickedPointsFileName(layer);
  if (!QFileInfo(suggested).isFile()) {
    g.set.source = QFile::encodeName(suggested).toStdString();
    g.set.status = cbd::Status::error(cbd::ErrorCode::FileNotFound,
                                      "no " + role + " anchors: " + layerName(layer) + " has no picked points and " +
                                          quoted(suggested) + " does not exist; " + fix);
    return g;
  }
  g.set = cbd::readAnchors(QFile::encodeName(suggested).toStdString());
  g.origin = "file " + quoted(suggested);
  return g;
}

PathLayer pathLayer(const cbd::Layout& layout) {
  PathLayer p;
  for (size_t e = 0; e < layout.edges.size(); ++e) {
    const std::vector<int>& chain = layout.edges[e].vertices;
    const int first = static_cast<int>(p.positions.size());
    for (size_t k = 0; k < chain.size(); ++k) {
      p.positions.push_back(layout.mesh.position(chain[k]));
      p.colours.push_back(labelColour(static_cast<int>(e)));
      p.edgeOfVertex.push_back(static_cast<int>(e));
      if (k > 0) p.segments.push_back({first + static_cast<int>(k) - 1, first + static_cast<int>(k)});
    }
  }
  return p;
}

MstLayer mstLayer(const cbd::IndexedMesh& source, const cbd::CrossParameterizationResult& r,
                  const MeshModel& targetLayer, const cbd::IndexedMesh& target, const LayerIndex& targetIndex) {
  MstLayer m;
  m.positions = r.map.sourceImage;
  m.faces = source.faces;
  m.faceQuality = r.metrics.faceStretch;
  m.faceQuality.resize(source.faces.size(), 0.0);
  for (double q : m.faceQuality) m.faceColours.push_back(cbd::stretchColor(q));
  m.hasVertexColour = targetLayer.hasDataMask(MeshModel::MM_VERTCOLOR);
  m.hasVertexQuality = targetLayer.hasDataMask(MeshModel::MM_VERTQUALITY);
  if (!m.hasVertexColour && !m.hasVertexQuality) return m;
  // The target's values per compact vertex, blended at the images as cbd's mst.ply does.
  cbd::VertexValues colour(target.positions.size()), quality(target.positions.size());
  for (size_t v = 0; v < target.positions.size(); ++v) {
    const CVertexO& tv = targetLayer.cm.vert[static_cast<size_t>(targetIndex.vertex[v])];
    colour[v] = Eigen::Vector4d(tv.cC()[0], tv.cC()[1], tv.cC()[2], tv.cC()[3]);
    quality[v] = Eigen::Vector4d(double(tv.cQ()), 0, 0, 0);
  }
  if (m.hasVertexColour)
    for (const Eigen::Vector4d& c : cbd::interpolateAtPoints(target.faces, r.map.sourceToTarget, colour,
                                                             Eigen::Vector4d::Constant(255)))
      m.vertexColours.push_back({cbd::colorByte(c[0]), cbd::colorByte(c[1]), cbd::colorByte(c[2]), cbd::colorByte(c[3])});
  if (m.hasVertexQuality)
    for (const Eigen::Vector4d& q : cbd::interpolateAtPoints(target.faces, r.map.sourceToTarget, quality))
      m.vertexQuality.push_back(static_cast<float>(q[0]));
  return m;
}

void colourFaces(MeshModel& layer, const LayerIndex& index, const std::vector<int>& labels) {
  layer.updateDataMask(MeshModel::MM_FACECOLOR);
  for (size_t f = 0; f < labels.size() && f < index.face.size(); ++f) {
    const auto c = labelColour(labels[f]);
    layer.cm.face[static_cast<size_t>(index.face[f])].C() = vcg::Color4b(c[0], c[1], c[2], 255);
  }
}

MeshModel* addPathLayer(MeshDocument& md, const QString& label, const PathLayer& p) {
  MeshModel* m = newLayer(md, label, false);
  m->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY);
  CMeshO& cm = m->cm;
  if (!p.positions.empty()) vcg::tri::Allocator<CMeshO>::AddVertices(cm, p.positions.size());
  for (size_t v = 0; v < p.positions.size(); ++v) {
    cm.vert[v].P() = point(p.positions[v]);
    cm.vert[v].C() = vcg::Color4b(p.colours[v][0], p.colours[v][1], p.colours[v][2], 255);
    cm.vert[v].Q() = Scalarm(p.edgeOfVertex[v]);
    cm.vert[v].N() = Point3m(0, 0, 1);
  }
  if (!p.segments.empty()) vcg::tri::Allocator<CMeshO>::AddEdges(cm, p.segments.size());
  for (size_t e = 0; e < p.segments.size(); ++e) {
    cm.edge[e].V(0) = &cm.vert[static_cast<size_t>(p.segments[e][0])];
    cm.edge[e].V(1) = &cm.vert[static_cast<size_t>(p.segments[e][1])];
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(cm);
  return m;
}

MeshModel* addMstLayer(MeshDocument& md, const QString& label, const MstLayer& s) {
  MeshModel* m = newLayer(md, label, true);  // the result the user asked for: the current layer
  int mask = MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
  if (s.hasVertexColour) mask |= MeshModel::MM_VERTCOLOR;
  if (s.hasVertexQuality) mask |= MeshModel::MM_VERTQUALITY;
  m->updateDataMask(mask);
  CMeshO& cm = m->cm;
  if (!s.positions.empty()) vcg::tri::Allocator<CMeshO>::AddVertices(cm, s.positions.size());
  for (size_t v = 0; v < s.positions.size(); ++v) {
    cm.vert[v].P() = point(s.positions[v]);
    if (s.hasVertexColour)
      cm.vert[v].C() = vcg::Color4b(s.vertexColours[v][0], s.vertexColours[v][1], s.vertexColours[v][2], s.vertexColours[v][3]);
    if (s.hasVertexQuality) cm.vert[v].Q() = s.vertexQuality[v];
  }
  if (!s.faces.empty()) vcg::tri::Allocator<CMeshO>::AddFaces(cm, s.faces.size());
  for (size_t f = 0; f < s.faces.size(); ++f) {
    CFaceO& face = cm.face[f];
    for (int k = 0; k < 3; ++k) face.V(k) = &cm.vert[static_cast<size_t>(s.faces[f][static_cast<size_t>(k)])];
    face.Q() = Scalarm(s.faceQuality[f]);
    face.C() = vcg::Color4b(s.faceColours[f][0], s.faceColours[f][1], s.faceColours[f][2], 255);
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(cm);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(cm);
  return m;
}

}  // namespace cbdplugin
