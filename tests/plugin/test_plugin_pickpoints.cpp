/// @file test_plugin_pickpoints.cpp
/// The cbd plugin reads anchors placed with MeshLab's own PickPoints tool. There is no GUI here,
/// so this does what edit_pickpoints does (PickPointsDialog::savePointsToMetaData): a
/// `PickedPoints*` stored as the per-mesh attribute "PickedPoints" of each layer. The plugin
/// is loaded the way MeshLab loads it (PluginManager::loadPlugins on a plugin folder), the
/// layers are built in a MeshDocument, and the filters are applied through applyFilter:
///   1. only the source has picked points (and no layer has a file name): the filter fails,
///      names the target layer, and leaves the document as it was;
///   2. both have picked points (plus an inactive point, skipped): "Cross-parameterize"
///      succeeds with the anchors from PickPoints; M_st has the source's vertex count; both
///      layers get per-face colours, the same set, one per patch;
///   3. "Voronoi common base domain" with "Colour by Voronoi cluster": one colour per anchor,
///      the same set on both layers, and two new path layers (edge meshes).
/// Usage: test_plugin_pickpoints PLUGIN_DIR SOURCE.off SOURCE.pp TARGET.off TARGET.pp PATCHES
/// (PLUGIN_DIR holds libfilter_cbd.so; PATCHES the expected patch count.) Runs without a display
/// (Qt's offscreen platform).

#include <array>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

// The OFF importer first: it uses GLU tessellation when gl.h was included before it.
#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/import_off.h>

#include <QApplication>
#include <QDir>

#include <common/GLLogStream.h>
#include <common/interfaces.h>
#include <common/meshmodel.h>
#include <common/pluginmanager.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include "pickedPoints.h"

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

MeshModel* loadLayer(MeshDocument& md, const char* path, const QString& label) {
  // No file name: the plugin's fallback (<mesh>_picked_points.pp next to the file) cannot apply.
  MeshModel* m = md.addNewMesh("", label, false);
  if (vcg::tri::io::ImporterOFF<CMeshO>::Open(m->cm, path) != 0) {
    std::fprintf(stderr, "cannot load %s\n", path);
    std::exit(2);
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m->cm);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m->cm);
  return m;
}

/// What PickPointsDialog::savePointsToMetaData stores: a PickedPoints* built with addPoint.
PickedPoints* pick(MeshModel& m, const char* ppFile, bool withInactive) {
  PickedPoints file;
  if (!file.open(ppFile)) {
    std::fprintf(stderr, "cannot read %s\n", ppFile);
    std::exit(2);
  }
  auto* pp = new PickedPoints();
  for (const PickedPoint* p : file.getPickedPointVector()) pp->addPoint(p->name, p->point, p->present);
  if (withInactive) pp->addPoint("not_really_picked", Point3m(0, 0, 0), false);
  CMeshO::PerMeshAttributeHandle<PickedPoints*> h =
      vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<PickedPoints*>(m.cm, PickedPoints::Key);
  h() = pp;
  return pp;
}

std::set<std::array<int, 3>> faceColours(const MeshModel& m) {
  std::set<std::array<int, 3>> s;
  if (!m.hasDataMask(MeshModel::MM_FACECOLOR)) return s;
  for (const CFaceO& f : m.cm.face)
    if (!f.IsD()) s.insert({f.cC()[0], f.cC()[1], f.cC()[2]});
  return s;
}

bool logHas(const GLLogStream& log, const QString& text) {
  for (const auto& line : log.logStringList())
    if (line.second.contains(text)) return true;
  return false;
}

