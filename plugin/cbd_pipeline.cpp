/// @file cbd_pipeline.cpp
/// The algorithm stages (cbd_core) and their results as MeshLab layers:
///   * "Voronoi common base domain": cbd::buildLayouts; both input layers coloured per face by
///     patch (patch k -> cbd::paletteColor(k) on both, so corresponding patches match) or by
///     Voronoi cluster; one new edge-mesh layer per surface with the layout paths.
///   * "Cross-parameterize": cbd::crossParameterize; optionally the layers coloured by patch,
///     the new layer M_st ("<source> onto <target>": the source's connectivity at the images of
///     its vertices on the target; face quality = L2 stretch, a stretch colour ramp, vertex
///     colour transferred from the target) and the path layers.
/// Everything is computed first; the document is modified only after every stage succeeded.

#include "cbd_pipeline.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <QFileInfo>
#include <QString>

#include <common/meshmodel.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include "cbd/layout.h"
#include "cbd/layout_io.h"
#include "cbd/map_io.h"
#include "cbd/pipeline.h"

namespace cbdplugin {
namespace {

using Rgb = std::array<unsigned char, 3>;

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string seconds(double s) { return fixed(s, 3) + " s"; }

std::string layerName(const MeshModel& m) { return "'" + m.label().toStdString() + "'"; }

/// A layer's name for the labels of derived layers: without the file extension and without dots
/// (MeshLab's layer dialog shows a label up to its last dot: "cow.off onto bull.off" would read
/// "cow.off onto bull", "bull.off base domain" just "bull").
QString stem(const MeshModel& m) {
  QString s = QFileInfo(m.label()).completeBaseName();
  if (s.isEmpty()) s = m.label();
  return s.replace('.', '_');
}

/// `forMap`: the Cross-parameterize filter (smoothing and straightening apply); else the layout filter.
cbd::CrossParameterizationOptions coreOptions(const PipelineOptions& o, bool forMap,
                                              const std::vector<std::string>& anchorNames) {
  cbd::CrossParameterizationOptions c;
  c.anchorNames = anchorNames;
  c.method = o.method == LayoutMethod::GreedyShortestPaths ? cbd::LayoutMethod::Greedy : cbd::LayoutMethod::Voronoi;
  c.edgeNodes.minEdgeNodes = o.minEdgeNodes;
  c.edgeNodes.adaptive = o.adaptiveEdgeNodes;
  if (forMap) c.smoothing.iterations = o.smoothingIterations;
  c.straightening.rounds = forMap ? o.straightenRounds : 0;
  return c;
}

/// Colour of a label (patch, cluster, layout edge); grey for -1.
Rgb labelColour(int label) { return label < 0 ? Rgb{128, 128, 128} : cbd::paletteColor(label); }

Rgb stretchColour(double s) { return cbd::stretchColor(s); }

/// The layout paths as an edge mesh: every layout edge a polyline of its own (its end anchors
/// duplicated), vertex colour = paletteColor(edge index), vertex quality = edge index.
struct PathMesh {
  std::vector<cbd::Vec3> positions;
  std::vector<Rgb> colours;
  std::vector<int> edgeOfVertex;
  std::vector<std::array<int, 2>> segments;
};

PathMesh pathMesh(const cbd::Layout& layout) {
  PathMesh p;
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

/// Everything M_st needs, computed before the document is touched.
struct MstMesh {
  std::vector<cbd::Vec3> positions;
  std::vector<double> faceQuality;
  std::vector<Rgb> faceColours;
  bool hasVertexColour = false, hasVertexQuality = false;
  std::vector<vcg::Color4b> vertexColours;
  std::vector<float> vertexQuality;
};

/// Per-face colours of one input layer (compact face order).
std::vector<Rgb> faceColours(const std::vector<int>& labels) {
  std::vector<Rgb> c(labels.size());
  for (size_t f = 0; f < labels.size(); ++f) c[f] = labelColour(labels[f]);
  return c;
}

int distinctLabels(const std::vector<int>& labels) {
  std::vector<int> l(labels);
  std::sort(l.begin(), l.end());
  return static_cast<int>(std::unique(l.begin(), l.end()) - l.begin());
}

// --- writing into the document (no failure past this point except out of memory)

void colourLayer(MeshModel& layer, const LayerIndex& index, const std::vector<Rgb>& colours) {
  layer.updateDataMask(MeshModel::MM_FACECOLOR);
  for (size_t f = 0; f < colours.size() && f < index.face.size(); ++f)
    layer.cm.face[static_cast<size_t>(index.face[f])].C() =
        vcg::Color4b(colours[f][0], colours[f][1], colours[f][2], 255);
}

MeshModel* addPathLayer(MeshDocument& doc, const QString& label, const PathMesh& p) {
  MeshModel* m = doc.addNewMesh("", label, false);
  if (m == nullptr) throw std::runtime_error("MeshLab could not add the layer '" + label.toStdString() + "'");
  m->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY);
  CMeshO& cm = m->cm;
  if (!p.positions.empty()) vcg::tri::Allocator<CMeshO>::AddVertices(cm, p.positions.size());
  for (size_t v = 0; v < p.positions.size(); ++v) {
    cm.vert[v].P() = Point3m(Scalarm(p.positions[v].x()), Scalarm(p.positions[v].y()), Scalarm(p.positions[v].z()));
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

MeshModel* addMstLayer(MeshDocument& doc, const QString& label, const cbd::IndexedMesh& source, const MstMesh& s) {
  MeshModel* m = doc.addNewMesh("", label, false);
  if (m == nullptr) throw std::runtime_error("MeshLab could not add the layer '" + label.toStdString() + "'");
  int mask = MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
  if (s.hasVertexColour) mask |= MeshModel::MM_VERTCOLOR;
  if (s.hasVertexQuality) mask |= MeshModel::MM_VERTQUALITY;
  m->updateDataMask(mask);
  CMeshO& cm = m->cm;
  if (!s.positions.empty()) vcg::tri::Allocator<CMeshO>::AddVertices(cm, s.positions.size());
  for (size_t v = 0; v < s.positions.size(); ++v) {
    cm.vert[v].P() = Point3m(Scalarm(s.positions[v].x()), Scalarm(s.positions[v].y()), Scalarm(s.positions[v].z()));
    if (s.hasVertexColour) cm.vert[v].C() = s.vertexColours[v];
    if (s.hasVertexQuality) cm.vert[v].Q() = s.vertexQuality[v];
  }
  if (!source.faces.empty()) vcg::tri::Allocator<CMeshO>::AddFaces(cm, source.faces.size());
  for (size_t f = 0; f < source.faces.size(); ++f) {
    CFaceO& face = cm.face[f];
    for (int k = 0; k < 3; ++k) face.V(k) = &cm.vert[static_cast<size_t>(source.faces[f][static_cast<size_t>(k)])];
    face.Q() = Scalarm(s.faceQuality[f]);
    face.C() = vcg::Color4b(s.faceColours[f][0], s.faceColours[f][1], s.faceColours[f][2], 255);
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(cm);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(cm);
  return m;
}

// --- log lines

std::string anchorList(const cbd::InputReport& report) {
  std::string s = std::to_string(report.anchors.size()) + " anchors:";
  for (size_t k = 0; k < report.anchors.source.size(); ++k) s += (k ? ", " : " ") + report.anchors.source[k].name;
  return s;
}

std::string layoutLine(const cbd::LayoutPair& p) {
  std::ostringstream s;
  s << "layout (" << cbd::layoutMethodName(p.method) << "): " << p.source.edges.size() << " edges, "
    << p.source.patches.size() << " patches, " << p.source.multipleLinkages() << " multiple linkages";
  if (p.method == cbd::LayoutMethod::Voronoi) {
    s << "; source: " << p.sourceStats.cutPaths - p.sourceStats.removedPaths << " paths across Voronoi cuts, "
      << p.sourceStats.triangulationPaths << " triangulating, " << p.sourceStats.removedPaths << " removed"
      << "; target: " << p.targetStats.embeddedInClusters << " paths inside the two clusters, "
      << p.targetStats.embeddedInRegion << " in the whole region, " << p.targetStats.postponements << " postponements";
    if (p.sameSurface) s << " (the target is the source itself: the same layout)";
    if (p.reversed)
      s << " (the source's layout detoured, detour " << p.reverseDetour << ": this one comes from the target's Voronoi "
        << "diagram, traced on the source; 'source' and 'target' above are swapped)";
  } else {
    const auto& g = p.greedyStats;
    s << "; " << g.candidates << " candidate pairs, " << g.tried << " traced, " << g.accepted << " accepted, "
      << g.rejected << " rejected, " << g.completionPaths << " completion paths (" << g.completionRejected
      << " undone), " << g.flips << " flips";
  }
  return s.str();
}

std::string timesLine(const cbd::StageTimes& t, bool withMap) {
  std::string s = "timings: voronoi " + seconds(t.voronoi) + ", source layout " + seconds(t.sourceLayout) +
                  ", target layout " + seconds(t.targetLayout);
  if (withMap)
    s += ", straighten " + seconds(t.straighten) + ", parameterization " + seconds(t.parameterization) + ", untangle " + seconds(t.untangle) + ", distortion " +
         seconds(t.distortion);
  return s + ", total " + seconds(t.total);
}

std::string failure(const std::string& tag, const cbd::Status& s) {
  return tag + s.message + " [" + cbd::errorCodeName(s.code) + "]";
}

}  // namespace

cbd::Status runPipeline(const PipelineRequest& rq, vcg::CallBackPos* cb) {
  auto progress = [cb](int percent, const char* text) {
    if (cb) (*cb)(percent, text);
  };
  const std::string tag = "cbd: " + rq.filterName + ": ";
  auto log = [&](const std::string& line) { rq.log(tag + line); };
  const PipelineOptions& o = rq.options;
  std::vector<int> sa, ta;
  for (const auto& a : rq.report.anchors.source) sa.push_back(a.vertex);
  for (const auto& a : rq.report.anchors.target) ta.push_back(a.vertex);
  const int euler = rq.report.source.eulerCharacteristic;
  const QString sourceLabel = stem(rq.sourceLayer), targetLabel = stem(rq.targetLayer);

  if (rq.filter == FilterKind::VoronoiBaseDomain) {
    progress(25, "cbd: building the common base domain");
    const auto t0 = std::chrono::steady_clock::now();
    cbd::LayoutPair p =
        cbd::buildLayouts(rq.source, sa, rq.target, ta, euler, coreOptions(o, false, rq.report.anchors.names));
    p.times.total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!p.status.ok()) return cbd::Status::error(p.status.code, failure(tag, p.status));
    progress(80, "cbd: layouts built");

    bool byCluster = o.colourByCluster;
    if (byCluster && (p.source.faceCluster.empty() || p.target.faceCluster.empty())) {
      log("warning: 'Colour by Voronoi cluster' needs the Voronoi method; colouring by patch");
      byCluster = false;
    }
    const std::vector<int> sourceLabels = byCluster ? cbd::inputFaceCluster(p.source) : cbd::inputFacePatch(p.source);
    const std::vector<int> targetLabels = byCluster ? cbd::inputFaceCluster(p.target) : cbd::inputFacePatch(p.target);
    const std::vector<Rgb> sourceColours = faceColours(sourceLabels), targetColours = faceColours(targetLabels);
    const PathMesh sourcePaths = pathMesh(p.source), targetPaths = pathMesh(p.target);

    // Success: write the results.
    colourLayer(rq.sourceLayer, rq.sourceIndex, sourceColours);
    colourLayer(rq.targetLayer, rq.targetIndex, targetColours);
    const QString sp = sourceLabel + " base domain", tp = targetLabel + " base domain";
    addPathLayer(rq.document, sp, sourcePaths);
    addPathLayer(rq.document, tp, targetPaths);
    progress(95, "cbd: layers written");

    log(anchorList(rq.report));
    log(layoutLine(p));
    for (const auto& w : p.warnings) log("warning: " + w);
    log(timesLine(p.times, false));
    log(std::string("layers ") + layerName(rq.sourceLayer) + " and " + layerName(rq.targetLayer) +
        " coloured per face by " + (byCluster ? "Voronoi cluster (" : "patch (") +
        std::to_string(distinctLabels(sourceLabels)) + " / " + std::to_string(distinctLabels(targetLabels)) +
        " colours; corresponding " + (byCluster ? "clusters" : "patches") + " share a colour)");
    log("new layers '" + sp.toStdString() + "' and '" + tp.toStdString() + "': the " +
        std::to_string(p.source.edges.size()) + " layout paths as edge meshes (" +
        std::to_string(sourcePaths.segments.size()) + " / " + std::to_string(targetPaths.segments.size()) +
        " segments; vertex colour per layout edge, vertex quality = edge index)");
    return cbd::Status::success();
  }

  // Cross-parameterize.
  progress(25, "cbd: building the common base domain and the cross-parameterization");
  cbd::CrossParameterizationResult r =
      cbd::crossParameterize(rq.source, sa, rq.target, ta, euler, coreOptions(o, true, rq.report.anchors.names));
  if (!r.status.ok()) return cbd::Status::error(r.status.code, failure(tag, r.status));
  progress(80, "cbd: cross-parameterization done");

  std::vector<Rgb> sourceColours, targetColours;
  if (o.colourByPatch) {
    sourceColours = faceColours(cbd::inputFacePatch(r.layouts.source));
    targetColours = faceColours(cbd::inputFacePatch(r.layouts.target));
  }
  PathMesh sourcePaths, targetPaths;
  if (o.addPathLayers) sourcePaths = pathMesh(r.layouts.source), targetPaths = pathMesh(r.layouts.target);

  MstMesh mst;
  const cbd::DistortionMetrics& m = r.metrics;
  if (o.addMstLayer) {
    mst.positions = r.map.sourceImage;
    mst.faceQuality = m.faceStretch;
    mst.faceQuality.resize(rq.source.faces.size(), 0.0);
    mst.faceColours.resize(mst.faceQuality.size());
    for (size_t f = 0; f < mst.faceQuality.size(); ++f) mst.faceColours[f] = stretchColour(mst.faceQuality[f]);
    const CMeshO& tm = rq.targetLayer.cm;
    mst.hasVertexColour = rq.targetLayer.hasDataMask(MeshModel::MM_VERTCOLOR);
    mst.hasVertexQuality = rq.targetLayer.hasDataMask(MeshModel::MM_VERTQUALITY);
    if (mst.hasVertexColour) mst.vertexColours.assign(mst.positions.size(), vcg::Color4b(255, 255, 255, 255));
    if (mst.hasVertexQuality) mst.vertexQuality.assign(mst.positions.size(), 0.0f);
    for (size_t v = 0; v < mst.positions.size() && v < r.map.sourceToTarget.size(); ++v) {
      const cbd::FacePoint& fp = r.map.sourceToTarget[v];
      if (fp.face < 0 || fp.face >= static_cast<int>(rq.target.faces.size())) continue;
      const auto& face = rq.target.faces[static_cast<size_t>(fp.face)];
      double c[4] = {0, 0, 0, 0}, q = 0;
      for (int k = 0; k < 3; ++k) {
        const CVertexO& tv = tm.vert[static_cast<size_t>(rq.targetIndex.vertex[static_cast<size_t>(face[static_cast<size_t>(k)])])];
        for (int i = 0; i < 4; ++i) c[i] += fp.bary[k] * tv.cC()[i];
        q += fp.bary[k] * double(tv.cQ());
      }
      auto byte = [](double x) { return static_cast<unsigned char>(std::clamp(std::lround(x), 0L, 255L)); };
      if (mst.hasVertexColour) mst.vertexColours[v] = vcg::Color4b(byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3]));
      if (mst.hasVertexQuality) mst.vertexQuality[v] = static_cast<float>(q);
    }
  }

