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
#include <utility>
#include <vector>
#include <string>

// The OFF importer first: it uses GLU tessellation when gl.h was included before it.
#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/import_off.h>

#include <QApplication>
#include <QDir>
#include <QRegularExpression>
#include <QTextDocumentFragment>

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

/// What the plugin reports to MeshLab's progress bar (MainWindow::QCallBack in the GUI).
std::vector<std::pair<int, std::string>> progressSeen;
bool recordProgress(const int percent, const char* text) {
  progressSeen.emplace_back(percent, text ? text : "");
  return true;
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
    check(filter->errorMsg().contains("no target anchors: layer 'target' has no picked points and no file name"),
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
    progressSeen.clear();
    const bool ok = filter->applyFilter(cross, md, par, recordProgress);
    // The bar moves through every stage, with the stage's name, not only at the ends.
    std::set<int> middle;
    std::set<std::string> stages;
    bool monotone = true;
    for (size_t k = 0; k < progressSeen.size(); ++k) {
      if (progressSeen[k].first > 25 && progressSeen[k].first < 95) middle.insert(progressSeen[k].first);
      stages.insert(progressSeen[k].second);
      monotone = monotone && (k == 0 || progressSeen[k].first >= progressSeen[k - 1].first);
    }
    check(middle.size() >= 10 && monotone && progressSeen.back().first == 100,
          "the progress bar moves past 25 % in " + std::to_string(middle.size()) + " steps, never back, to 100 %");
    check(stages.count("tracing the base domain") && stages.count("mapping the patches") &&
              stages.count("polishing the map"),
          "the stages are named: " + [&] {
            std::string all;
            for (const std::string& n : stages) all += (all.empty() ? "" : ", ") + n;
            return all;
          }());
    if (!ok) dumpLog(log);
    check(ok, "Cross-parameterize succeeds with anchors from PickPoints");
    check(logHas(log, "anchors matched by name (source: PickPoints of layer 'source', target: PickPoints of "
                      "layer 'target'), 1 inactive points skipped"),
          "the anchors came from the PickedPoints attributes (inactive point skipped)");
    check(md.size() == 3, "one new layer (M_st): " + std::to_string(md.size()) + " layers");
    MeshModel* mst = md.size() == 3 ? md.meshList.at(2) : nullptr;
    check(mst && mst->label() == "source onto target" && mst->cm.vn == sourceVertices &&
              mst->cm.fn == source->cm.fn && mst->hasDataMask(MeshModel::MM_FACEQUALITY),
          "M_st 'source onto target' has the source's vertex and face counts and face quality");
    check(mst && md.mm() == mst, "M_st is the current layer");
    check(!log.logStringList().empty() && log.logStringList().front().second.startsWith(
              "cbd: Cross-parameterize: 'source' onto 'target': E_ang "),
          "the log's first line is the summary: " +
              (log.logStringList().empty() ? std::string() : log.logStringList().front().second.toStdString()));
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
    check(logHas(log, "layout voronoi: ") && logHas(log, "time voronoi "), "the log lists the layout and the timings");
  }

  // 4. Cross-parameterize again: MeshLab makes the new label unique, and the log names the layer
  //    as the layer panel shows it.
  log.Clear();
  {
    RichParameterList par = params(cross);
    const bool ok = filter->applyFilter(cross, md, par, nullptr);
    check(ok, "Cross-parameterize runs a second time");
    MeshModel* again = md.mm();
    const std::string label = again ? again->label().toStdString() : std::string();
    check(again && again->cm.vn == sourceVertices && label != "source onto target",
          "the second M_st is current, under a label of its own: '" + label + "'");
    check(logHas(log, QString::fromStdString("new layer '" + label + "' (M_st)")),
          "the log names the second M_st '" + label + "'");
  }

  // 5. Help texts: rich text in MeshLab's dialog; no word may read as a tag.
  {
    QStringList texts;
    for (QAction* a : {cross, voronoi}) {
      texts << filter->filterInfo(a);
      RichParameterList par = params(a);
      for (auto it = par.begin(); it != par.end(); ++it) texts << it->fieldDescription() << it->toolTip();
    }
    const QRegularExpression tag("<(?!/?(b|i|br|sub)>)[^>]*>");
    int stray = 0;
    for (const QString& t : texts)
      if (tag.match(t).hasMatch()) {
        ++stray;
        std::printf("  stray markup: %s\n", qUtf8Printable(tag.match(t).captured(0)));
      }
    check(stray == 0, "no help text holds markup Qt would drop");
    const QString plain = QTextDocumentFragment::fromHtml(texts.join("<br>")).toPlainText();
    check(plain.contains("'<source> onto <target>'") && plain.contains("<mesh name>_picked_points.pp"),
          "the help shows '<source> onto <target>' and '<mesh name>_picked_points.pp' as written");
  }

  for (MeshModel* m : {source, target})
    vcg::tri::Allocator<CMeshO>::DeletePerMeshAttribute(m->cm, PickedPoints::Key);
  delete sp;
  delete tp;
  std::printf("%s\n", failures ? "FAILED" : "PASS");
  return failures ? 1 : 0;
}