void dumpLog(const GLLogStream& log) {
  for (const auto& line : log.logStringList()) std::printf("  log: %s\n", qUtf8Printable(line.second));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s PLUGIN_DIR SOURCE.off SOURCE.pp TARGET.off TARGET.pp PATCHES\n", argv[0]);
    return 2;
  }
  if (qgetenv("QT_QPA_PLATFORM").isEmpty()) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  const int patches = std::atoi(argv[6]);

  PluginManager pm;
  RichParameterList globals;
  pm.loadPlugins(globals, QDir(argv[1]));
  MeshFilterInterface* filter = pm.stringFilterMap.value("Cross-parameterize", nullptr);
  QAction* cross = pm.actionFilterMap.value("Cross-parameterize", nullptr);
  QAction* voronoi = pm.actionFilterMap.value("Voronoi common base domain", nullptr);
  check(filter && cross && voronoi, "PluginManager loaded the cbd filters from " + std::string(argv[1]));
  if (!filter || !cross || !voronoi) return 1;
  GLLogStream log;
  filter->setLog(&log);

  MeshDocument md;
  MeshModel* source = loadLayer(md, argv[2], "source.off");
  MeshModel* target = loadLayer(md, argv[4], "target.off");
  const int sourceVertices = source->cm.vn;
  auto params = [&](QAction* action) {
    RichParameterList par;
    filter->initParameterSet(action, md, par);
    par.setValue("SourceMesh", MeshValue(source));
    par.setValue("TargetMesh", MeshValue(target));
    return par;
  };

  // 1. Picked points on the source only.
  PickedPoints* sp = pick(*source, argv[3], true);
  {
    RichParameterList par = params(cross);
    const bool ok = filter->applyFilter(cross, md, par, nullptr);
    check(!ok, "Cross-parameterize fails without picked points on the target");
    check(filter->errorMsg().contains("no target anchors: layer 'target.off' has no picked points and no file name"),
          "the error names the target layer: " + filter->errorMsg().toStdString());
    check(logHas(log, "no target anchors"), "the error is in the log");
    check(md.size() == 2 && !source->hasDataMask(MeshModel::MM_FACECOLOR) &&
              !target->hasDataMask(MeshModel::MM_FACECOLOR),
          "the document is unchanged (2 layers, no face colour)");
  }

  // 2. Both layers have picked points: Cross-parameterize.
  PickedPoints* tp = pick(*target, argv[5], false);
  log.Clear();
  {
    RichParameterList par = params(cross);
    const bool ok = filter->applyFilter(cross, md, par, nullptr);
    if (!ok) dumpLog(log);
    check(ok, "Cross-parameterize succeeds with anchors from PickPoints");
    check(logHas(log, "anchors matched by name (source: PickPoints of layer 'source.off', target: PickPoints of "
                      "layer 'target.off'), 1 inactive points skipped"),
          "the anchors came from the PickedPoints attributes (inactive point skipped)");
    check(md.size() == 3, "one new layer (M_st): " + std::to_string(md.size()) + " layers");
    MeshModel* mst = md.size() == 3 ? md.meshList.at(2) : nullptr;
    check(mst && mst->label() == "source onto target" && mst->cm.vn == sourceVertices &&
              mst->cm.fn == source->cm.fn && mst->hasDataMask(MeshModel::MM_FACEQUALITY),
          "M_st 'source onto target' has the source's vertex and face counts and face quality");
    const auto sc = faceColours(*source), tc = faceColours(*target);
    check(sc == tc && static_cast<int>(sc.size()) == patches,
          "both layers coloured by patch, same colour set: " + std::to_string(sc.size()) + " / " +
              std::to_string(tc.size()) + " colours (expected " + std::to_string(patches) + ")");
  }

  // 3. Voronoi common base domain, coloured by Voronoi cluster.
  log.Clear();
  {
    RichParameterList par = params(voronoi);
    par.setValue("ColourByCluster", BoolValue(true));
    const int layers = md.size();
    const bool ok = filter->applyFilter(voronoi, md, par, nullptr);
    if (!ok) dumpLog(log);
    check(ok, "Voronoi common base domain succeeds with anchors from PickPoints");
    const int anchors = static_cast<int>(sp->getPickedPointVector().size()) - 1;
    const auto sc = faceColours(*source), tc = faceColours(*target);
    check(sc == tc && static_cast<int>(sc.size()) == anchors,
          "both layers coloured by Voronoi cluster, same colour set: " + std::to_string(sc.size()) + " / " +
              std::to_string(tc.size()) + " colours (expected " + std::to_string(anchors) + ")");
    check(md.size() == layers + 2 && md.meshList.at(layers)->cm.en > 0 && md.meshList.at(layers + 1)->cm.en > 0 &&
              md.meshList.at(layers)->cm.fn == 0,
          "two new path layers (edge meshes)");
    check(logHas(log, "layout (voronoi): ") && logHas(log, "timings: "), "the log lists the layout and the timings");
  }

  for (MeshModel* m : {source, target})
    vcg::tri::Allocator<CMeshO>::DeletePerMeshAttribute(m->cm, PickedPoints::Key);
  delete sp;
  delete tp;
  std::printf("%s\n", failures ? "FAILED" : "PASS");
  return failures ? 1 : 0;
}
