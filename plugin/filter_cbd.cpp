/// @file filter_cbd.cpp
/// The MeshLab adapter of cbd: layer -> cbd::IndexedMesh, anchors -> cbd::AnchorSet,
/// cbd::validateInput, report, then runPipeline. No geometry here.

#include "filter_cbd.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <new>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include <QFile>
#include <QFileInfo>

#include "cbd/anchors.h"
#include "cbd/mesh.h"
#include "cbd/status.h"
#include "cbd/validate_input.h"
#include "cbd_pipeline.h"
#include "pickedPoints.h"

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

/// An input problem found by the adapter; applyFilter turns it into the error message.
struct AdapterError {
  cbd::Status status;
};

[[noreturn]] void throwError(cbd::ErrorCode code, const std::string& message) {
  throw AdapterError{cbd::Status::error(code, message)};
}

std::string str(const QString& s) { return s.toStdString(); }
std::string filePath(const QString& s) { return QFile::encodeName(s).toStdString(); }
std::string quoted(const QString& s) { return "'" + str(s) + "'"; }

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// --- parameters, read without MeshLab's asserting getters (a hand-written .mlx may give a
// --- parameter the wrong type, which would abort MeshLab inside RichParameterList::getX).

const Value& paramValue(const RichParameterList& par, const char* name) {
  if (!par.hasParameter(name)) throwError(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' is missing");
  return par.getParameterByName(name).value();
}

MeshModel* meshParam(const RichParameterList& par, const char* name) {
  const Value& v = paramValue(par, name);
  MeshModel* m = v.isMesh() ? v.getMesh() : nullptr;
  if (m == nullptr)
    throwError(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' does not name a mesh layer");
  return m;
}

QString pathParam(const RichParameterList& par, const char* name) {
  const Value& v = paramValue(par, name);
  if (v.isFileName()) return v.getFileName().trimmed();
  if (v.isString()) return v.getString().trimmed();
  throwError(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' must be a file name (RichOpenFile or RichString)");
}

int intParam(const RichParameterList& par, const char* name) {
  const Value& v = paramValue(par, name);
  if (v.isInt() || v.isEnum()) return v.getInt();
  throwError(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' must be an integer");
}

bool boolParam(const RichParameterList& par, const char* name) {
  const Value& v = paramValue(par, name);
  if (v.isBool()) return v.getBool();
  throwError(cbd::ErrorCode::InvalidArgument, std::string("parameter '") + name + "' must be true or false");
}

// --- layers

std::string layerName(const MeshModel& m) { return "layer " + quoted(m.label()); }

/// Compact double-precision copy of a layer: deleted vertices and faces skipped, vertex indices
/// renumbered in order; `where` tells where each compact element is in the layer. The layer is
/// only read.
cbd::IndexedMesh toIndexed(const MeshModel& layer, int& deletedVertices, cbdplugin::LayerIndex& where) {
  const CMeshO& cm = layer.cm;
  cbd::IndexedMesh out;
  std::vector<int> index(cm.vert.size(), -1);
  out.positions.reserve(static_cast<size_t>(std::max(cm.vn, 0)));
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
  out.faces.reserve(static_cast<size_t>(std::max(cm.fn, 0)));
  const CVertexO* base = cm.vert.empty() ? nullptr : &cm.vert[0];
  for (size_t f = 0; f < cm.face.size(); ++f) {
    const CFaceO& face = cm.face[f];
    if (face.IsD()) continue;
    std::array<int, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const CVertexO* vp = face.cV(k);
      const std::ptrdiff_t i = (vp && base) ? vp - base : -1;
      if (i < 0 || i >= static_cast<std::ptrdiff_t>(index.size()) || index[static_cast<size_t>(i)] < 0)
        throwError(cbd::ErrorCode::MalformedMesh,
              layerName(layer) + ": face " + std::to_string(f) + " refers to a deleted or foreign vertex "
              "(save and reload the layer, or run Filters > Cleaning and Repairing > Remove Unreferenced Vertices)");
      t[static_cast<size_t>(k)] = index[static_cast<size_t>(i)];
    }
    out.faces.push_back(t);
    where.face.push_back(static_cast<int>(f));
  }
  return out;
}

// --- anchors

/// Where a layer's anchors came from, for the report.
struct GatheredAnchors {
  cbd::AnchorSet set;
  std::string origin;
};

/// The layer's PickPoints attribute ("PickedPoints", a PickedPoints*), or null. Never creates it.
PickedPoints* pickedPointsOf(MeshModel& layer) {
  auto h = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<PickedPoints*>(layer.cm, PickedPoints::Key);
  if (!vcg::tri::Allocator<CMeshO>::IsValidHandle<PickedPoints*>(layer.cm, h)) return nullptr;
  return h();
}

/// Anchors of one layer: the explicit file when given; else the layer's PickPoints points;
/// else `<mesh basename>_picked_points.pp` next to the layer's file (PickPoints' own naming).
GatheredAnchors gatherAnchors(MeshModel& layer, const QString& explicitPath, const std::string& role) {
  GatheredAnchors g;
  if (!explicitPath.isEmpty()) {
    g.set = cbd::readAnchors(filePath(explicitPath));
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
  if (layer.fullName().isEmpty()) {
    g.set.source = layerName(layer);
    g.set.status = cbd::Status::error(
        cbd::ErrorCode::FileNotFound,
        "no " + role + " anchors: " + layerName(layer) + " has no picked points and no file name; pick points "
        "(Edit > PickPoints) or set the '" + role + " anchors file' parameter");
    return g;
  }
  const QString suggested = QFileInfo(layer.fullName()).absolutePath() + "/" +
                            PickedPoints::getSuggestedPickedPointsFileName(layer);
  if (!QFileInfo(suggested).isFile()) {
    g.set.source = filePath(suggested);
    g.set.status = cbd::Status::error(
        cbd::ErrorCode::FileNotFound,
        "no " + role + " anchors: " + layerName(layer) + " has no picked points and " + quoted(suggested) +
            " does not exist; pick points (Edit > PickPoints) or set the '" + role + " anchors file' parameter");
    return g;
  }
  g.set = cbd::readAnchors(filePath(suggested));
  g.origin = "file " + quoted(suggested);
  return g;
}

/// validateInput names the meshes "source"/"target"; say which layer that is.
std::string withLayerNames(std::string message, const MeshModel& source, const MeshModel& target) {
  for (const auto& [role, layer] : {std::pair<std::string, const MeshModel*>{"source mesh", &source},
                                    std::pair<std::string, const MeshModel*>{"target mesh", &target}}) {
    const std::string prefix = role, the = "the " + role;
    if (message.rfind(prefix, 0) == 0)
      return role + " (" + layerName(*layer) + ")" + message.substr(prefix.size());
    if (message.rfind(the, 0) == 0)
      return the + " (" + layerName(*layer) + ")" + message.substr(the.size());
  }
  return message;
}

std::string meshSummary(const cbd::MeshReport& r) {
  std::ostringstream s;
  s << r.vertices << " vertices, " << r.faces << " faces, genus " << r.genus;
  if (r.unreferencedVertices > 0)
    s << ", " << cbd::counted(r.unreferencedVertices, "unreferenced vertex", "unreferenced vertices") << " ignored";
  return s.str();
}

/// The largest snap distance of one side, with the anchor's name.
std::string largestSnap(const std::vector<cbd::SnappedAnchor>& anchors) {
  const cbd::SnappedAnchor* worst = nullptr;
  for (const auto& a : anchors)
    if (!worst || a.snapDistance > worst->snapDistance) worst = &a;
  if (!worst) return "-";
  return fmt(worst->snapDistance) + " ('" + worst->name + "')";
}

cbdplugin::FilterKind kindOf(int filter) {
  return filter == FilterCbdPlugin::FP_CROSS_PARAMETERIZE ? cbdplugin::FilterKind::CrossParameterize
                                                           : cbdplugin::FilterKind::VoronoiBaseDomain;
}

}  // namespace

FilterCbdPlugin::FilterCbdPlugin() {
  typeList << FP_VORONOI_BASE_DOMAIN << FP_CROSS_PARAMETERIZE;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

FilterCbdPlugin::~FilterCbdPlugin() = default;  // the actions are children of this QObject

QString FilterCbdPlugin::pluginName() const { return "FilterCbd"; }

QString FilterCbdPlugin::filterName(FilterIDType filter) const {
  switch (filter) {
    case FP_VORONOI_BASE_DOMAIN: return QStringLiteral("Voronoi common base domain");
    case FP_CROSS_PARAMETERIZE: return QStringLiteral("Cross-parameterize");
  }
  return QStringLiteral("cbd: unknown filter");
}

QString FilterCbdPlugin::filterInfo(FilterIDType filter) const {
  const QString common = tr(
      "<br><br>Source and target are two closed, manifold, connected, consistently oriented triangle "
      "meshes of the same genus. Their corresponding anchor points are matched <b>by name</b> "
      "(at least 3). The anchors of a layer are, in this order: the given anchors file (MeshLab "
      "PickPoints <i>.pp</i>, <i>index [x y z]</i> lines, or <i>name x y z</i> lines); else the "
      "points picked with <i>Edit &gt; PickPoints</i> on the layer; else the file "
      "<i>&lt;mesh name&gt;_picked_points.pp</i> next to the mesh file. The input layers "
      "are changed only on success (their face colours), never their geometry.<br><br>See: <i>Tsz-Ho Kwok, Yunbo Zhang, Charlie C. L. Wang</i><br>"
      "<b>\"Constructing common base domains by cues from Voronoi diagram\"</b><br>"
      "Graphical Models 74(4), 2012.");
  switch (filter) {
    case FP_VORONOI_BASE_DOMAIN:
      return tr("Builds a common base domain of two meshes: corresponding patch layouts on both "
                "surfaces whose nodes are the anchors, traced from cues of the geodesic Voronoi "
                "diagram of the anchors (or by greedy shortest paths).<br><br>Result: both layers "
                "coloured per face by patch (corresponding patches get the same colour) or, "
                "optionally, by Voronoi cluster; a new layer per surface with the layout paths as "
                "an edge mesh (one colour per path); the log lists the anchors, edges, patches, "
                "multiple linkages and timings.") + common;
    case FP_CROSS_PARAMETERIZE:
      return tr("Builds a common base domain of two meshes and, through it, a cross-parameterization: "
                "a bijective map between the two surfaces that sends each anchor to its "
                "corresponding anchor.<br><br>Result: the layer <i>&lt;source&gt; onto "
                "&lt;target&gt;</i> (M<sub>st</sub>: the source's triangles with every vertex at its "
                "image on the target; face quality = L2 stretch, coloured blue - white - red; "
                "vertex colour transferred from the target when it has vertex colours); both "
                "layers coloured per face by patch; optionally the layout paths as edge meshes. "
                "The log lists the distortion (E<sub>ang</sub>, E<sub>L2</sub> and its inverse, "
                "flipped and degenerate triangles) and timings.") + common;
  }
  return QString();
}

// Remeshing only: the menu Filters > Remeshing, Simplification and Reconstruction. (MeshCreation
// would also list the filters under "Create New Mesh Layer" and reset the view; MeshLab sets up
// the rendering of new layers without it. FaceColoring would list them under "Color Creation".)
// The face colours of the existing layers are announced by postCondition.
MeshFilterInterface::FilterClass FilterCbdPlugin::getClass(QAction*) { return MeshFilterInterface::Remeshing; }

MeshFilterInterface::FILTER_ARITY FilterCbdPlugin::filterArity(QAction*) const { return FIXED; }

int FilterCbdPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

// The current layer must have faces (MeshLab greys the filter out otherwise).
int FilterCbdPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

// What changes on the existing layers: per-face colour (the new layers are set up by MeshLab as
// new meshes). MeshLab re-uploads these attributes and switches the rendering to face colour.
int FilterCbdPlugin::postCondition(QAction*) const { return MeshModel::MM_FACECOLOR; }

void FilterCbdPlugin::initParameterSet(QAction* action, MeshDocument& md, RichParameterList& par) {
  const int id = ID(action);
  MeshModel* current = md.mm();
  if (current == nullptr && !md.meshList.isEmpty()) current = md.meshList.first();
  MeshModel* other = current;
  for (MeshModel* m : md.meshList)
    if (m != current) {
      other = m;
      break;
    }
  // RichMesh asserts that its default belongs to the document: with no layer at all, give none.
  MeshDocument* doc = current ? &md : nullptr;
  par.addParam(RichMesh(kSourceMesh, current, doc, "Source mesh",
                        "The source surface (a closed triangle mesh)."));
  par.addParam(RichMesh(kTargetMesh, other, doc, "Target mesh",
                        "The target surface: same genus as the source."));
  const QStringList exts("Anchor files (*.pp *.txt *.vts);;All files (*)");
  par.addParam(RichOpenFile(kSourceAnchors, QString(), exts, "Source anchors file",
                            "Empty: the points picked with Edit > PickPoints on the source layer, else "
                            "<mesh name>_picked_points.pp next to the source mesh file. To clear a chosen "
                            "file, press the browse button and cancel."));
  par.addParam(RichOpenFile(kTargetAnchors, QString(), exts, "Target anchors file",
                            "Empty: the points picked with Edit > PickPoints on the target layer, else "
                            "<mesh name>_picked_points.pp next to the target mesh file."));
  par.addParam(RichEnum(kMethod, 0, QStringList{"Voronoi", "Greedy shortest paths"}, "Method",
                        "How the base-domain edges are traced: from cues of the geodesic Voronoi "
                        "diagram of the anchors, or greedily as shortest paths."));
  par.addParam(RichInt(kMinEdgeNodes, 3, "Minimum edge nodes",
                       "b (1..16): the nodes the paths may pass on every edge of the mesh, besides its "
                       "vertices; 1 with adaptive nodes off is the paper's E1."));
  par.addParam(RichBool(kAdaptiveEdgeNodes, true, "Adaptive edge nodes",
                        "More nodes on mesh edges longer than their neighbours' mean: max(b, b l / l_mean) "
                        "(else every edge gets b)."));
  if (id == FP_VORONOI_BASE_DOMAIN)
    par.addParam(RichBool(kColourByCluster, false, "Colour by Voronoi cluster",
                          "Colour the two layers per face by the Voronoi cluster of the anchors "
                          "(corresponding clusters get the same colour) instead of by patch. "
                          "Voronoi method only."));
  if (id == FP_CROSS_PARAMETERIZE) {
    par.addParam(RichInt(kStraightenRounds, cbd::PathStraighteningOptions{}.rounds, "Straighten paths (rounds)",
                         "Rounds straightening every path of both base domains inside its two patches "
                         "(the diagonal of their quadrilateral mapped onto a square), before the patches "
                         "are parameterized; the same for either method (0: the paths as traced; at most 8)."));
    par.addParam(RichInt(kSmoothingIterations, 0, "Smoothing iterations",
                         "Smoothing passes over the cross-parameterization (0: none)."));
    par.addParam(RichBool(kAddMstLayer, true, "Add M_st layer",
                          "Add the layer '<source> onto <target>': the source's triangles with every "
                          "vertex moved to its image on the target. Face quality = L2 stretch "
                          "(coloured blue - white - red); vertex colour transferred from the target "
                          "when it has vertex colours."));
    par.addParam(RichBool(kColourByPatch, true, "Colour layers by patch",
                          "Colour the source and target layers per face by patch of the common base "
                          "domain (corresponding patches get the same colour)."));
    par.addParam(RichBool(kAddPathLayers, false, "Add path layers",
                          "Also add one edge-mesh layer per surface with the paths of the common "
                          "base domain."));
  }
}

void FilterCbdPlugin::logLine(const std::string& text) { Log(GLLogStream::FILTER, text); }

bool FilterCbdPlugin::fail(const std::string& text) {
  errorMessage = QString::fromStdString(text);
  Log(GLLogStream::WARNING, text);  // meshlabserver prints the log, not errorMessage
  return false;
}

bool FilterCbdPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                                  vcg::CallBackPos* cb) {
  errorMessage.clear();
  std::string name = "cbd";
  try {
    name = str(filterName(action));
    return apply(ID(action), md, par, cb);
  } catch (const AdapterError& e) {
    return fail("cbd: " + name + ": " + e.status.message + " [" + cbd::errorCodeName(e.status.code) + "]");
  } catch (const std::bad_alloc&) {
    return fail("cbd: " + name + ": out of memory [internal_error]");
  } catch (const std::exception& e) {
    return fail("cbd: " + name + ": unexpected error: " + e.what() + " [internal_error]");
  } catch (...) {
    return fail("cbd: " + name + ": unexpected error of unknown type [internal_error]");
  }
}

bool FilterCbdPlugin::apply(int filter, MeshDocument& md, const RichParameterList& par,
                            vcg::CallBackPos* cb) {
  const std::string name = str(filterName(filter));
  const std::string tag = "cbd: " + name + ": ";
  auto progress = [cb](int percent, const char* text) {
    if (cb) (*cb)(percent, text);
  };

  // Parameters.
  MeshModel* sourceLayer = meshParam(par, kSourceMesh);
  MeshModel* targetLayer = meshParam(par, kTargetMesh);
  const QString sourcePath = pathParam(par, kSourceAnchors);
  const QString targetPath = pathParam(par, kTargetAnchors);
  cbdplugin::PipelineOptions options;
  const int method = intParam(par, kMethod);
  if (method != 0 && method != 1)
    throwError(cbd::ErrorCode::InvalidArgument, "'Method' must be 0 (Voronoi) or 1 (Greedy shortest paths), got " +
                                               std::to_string(method));
  options.method = static_cast<cbdplugin::LayoutMethod>(method);
  options.minEdgeNodes = intParam(par, kMinEdgeNodes);
  if (options.minEdgeNodes < 1 || options.minEdgeNodes > 16)
    throwError(cbd::ErrorCode::InvalidArgument,
               "'Minimum edge nodes' must be in 1..16 (as cbd's --min-edge-nodes), got " + std::to_string(options.minEdgeNodes));
  options.adaptiveEdgeNodes = boolParam(par, kAdaptiveEdgeNodes);
  if (filter == FP_CROSS_PARAMETERIZE) {
    options.straightenRounds = intParam(par, kStraightenRounds);
    if (options.straightenRounds < 0 || options.straightenRounds > 8)
      throwError(cbd::ErrorCode::InvalidArgument,
                 "'Straighten paths (rounds)' must be in 0..8 (each round refines the mesh along the paths), got " + std::to_string(options.straightenRounds));
    options.smoothingIterations = intParam(par, kSmoothingIterations);
    if (options.smoothingIterations < 0)
      throwError(cbd::ErrorCode::InvalidArgument,
            "'Smoothing iterations' must be >= 0, got " + std::to_string(options.smoothingIterations));
    options.addMstLayer = boolParam(par, kAddMstLayer);
    options.colourByPatch = boolParam(par, kColourByPatch);
    options.addPathLayers = boolParam(par, kAddPathLayers);
  } else {
    options.colourByCluster = boolParam(par, kColourByCluster);
    options.colourByPatch = !options.colourByCluster;
    options.addPathLayers = true;
    options.addMstLayer = false;
  }
  if (sourceLayer == targetLayer)
    logLine(tag + "warning: source and target are the same " + layerName(*sourceLayer));

  // Layers and anchors (read only).
  progress(0, "cbd: reading the layers");
  int sourceDeleted = 0, targetDeleted = 0;
  cbdplugin::LayerIndex sourceIndex, targetIndex;
  const cbd::IndexedMesh source = toIndexed(*sourceLayer, sourceDeleted, sourceIndex);
  const cbd::IndexedMesh target = toIndexed(*targetLayer, targetDeleted, targetIndex);
  const GatheredAnchors sourceAnchors = gatherAnchors(*sourceLayer, sourcePath, "source");
  const GatheredAnchors targetAnchors = gatherAnchors(*targetLayer, targetPath, "target");
  for (const auto& [layer, anchors, deleted] :
       {std::tuple<const MeshModel*, const GatheredAnchors*, int>{sourceLayer, &sourceAnchors, sourceDeleted},
        std::tuple<const MeshModel*, const GatheredAnchors*, int>{targetLayer, &targetAnchors, targetDeleted}}) {
    if (deleted > 0 && anchors->set.status.ok() && anchors->set.format == cbd::AnchorFormat::VertexList)
      logLine(tag + "warning: " + layerName(*layer) + " has " + std::to_string(deleted) +
              " deleted vertices: the anchor vertex indices refer to the compacted layer");
    if (!(layer->cm.Tr == Matrix44m::Identity()))
      logLine(tag + "warning: " + layerName(*layer) + " has a transformation matrix; cbd uses the untransformed "
              "vertex coordinates (Filters > Normals, Curvatures and Orientation > Matrix: Freeze Current Matrix)");
  }

  // Validation.
  progress(10, "cbd: validating the input");
  const cbd::InputReport report =
      cbd::validateInput(source, target, sourceAnchors.set, targetAnchors.set, cbd::ValidationOptions{});
  for (const auto* r : {&report.source, &report.target})
    for (const auto& w : r->warnings) logLine(tag + "warning: " + withLayerNames(w, *sourceLayer, *targetLayer));
  if (!report.status.ok())
    return fail(tag + withLayerNames(report.status.message, *sourceLayer, *targetLayer) + " [" +
                cbd::errorCodeName(report.status.code) + "]");

  logLine(tag + "source " + layerName(*sourceLayer) + ": " + meshSummary(report.source));
  logLine(tag + "target " + layerName(*targetLayer) + ": " + meshSummary(report.target));
  std::string anchorsLine = tag + std::to_string(report.anchors.size()) + " anchors matched by name (source: " +
                            sourceAnchors.origin + ", target: " + targetAnchors.origin + ")";
  const int inactive = sourceAnchors.set.skippedInactive + targetAnchors.set.skippedInactive;
  if (inactive > 0) anchorsLine += ", " + std::to_string(inactive) + " inactive points skipped";
  logLine(anchorsLine);
  logLine(tag + "largest snap distance (fraction of the bounding-box diagonal): source " +
          largestSnap(report.anchors.source) + ", target " + largestSnap(report.anchors.target));
  logLine(tag + "input valid");

  // The algorithm stages.
  progress(20, "cbd: building the common base domain");
  const cbdplugin::PipelineRequest request{kindOf(filter), name,         source,       target,      sourceIndex,
                                           targetIndex,    report,       options,      md,          *sourceLayer,
                                           *targetLayer,   [this](const std::string& s) { logLine(s); }};
  const cbd::Status status = cbdplugin::runPipeline(request, cb);
  if (!status.ok()) return fail(status.message);
  progress(100, "cbd: done");
  return true;
}