  // Success: write the results.
  if (o.colourByPatch) {
    colourLayer(rq.sourceLayer, rq.sourceIndex, sourceColours);
    colourLayer(rq.targetLayer, rq.targetIndex, targetColours);
  }
  const QString mstLabel = sourceLabel + " onto " + targetLabel;
  if (o.addMstLayer) addMstLayer(rq.document, mstLabel, rq.source, mst);
  const QString sp = sourceLabel + " base domain", tp = targetLabel + " base domain";
  if (o.addPathLayers) {
    addPathLayer(rq.document, sp, sourcePaths);
    addPathLayer(rq.document, tp, targetPaths);
  }
  progress(95, "cbd: layers written");

  log(anchorList(rq.report));
  log(layoutLine(r.layouts));
  for (const auto& w : r.layouts.warnings) log("warning: " + w);
  if (o.straightenRounds > 0 && r.straightenFailed)
    log("straighten: failed (" +
        (!r.straightenSource.status ? r.straightenSource.status : r.straightenTarget.status).message +
        "); both base domains kept as traced");
  else if (o.straightenRounds > 0)
    log("straighten: " + std::to_string(o.straightenRounds) + " round(s), " +
        std::to_string(r.straightenSource.straightened) + " / " + std::to_string(r.straightenTarget.straightened) +
        " paths straightened (source / target), total length " + fixed(r.straightenSource.lengthBefore, 4) + " -> " +
        fixed(r.straightenSource.lengthAfter, 4) + " / " + fixed(r.straightenTarget.lengthBefore, 4) + " -> " +
        fixed(r.straightenTarget.lengthAfter, 4));
  if (o.smoothingIterations > 0)
    log("smoothing: " + std::to_string(o.smoothingIterations) + " iterations, " + std::to_string(r.smoothing.moves) +
        " moves, " + std::to_string(r.smoothing.rejected) + " rejected, flipped " +
        std::to_string(r.smoothing.flippedBefore) + " -> " + std::to_string(r.smoothing.flippedAfter));
  log("untangle: flipped triangles of M_st " + std::to_string(r.untangleSource.flippedBefore) + " -> " +
      std::to_string(r.untangleSource.flippedAfter) + " (" + std::to_string(r.untangleSource.movedVertices) +
      " vertices moved over the target, " + std::to_string(r.untangleSource.attempts) + " runs)");
  log("map: E_ang " + fixed(m.eAng, 4) + " (" + fixed(m.eAngDegrees, 2) + " deg), E_L2 " + fixed(m.eL2, 4) +
      " (inverse " + fixed(m.eL2Inverse, 4) + "), " + std::to_string(m.flipped) + " flipped, " +
      std::to_string(m.degenerate) + " degenerate triangles");
  log(timesLine(r.times, true));
  if (o.colourByPatch)
    log("layers " + layerName(rq.sourceLayer) + " and " + layerName(rq.targetLayer) + " coloured per face by patch (" +
        std::to_string(r.layouts.source.patches.size()) + " patches; corresponding patches share a colour)");
  if (o.addMstLayer) {
    std::vector<double> s;
    for (double q : mst.faceQuality)
      if (!std::isnan(q)) s.push_back(q);
    std::sort(s.begin(), s.end());
    const double median = s.empty() ? 0.0 : s[s.size() / 2], worst = s.empty() ? 0.0 : s.back();
    log("new layer '" + mstLabel.toStdString() + "' (M_st): " + std::to_string(mst.positions.size()) + " vertices, " +
        std::to_string(rq.source.faces.size()) + " faces on the target; face quality = L2 stretch (median " +
        fixed(median, 3) + ", max " + fixed(worst, 3) + "), face colour blue (compressed) - white - red (stretched x2)" +
        (mst.hasVertexColour ? "; vertex colour transferred from the target" : "") +
        (mst.hasVertexQuality ? "; vertex quality transferred from the target" : ""));
  }
  if (o.addPathLayers)
    log("new layers '" + sp.toStdString() + "' and '" + tp.toStdString() + "': the " +
        std::to_string(r.layouts.source.edges.size()) + " layout paths as edge meshes");
  return cbd::Status::success();
}

}  // namespace cbdplugin
