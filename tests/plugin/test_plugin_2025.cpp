/// @file test_plugin_2025.cpp
/// The cbd plugin in a real MeshLab 2025.07: loaded by MeshLab's PluginManager from a plugin
/// folder (with io_base and edit_pickpoints), meshes opened by io_base, anchors attached as
/// PickPoints leaves them (the per-mesh attribute "PickedPoints"), filters applied as the GUI
/// applies them:
///   1. "Cross-parameterize": M_st has the source's vertex count, lies in a new current layer,
///      both input layers share one colour per patch, the progress bar moves through the stages,
///      the log starts with the summary;
///   2. "Voronoi common base domain" by Voronoi cluster: one colour per anchor on both layers, two
///      path layers;
///   3. anchors that do not match: an MLException with the error, and no layer changed;
///   4. help texts hold no markup Qt would drop.
/// Usage: test_plugin_2025 PLUGIN_DIR SOURCE.off SOURCE.pp TARGET.off TARGET.pp PATCHES

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <QApplication>
#include <QDir>
#include <QRegularExpression>
#include <QTextDocumentFragment>

#include <common/GLLogStream.h>
#include <common/mlexception.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include "pickedPoints.h"

namespace {

int failures = 0;
void check(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

std::vector<std::pair<int, std::string>> progressSeen;
bool recordProgress(const int percent, const char* text) {
  progressSeen.emplace_back(percent, text ? text : "");
  return true;
}

PickedPoints* pick(MeshModel& m, const char* ppFile, const QString& rename = QString()) {
  PickedPoints file;
  if (!file.open(ppFile)) {
    std::fprintf(stderr, "cannot read %s\n", ppFile);
    std::exit(2);
  }
  auto* pp = new PickedPoints();
  bool renamed = false;
  for (const PickedPoint* p : file.getPickedPointVector()) {
    const bool swap = !rename.isEmpty() && !renamed;
    pp->addPoint(swap ? rename : p->name, p->point, p->present);
    renamed = renamed || swap;
  }
  vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<PickedPoints*>(m.cm, PickedPoints::Key)() = pp;
  return pp;
}

std::set<std::array<int, 3>> faceColours(const MeshModel& m) {
  std::set<std::array<int, 3>> s;
  if (!m.hasDataMask(MeshModel::MM_FACECOLOR)) return s;
  for (const CFaceO& f : m.cm.face)
    if (!f.IsD()) s.insert({f.cC()[0], f.cC()[1], f.cC()[2]});
  return s;
}

std::vector<MeshModel*> layers(MeshDocument& md) {
  std::vector<MeshModel*> v;
  for (MeshModel& m : md.meshIterator()) v.push_back(&m);
  return v;
}

bool logHas(const GLLogStream& log, const QString& text) {
  for (const auto& line : log.logStringList())
    if (line.second.contains(text)) return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s PLUGIN_DIR SOURCE.off SOURCE.pp TARGET.off TARGET.pp PATCHES\n", argv[0]);
    return 2;
  }
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  const int patches = std::atoi(argv[6]);
  std::printf("MeshLab %s\n", meshlab::meshlabCompleteVersion().c_str());

  PluginManager& pm = meshlab::pluginManagerInstance();
  try {
    pm.loadPlugins(QDir(QString::fromLocal8Bit(argv[1])));
  } catch (const MLException& e) {
    check(false, std::string("PluginManager loaded every plugin: ") + e.what());
  }
  QAction* cross = pm.filterAction("Cross-parameterize");
  QAction* voronoi = pm.filterAction("Voronoi common base domain");
  FilterPlugin* filter = cross ? pm.getFilterPluginFromAction(cross) : nullptr;
  check(filter && voronoi && pm.inputMeshPlugin("off"), "PluginManager has both cbd filters and io_base");
  if (!filter || !voronoi || !pm.inputMeshPlugin("off")) return 1;

  MeshDocument md;
  GLLogStream& log = md.Log;
  filter->setLog(&log);
  MeshModel* source = meshlab::loadMeshWithStandardParameters(argv[2], md).front();
  MeshModel* target = meshlab::loadMeshWithStandardParameters(argv[4], md).front();
  const int sourceVertices = source->cm.vn;
  PickedPoints* sp = pick(*source, argv[3]);
  PickedPoints* tp = pick(*target, argv[5]);
  auto params = [&](QAction* a) {
    RichParameterList par = filter->initParameterList(a, md);
    par.setValue("SourceMesh", IntValue(source->id()));
    par.setValue("TargetMesh", IntValue(target->id()));
    return par;
  };
  auto apply = [&](QAction* a, const RichParameterList& par, std::string& error) {
    unsigned int mask = MeshModel::MM_UNKNOWN;
    try {
      filter->applyFilter(a, par, md, mask, recordProgress);
      return true;
    } catch (const MLException& e) {
      error = e.what();
      return false;
    }
  };

  // 1. Cross-parameterize.
  {
    progressSeen.clear();
    std::string error;
    const bool ok = apply(cross, params(cross), error);
    check(ok, "Cross-parameterize succeeds with anchors from PickPoints " + error);
    const std::vector<MeshModel*> all = layers(md);
    MeshModel* mst = all.size() == 3 ? all[2] : nullptr;
    check(mst && mst->cm.vn == sourceVertices && mst->cm.fn == source->cm.fn &&
              mst->hasDataMask(MeshModel::MM_FACEQUALITY) && md.mm() == mst,
          "M_st: a new current layer with the source's vertex and face counts and face quality");
    const auto sc = faceColours(*source), tc = faceColours(*target);
    check(sc == tc && static_cast<int>(sc.size()) == patches,
          "both layers coloured by patch, same colour set: " + std::to_string(sc.size()) + " colours");
    std::set<int> middle;
    for (const auto& [percent, text] : progressSeen)
      if (percent > 25 && percent < 95 && !text.empty()) middle.insert(percent);
    check(middle.size() >= 10 && !progressSeen.empty() && progressSeen.back().first == 100,
          "the progress bar moves past 25 % in " + std::to_string(middle.size()) + " steps, with stage names");
    check(!log.logStringList().empty() &&
              log.logStringList().front().second.contains("E_ang ") &&
              log.logStringList().front().second.contains("new layer '" + (mst ? mst->label() : QString()) + "' (M_st)"),
          "the log starts with the summary, naming the new layer");
  }

  // 2. Voronoi common base domain by cluster.
  log.clear();
  {
    RichParameterList par = params(voronoi);
    par.setValue("ColourByCluster", BoolValue(true));
    const size_t before = layers(md).size();
    std::string error;
    check(apply(voronoi, par, error), "Voronoi common base domain succeeds " + error);
    const int anchors = static_cast<int>(sp->getPickedPointVector().size());
    const auto sc = faceColours(*source), tc = faceColours(*target);
    check(sc == tc && static_cast<int>(sc.size()) == anchors,
          "both layers coloured by Voronoi cluster: " + std::to_string(sc.size()) + " colours");
    const std::vector<MeshModel*> all = layers(md);
    check(all.size() == before + 2 && all[before]->cm.en > 0 && all[before + 1]->cm.en > 0 && all[before]->cm.fn == 0,
          "two new path layers (edge meshes)");
  }

  // 3. Anchors that do not match: the error, and nothing changed.
  {
    vcg::tri::Allocator<CMeshO>::DeletePerMeshAttribute(target->cm, PickedPoints::Key);
    delete tp;
    tp = pick(*target, argv[5], "not_on_the_source");
    const size_t before = layers(md).size();
    const auto sc = faceColours(*source), tc = faceColours(*target);
    std::string error;
    const bool ok = apply(cross, params(cross), error);
    check(!ok && error.find("1 target-only") != std::string::npos && error.find("[anchor_name_mismatch]") != std::string::npos,
          "anchors that do not match: MLException '" + error + "'");
    check(layers(md).size() == before && faceColours(*source) == sc && faceColours(*target) == tc,
          "no layer added or recoloured");
    check(logHas(log, "[anchor_name_mismatch]"), "the error is in the log");
  }

  // 4. Help texts.
  {
    QStringList texts;
    for (QAction* a : {cross, voronoi}) {
      texts << filter->filterInfo(a);
      for (const RichParameter& p : filter->initParameterList(a, md)) texts << p.fieldDescription() << p.toolTip();
    }
    const QRegularExpression tag("<(?!/?(b|i|br|sub)>)[^>]*>");
    int stray = 0;
    for (const QString& t : texts) stray += tag.match(t).hasMatch();
    check(stray == 0, "no help text holds markup Qt would drop");
    const QString plain = QTextDocumentFragment::fromHtml(texts.join("<br>")).toPlainText();
    check(plain.contains("'<source> onto <target>'") && plain.contains("<mesh name>_picked_points.pp"),
          "the help shows '<source> onto <target>' and '<mesh name>_picked_points.pp' as written");
  }

  for (MeshModel* m : {source, target}) vcg::tri::Allocator<CMeshO>::DeletePerMeshAttribute(m->cm, PickedPoints::Key);
  delete sp;
  delete tp;
  std::printf("%s\n", failures ? "FAILED" : "PASS");
  return failures ? 1 : 0;
}
