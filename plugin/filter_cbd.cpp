/// @file filter_cbd.cpp
/// Parameters in, one core call, layers out. No geometry here (layers.h converts, cbd's core
/// computes and reports).

#include "filter_cbd.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <tuple>
#include <utility>
#include <vector>

#include "cbd/pipeline.h"
#include "cbd/progress.h"
#include "cbd/report.h"
#include "cbd/validate_input.h"
#include "layers.h"

namespace {

// Parameter names: what .mlx scripts use (<Param name="..."/>). Keep them stable.
const char* const kSourceMesh = "SourceMesh";
const char* const kTargetMesh = "TargetMesh";
const char* const kSourceAnchors = "SourceAnchors";
const char* const kTargetAnchors = "TargetAnchors";
const char* const kMethod = "Method";
const char* const kMinEdgeNodes = "MinEdgeNodes";
const char* const kAdaptiveEdgeNodes = "AdaptiveEdgeNodes";
const char* const kSmoothingIterations = "SmoothingIterations";
const char* const kStraightenRounds = "StraightenRounds";
const char* const kColourByCluster = "ColourByCluster";
const char* const kAddMstLayer = "AddMstLayer";
const char* const kColourByPatch = "ColourByPatch";
const char* const kAddPathLayers = "AddPathLayers";

/// A problem found before the core runs; `run` turns it into the error text.
struct InputError {
  cbd::Status status;
};

[[noreturn]] void refuse(cbd::ErrorCode code, const std::string& message) {
  throw InputError{cbd::Status::error(code, message)};
}

std::string str(const QString& s) { return s.toStdString(); }
std::string quoted(const QString& s) { return "'" + str(s) + "'"; }
std::string layerName(const MeshModel& m) { return "layer " + quoted(cbdplugin::panelName(m)); }

/// Help texts are rich text: anything that reads like a tag ("<source>") must be escaped, or Qt
/// drops it.
QString help(const char* text) { return QString(text).toHtmlEscaped(); }

// --- parameters, read without MeshLab's asserting getters

MeshModel* layerParameter(const RichParameterList& par, const char* name, MeshDocument& md) {
  MeshModel* m = cbdplugin::layerParameter(par, name, md);
  if (m == nullptr) refuse(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' does not name a mesh layer");
  return m;
}

QString fileParameter(const RichParameterList& par, const char* name) {
  QString s;
  if (!cbdplugin::fileParameterValue(par, name, s))
    refuse(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' is missing or not a file name");
  return s.trimmed();
}

int intParameter(const RichParameterList& par, const char* name) {
  int v = 0;
  if (!cbdplugin::intParameterValue(par, name, v))
    refuse(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' is missing or not an integer");
  return v;
}

bool boolParameter(const RichParameterList& par, const char* name) {
  bool v = false;
  if (!cbdplugin::boolParameterValue(par, name, v))
    refuse(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' is missing or not true/false");
  return v;
}

/// validateInput names the meshes "source"/"target"; say which layer that is.
std::string withLayerNames(std::string message, const MeshModel& source, const MeshModel& target) {
  for (const auto& [role, layer] : {std::pair<std::string, const MeshModel*>{"source mesh", &source},
                                    std::pair<std::string, const MeshModel*>{"target mesh", &target}}) {
    const std::string the = "the " + role;
    if (message.rfind(role, 0) == 0) return role + " (" + layerName(*layer) + ")" + message.substr(role.size());
    if (message.rfind(the, 0) == 0) return the + " (" + layerName(*layer) + ")" + message.substr(the.size());
  }
  return message;
}

/// The largest snap distance of one side, with the anchor's name.
std::string largestSnap(const std::vector<cbd::SnappedAnchor>& anchors) {
  const cbd::SnappedAnchor* worst = nullptr;
  for (const auto& a : anchors)
    if (!worst || a.snapDistance > worst->snapDistance) worst = &a;
  return worst ? cbd::fixed(100 * worst->snapDistance, 2) + " % ('" + worst->name + "')" : "-";
}

int distinct(std::vector<int> labels) {
  std::sort(labels.begin(), labels.end());
  return static_cast<int>(std::unique(labels.begin(), labels.end()) - labels.begin());
}

}  // namespace

FilterCbdPlugin::FilterCbdPlugin() { CBD_REGISTER_FILTERS(FP_VORONOI_BASE_DOMAIN, FP_CROSS_PARAMETERIZE); }

FilterCbdPlugin::~FilterCbdPlugin() = default;  // the actions are children of this QObject

QString FilterCbdPlugin::pluginName() const { return "FilterCbd"; }

QString FilterCbdPlugin::filterName(int filter) const {
  switch (filter) {
    case FP_VORONOI_BASE_DOMAIN: return QStringLiteral("Voronoi common base domain");
    case FP_CROSS_PARAMETERIZE: return QStringLiteral("Cross-parameterize");
  }
  return QStringLiteral("cbd: unknown filter");
}

QString FilterCbdPlugin::filterInfo(int filter) const {
  const QString common = tr(
      "<br><br>Source and target are two closed, manifold, connected, consistently oriented triangle "
      "meshes of the same genus. Their corresponding anchor points are matched <b>by name</b> "
      "(at least 3). The anchors of a layer are, in this order: the given anchors file (MeshLab "
      "PickPoints <i>.pp</i>, <i>index [x y z]</i> lines, or <i>name x y z</i> lines); else the "
      "points picked with <i>Edit &gt; PickPoints</i> on the layer; else the file "
      "<i>&lt;mesh name&gt;_picked_points.pp</i> next to the mesh file. The input layers "
      "are changed only on success (their face colours), never their geometry.<br><br>See: <i>Tsz-Ho "
      "Kwok, Yunbo Zhang, Charlie C. L. Wang</i><br><b>\"Constructing common base domain by cues from "
      "Voronoi diagram\"</b><br>Graphical Models 74(4), 2012.");
  switch (filter) {
    case FP_VORONOI_BASE_DOMAIN:
      return tr("Builds a common base domain of two meshes: corresponding patch layouts on both "
                "surfaces whose nodes are the anchors, traced from cues of the geodesic Voronoi "
                "diagram of the anchors (or by greedy shortest paths).<br><br>Result: both layers "
                "coloured per face by patch (corresponding patches get the same colour) or, "
                "optionally, by Voronoi cluster; a new layer per surface with the layout paths as "
                "an edge mesh (one colour per path); the log sums it up, then lists the anchors, "
                "edges, patches and timings.") + common;
    case FP_CROSS_PARAMETERIZE:
      return tr("Builds a common base domain of two meshes and, through it, a cross-parameterization: "
                "a bijective map between the two surfaces that sends each anchor to its "
                "corresponding anchor.<br><br>Result: the new current layer <i>&lt;source&gt; onto "
                "&lt;target&gt;</i> (M<sub>st</sub>: the source's triangles with every vertex at its "
                "image on the target; face quality = L2 stretch, coloured blue - white - red; "
                "vertex colour transferred from the target when it has vertex colours); both "
                "layers coloured per face by patch; optionally the layout paths as edge meshes. "
                "The log's first line sums up the distortion (E<sub>ang</sub>, E<sub>L2</sub>, "
                "flipped triangles) and the time; the details follow.") + common;
  }
  return QString();
}

// Remeshing: the menu Filters > Remeshing, Simplification and Reconstruction. (MeshCreation would
// also list the filters under "Create New Mesh Layer" and reset the view; FaceColoring would list
// them under "Color Creation".)
cbdplugin::FilterClassType FilterCbdPlugin::filterClass(int) const { return cbdplugin::FilterBase::Remeshing; }

cbdplugin::Arity FilterCbdPlugin::arity(int) const { return cbdplugin::FilterBase::FIXED; }

int FilterCbdPlugin::requirements(int) const { return MeshModel::MM_NONE; }

// None: the filters pick their own layers in their dialog, so MeshLab must not refuse them for
// what the current layer lacks (a path layer has no faces); the input checks name what is wrong.
int FilterCbdPlugin::preconditions(int) const { return MeshModel::MM_NONE; }

// What changes on the existing layers: per-face colour (the new layers are set up by MeshLab as
// new meshes). MeshLab re-uploads these attributes and switches the rendering to face colour.
int FilterCbdPlugin::postconditions(int) const { return MeshModel::MM_FACECOLOR; }

void FilterCbdPlugin::parameters(int id, const MeshDocument& md, RichParameterList& par) {
  const std::vector<const MeshModel*> all = cbdplugin::layers(md);
  const MeshModel* current = md.mm() ? md.mm() : (all.empty() ? nullptr : all.front());
  const MeshModel* other = current;
  for (const MeshModel* m : all)
    if (m != current) {
      other = m;
      break;
    }
  par.addParam(cbdplugin::meshParameter(kSourceMesh, current, md, "Source mesh",
                                        help("The source surface (a closed triangle mesh).")));
  par.addParam(cbdplugin::meshParameter(kTargetMesh, other, md, "Target mesh",
                                        help("The target surface: same genus as the source.")));
  const QStringList exts("Anchor files (*.pp *.txt *.vts);;All files (*)");
  par.addParam(cbdplugin::fileParameter(
      kSourceAnchors, exts, "Source anchors file",
      help("Empty: the points picked with Edit > PickPoints on the source layer, else "
           "<mesh name>_picked_points.pp next to the source mesh file. To clear a chosen file, press "
           "the browse button and cancel.")));
  par.addParam(cbdplugin::fileParameter(
      kTargetAnchors, exts, "Target anchors file",
      help("Empty: the points picked with Edit > PickPoints on the target layer, else "
           "<mesh name>_picked_points.pp next to the target mesh file.")));
  par.addParam(RichEnum(kMethod, 0, QStringList{"Voronoi", "Greedy shortest paths"}, "Method",
                        help("How the base-domain edges are traced: from cues of the geodesic Voronoi "
                             "diagram of the anchors, or greedily as shortest paths (Kraevoy & Sheffer 2004).")));
  par.addParam(RichInt(kMinEdgeNodes, 3, "Minimum edge nodes",
                       help("b (1..16): the nodes the paths may pass on every edge of the mesh, besides its "
                            "vertices; 1 with adaptive nodes off is the paper's E1.")));
  par.addParam(RichBool(kAdaptiveEdgeNodes, true, "Adaptive edge nodes",
                        help("More nodes on mesh edges longer than their neighbours' mean: max(b, b l / l_mean) "
                             "(else every edge gets b).")));
  if (id == FP_VORONOI_BASE_DOMAIN)
    par.addParam(RichBool(kColourByCluster, false, "Colour by Voronoi cluster",
                          help("Colour the two layers per face by the Voronoi cluster of the anchors "
                               "(corresponding clusters get the same colour) instead of by patch. "
                               "Voronoi method only.")));
  if (id == FP_CROSS_PARAMETERIZE) {
    par.addParam(RichInt(kStraightenRounds, cbd::PathStraighteningOptions{}.rounds, "Straighten paths (rounds)",
                         help("Rounds straightening every path of both base domains inside its two patches "
                              "(the diagonal of their quadrilateral mapped onto a square), before the patches "
                              "are parameterized; the same for either method (0: the paths as traced; at most 8).")));
    par.addParam(RichInt(kSmoothingIterations, 0, "Smoothing iterations",
                         help("Smoothing passes over the cross-parameterization (0: none; at most 1000).")));
    par.addParam(RichBool(kAddMstLayer, true, "Add M_st layer",
                          help("Add the layer '<source> onto <target>' and make it current: the source's "
                               "triangles with every vertex moved to its image on the target. Face quality = "
                               "L2 stretch (coloured blue - white - red); vertex colour transferred from the "
                               "target when it has vertex colours.")));
    par.addParam(RichBool(kColourByPatch, true, "Colour layers by patch",
                          help("Colour the source and target layers per face by patch of the common base "
                               "domain (corresponding patches get the same colour).")));
    par.addParam(RichBool(kAddPathLayers, false, "Add path layers",
                          help("Also add one edge-mesh layer per surface with the paths of the common "
                               "base domain.")));
  }
}

cbdplugin::Outcome FilterCbdPlugin::run(int filter, MeshDocument& md, const RichParameterList& par,
                                        vcg::CallBackPos* cb) {
  const std::string tag = "cbd: " + str(filterName(filter)) + ": ";
  cbdplugin::Outcome o;
  try {
    o = apply(filter, md, par, cb);
  } catch (const InputError& e) {
    o.error = tag + e.status.message + " [" + cbd::errorCodeName(e.status.code) + "]";
  } catch (const std::bad_alloc&) {
    o.error = tag + "out of memory [internal_error]";
  } catch (const std::exception& e) {
    o.error = tag + "unexpected error: " + e.what() + " [internal_error]";
  } catch (...) {
    o.error = tag + "unexpected error of unknown type [internal_error]";
  }
  // meshlabserver prints the log, not the error dialog's text.
  if (!o.ok()) logLine(GLLogStream::WARNING, o.error);
  return o;
}

cbdplugin::Outcome FilterCbdPlugin::apply(int filter, MeshDocument& md, const RichParameterList& par,
                                          vcg::CallBackPos* cb) {
  const bool map = filter == FP_CROSS_PARAMETERIZE;
  const std::string tag = "cbd: " + str(filterName(filter)) + ": ";
  std::vector<std::string> details;  // logged after the summary line
  auto detail = [&](const std::string& line) { details.push_back(line); };

  // Parameters.
  MeshModel* sourceLayer = layerParameter(par, kSourceMesh, md);
  MeshModel* targetLayer = layerParameter(par, kTargetMesh, md);
  const QString sourceFile = fileParameter(par, kSourceAnchors), targetFile = fileParameter(par, kTargetAnchors);
  cbd::CrossParameterizationOptions options;
  const int method = intParameter(par, kMethod);
  if (method != 0 && method != 1)
    refuse(cbd::ErrorCode::InvalidArgument, "'Method' must be 0 (Voronoi) or 1 (Greedy shortest paths), got " +
                                                std::to_string(method));
  options.method = method == 1 ? cbd::LayoutMethod::Greedy : cbd::LayoutMethod::Voronoi;
  options.edgeNodes.minEdgeNodes = intParameter(par, kMinEdgeNodes);
  options.edgeNodes.adaptive = boolParameter(par, kAdaptiveEdgeNodes);
  bool byCluster = false, colourByPatch = true, addMst = false, addPaths = true;
  if (map) {
    options.straightening.rounds = intParameter(par, kStraightenRounds);
    options.smoothing.iterations = intParameter(par, kSmoothingIterations);
    addMst = boolParameter(par, kAddMstLayer);
    colourByPatch = boolParameter(par, kColourByPatch);
    addPaths = boolParameter(par, kAddPathLayers);
  } else {
    options.straightening.rounds = 0;  // the layout filter shows the paths as traced
    byCluster = boolParameter(par, kColourByCluster);
  }
  if (cbd::Status s = cbd::validate(options); !s) refuse(s.code, s.message);
  if (sourceLayer == targetLayer) detail(tag + "warning: source and target are the same " + layerName(*sourceLayer));

  // MeshLab's progress bar: reading 0-5 %, the core 5-95 %, the layers 95-100 %.
  auto bar = [cb](int percent, const char* text) { return cb == nullptr || (*cb)(percent, text); };
  bar(0, "cbd: reading the layers");

  // Layers and anchors (read only).
  cbd::IndexedMesh source, target;
  cbdplugin::LayerIndex sourceIndex, targetIndex;
  int sourceDeleted = 0, targetDeleted = 0;
  if (cbd::Status s = cbdplugin::toIndexed(*sourceLayer, source, sourceIndex, sourceDeleted); !s) refuse(s.code, s.message);
  if (cbd::Status s = cbdplugin::toIndexed(*targetLayer, target, targetIndex, targetDeleted); !s) refuse(s.code, s.message);
  const cbdplugin::GatheredAnchors sa = cbdplugin::gatherAnchors(*sourceLayer, sourceFile, "source");
  const cbdplugin::GatheredAnchors ta = cbdplugin::gatherAnchors(*targetLayer, targetFile, "target");
  for (const auto& [layer, anchors, deleted] :
       {std::tuple<const MeshModel*, const cbdplugin::GatheredAnchors*, int>{sourceLayer, &sa, sourceDeleted},
        std::tuple<const MeshModel*, const cbdplugin::GatheredAnchors*, int>{targetLayer, &ta, targetDeleted}}) {
    if (deleted > 0 && anchors->set.status.ok() && anchors->set.format == cbd::AnchorFormat::VertexList)
      detail(tag + "warning: " + layerName(*layer) + " has " + std::to_string(deleted) +
             " deleted vertices: the anchor vertex indices refer to the compacted layer");
    if (!(layer->cm.Tr == Matrix44m::Identity()))
      detail(tag + "warning: " + layerName(*layer) + " has a transformation matrix; cbd uses the untransformed "
             "vertex coordinates (Filters > Normals, Curvatures and Orientation > Matrix: Freeze Current Matrix)");
  }

  // Validation.
  const cbd::InputReport report = cbd::validateInput(source, target, sa.set, ta.set, cbd::ValidationOptions{});
  for (const std::string& w : cbd::inputWarnings(report))
    detail(tag + "warning: " + withLayerNames(w, *sourceLayer, *targetLayer));
  if (!report.status) {
    for (const std::string& line : details) logLine(GLLogStream::FILTER, line);
    refuse(report.status.code, withLayerNames(report.status.message, *sourceLayer, *targetLayer));
  }
  std::string anchorsLine = tag + std::to_string(report.anchors.size()) + " anchors matched by name (source: " +
                            sa.origin + ", target: " + ta.origin + ")";
  if (const int inactive = sa.set.skippedInactive + ta.set.skippedInactive; inactive > 0)
    anchorsLine += ", " + std::to_string(inactive) + " inactive points skipped";
  detail(tag + "source " + layerName(*sourceLayer) + ": " + std::to_string(report.source.vertices) + " vertices, " +
         std::to_string(report.source.faces) + " faces, genus " + std::to_string(report.source.genus));
  detail(tag + "target " + layerName(*targetLayer) + ": " + std::to_string(report.target.vertices) + " vertices, " +
         std::to_string(report.target.faces) + " faces, genus " + std::to_string(report.target.genus));
  detail(anchorsLine);
  detail(tag + "largest snap distance (of the bounding-box diagonal): source " + largestSnap(report.anchors.source) +
         ", target " + largestSnap(report.anchors.target));

  // The core.
  options.anchorNames = report.anchors.names;
  std::vector<int> sv, tv;
  for (const auto& a : report.anchors.source) sv.push_back(a.vertex);
  for (const auto& a : report.anchors.target) tv.push_back(a.vertex);
  const int euler = report.source.eulerCharacteristic;
  const cbd::Progress progress(
      [&bar](int percent, const char* stage) { return bar(5 + percent * 90 / 100, stage); });
  auto coreLines = [&](const std::vector<std::string>& lines) {
    for (const std::string& l : lines) detail(tag + QString::fromStdString(l).simplified().toStdString());
  };
  const QString sourceStem = cbdplugin::stem(*sourceLayer), targetStem = cbdplugin::stem(*targetLayer);
  std::string summary;
  std::vector<std::string> layerLines;

  if (!map) {
    cbd::LayoutPair p = cbd::buildLayouts(source, sv, target, tv, euler, options, progress);
    if (!p.status) refuse(p.status.code, p.status.message);
    bar(95, "cbd: writing the layers");
    if (byCluster && (p.source.faceCluster.empty() || p.target.faceCluster.empty())) {
      detail(tag + "warning: 'Colour by Voronoi cluster' needs the Voronoi method; colouring by patch");
      byCluster = false;
    }
    const std::vector<int> sl = byCluster ? cbd::inputFaceCluster(p.source) : cbd::inputFacePatch(p.source);
    const std::vector<int> tl = byCluster ? cbd::inputFaceCluster(p.target) : cbd::inputFacePatch(p.target);
    const cbdplugin::PathLayer sp = cbdplugin::pathLayer(p.source), tp = cbdplugin::pathLayer(p.target);
    // Success: write the results.
    cbdplugin::colourFaces(*sourceLayer, sourceIndex, sl);
    cbdplugin::colourFaces(*targetLayer, targetIndex, tl);
    const MeshModel* a = cbdplugin::addPathLayer(md, sourceStem + " base domain", sp);
    const MeshModel* b = cbdplugin::addPathLayer(md, targetStem + " base domain", tp);
    summary = tag + std::to_string(p.source.edges.size()) + " paths, " + std::to_string(p.source.patches.size()) +
              " patches on " + quoted(cbdplugin::panelName(*sourceLayer)) + " and " +
              quoted(cbdplugin::panelName(*targetLayer)) + ", " + cbd::fixed(p.times.voronoi + p.times.sourceLayout + p.times.targetLayout, 2) +
              " s; new layers " + quoted(cbdplugin::panelName(*a)) + " and " + quoted(cbdplugin::panelName(*b));
    coreLines(cbd::layoutLines(p));
    for (const std::string& w : p.warnings) detail(tag + "warning: " + w);
    coreLines({cbd::timesLine(p.times, false)});
    layerLines.push_back(tag + "layers " + quoted(cbdplugin::panelName(*sourceLayer)) + " and " +
                         quoted(cbdplugin::panelName(*targetLayer)) + " coloured per face by " +
                         (byCluster ? "Voronoi cluster (" : "patch (") + std::to_string(distinct(sl)) + " / " +
                         std::to_string(distinct(tl)) + " colours; corresponding " +
                         (byCluster ? "clusters" : "patches") + " share a colour)");
    layerLines.push_back(tag + "new layers " + quoted(cbdplugin::panelName(*a)) + " and " +
                         quoted(cbdplugin::panelName(*b)) + ": the layout paths as edge meshes (" +
                         std::to_string(sp.segments.size()) + " / " + std::to_string(tp.segments.size()) +
                         " segments; vertex colour per path, vertex quality = path index)");
  } else {
    const cbd::CrossParameterizationResult r = cbd::crossParameterize(source, sv, target, tv, euler, options, progress);
    if (!r.status) refuse(r.status.code, r.status.message);
    bar(95, "cbd: writing the layers");
    std::vector<int> sl, tl;
    if (colourByPatch) sl = cbd::inputFacePatch(r.layouts.source), tl = cbd::inputFacePatch(r.layouts.target);
    cbdplugin::PathLayer sp, tp;
    if (addPaths) sp = cbdplugin::pathLayer(r.layouts.source), tp = cbdplugin::pathLayer(r.layouts.target);
    cbdplugin::MstLayer mst;
    if (addMst) mst = cbdplugin::mstLayer(source, r, *targetLayer, target, targetIndex);
    // Success: write the results.
    if (colourByPatch) {
      cbdplugin::colourFaces(*sourceLayer, sourceIndex, sl);
      cbdplugin::colourFaces(*targetLayer, targetIndex, tl);
    }
    const MeshModel *a = nullptr, *b = nullptr, *m = nullptr;
    if (addPaths) {
      a = cbdplugin::addPathLayer(md, sourceStem + " base domain", sp);
      b = cbdplugin::addPathLayer(md, targetStem + " base domain", tp);
    }
    if (addMst) m = cbdplugin::addMstLayer(md, sourceStem + " onto " + targetStem, mst);
    summary = tag + quoted(cbdplugin::panelName(*sourceLayer)) + " onto " + quoted(cbdplugin::panelName(*targetLayer)) +
              ": " + cbd::summary(r.metrics, r.times.total) +
              (m ? "; new layer " + quoted(cbdplugin::panelName(*m)) + " (M_st)" : std::string());
    coreLines(cbd::layoutLines(r.layouts));
    for (const std::string& w : r.layouts.warnings) detail(tag + "warning: " + w);
    coreLines(cbd::mapLines(r, options));
    coreLines({cbd::timesLine(r.times, true)});
    if (colourByPatch)
      layerLines.push_back(tag + "layers " + quoted(cbdplugin::panelName(*sourceLayer)) + " and " +
                           quoted(cbdplugin::panelName(*targetLayer)) + " coloured per face by patch (" +
                           std::to_string(r.layouts.source.patches.size()) +
                           " patches; corresponding patches share a colour)");
    if (m) {
      std::vector<double> s;
      for (double q : mst.faceQuality)
        if (!std::isnan(q)) s.push_back(q);
      std::sort(s.begin(), s.end());
      layerLines.push_back(
          tag + "new layer " + quoted(cbdplugin::panelName(*m)) + " (M_st): " + std::to_string(mst.positions.size()) +
          " vertices, " + std::to_string(mst.faces.size()) + " faces on the target; face quality = L2 stretch (median " +
          cbd::fixed(s.empty() ? 0.0 : s[s.size() / 2], 3) + ", max " + cbd::fixed(s.empty() ? 0.0 : s.back(), 3) +
          "), face colour blue (compressed) - white - red (stretched x2)" +
          (mst.hasVertexColour ? "; vertex colour transferred from the target" : "") +
          (mst.hasVertexQuality ? "; vertex quality transferred from the target" : ""));
    }
    if (a && b)
      layerLines.push_back(tag + "new layers " + quoted(cbdplugin::panelName(*a)) + " and " +
                           quoted(cbdplugin::panelName(*b)) + ": the layout paths as edge meshes");
  }
  logLine(GLLogStream::FILTER, summary);
  for (const std::string& line : details) logLine(GLLogStream::FILTER, line);
  for (const std::string& line : layerLines) logLine(GLLogStream::FILTER, line);
  bar(100, "cbd: done");
  return {};
}
