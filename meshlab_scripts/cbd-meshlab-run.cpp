/// @file cbd-meshlab-run.cpp
/// A headless runner of MeshLab filter scripts for MeshLab 2022.02 and later, where meshlabserver
/// no longer exists: what meshlabserver did for meshlab_scripts/*.sh, built on MeshLab 2025.07's
/// own libraries (PluginManager, the io plugins, FilterScript), so the filters run exactly as in
/// the GUI's "Filters > Apply filter script".
///
/// Usage: cbd-meshlab-run [--plugins DIR] SCRIPT.mlx INPUT... -o OUTPUT...
///   INPUT k becomes layer k (MeshLab's io plugins read it); when <mesh name>_picked_points.pp
///   lies next to it, its points become the layer's PickPoints anchors, as Edit > PickPoints
///   would load them. Each filter of SCRIPT.mlx is then applied in order (a RichMesh value is a
///   layer's position); OUTPUT k receives layer k with its vertex and face colours and qualities
///   ("-": not saved). DIR: the plugin folder (default: plugins/ beside this program, else the
///   installed MeshLab's). Exit status 0: every filter ran and every output was written; 1: a
///   filter failed or a file could not be read or written (the reason is printed); 2: bad usage.

#include <clocale>
#include <cstdio>
#include <string>
#include <vector>

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QLocale>

#include <common/GLLogStream.h>
#include <common/filterscript.h>
#include <common/globals.h>
#include <common/mlexception.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>
#include <wrap/io_trimesh/io_mask.h>

#include "pickedPoints.h"

namespace {

int usage(const char* why) {
  if (why) std::fprintf(stderr, "cbd-meshlab-run: %s\n", why);
  std::fprintf(stderr,
               "Usage: cbd-meshlab-run [--plugins DIR] SCRIPT.mlx INPUT... -o OUTPUT...\n"
               "  Opens each INPUT as a layer (with <mesh name>_picked_points.pp next to it as its PickPoints\n"
               "  anchors), applies the filters of SCRIPT.mlx in order, and saves layer k to OUTPUT k\n"
               "  ('-': not saved) with its colours and qualities. MeshLab %s.\n",
               meshlab::meshlabVersion().c_str());
  return why ? 2 : 0;
}

void printLog(GLLogStream& log) {
  for (const auto& line : log.logStringList()) std::printf("%s\n", qUtf8Printable(line.second));
  log.clear();
}

/// The layer's attributes MeshLab can write in that format: colours and qualities per vertex and
/// face, and edges (the path layers: io_base does not list edges among PLY's capabilities, but
/// vcglib's PLY exporter, which it calls, writes them).
int saveMask(const MeshModel& m, const QString& format, int capability) {
  if (format == "ply") capability |= vcg::tri::io::Mask::IOM_EDGEINDEX;
  namespace io = vcg::tri::io;
  int mask = 0;
  if (m.hasDataMask(MeshModel::MM_VERTCOLOR)) mask |= io::Mask::IOM_VERTCOLOR;
  if (m.hasDataMask(MeshModel::MM_VERTQUALITY)) mask |= io::Mask::IOM_VERTQUALITY;
  if (m.hasDataMask(MeshModel::MM_FACECOLOR)) mask |= io::Mask::IOM_FACECOLOR;
  if (m.hasDataMask(MeshModel::MM_FACEQUALITY)) mask |= io::Mask::IOM_FACEQUALITY;
  if (m.cm.en > 0) mask |= io::Mask::IOM_EDGEINDEX;
  return mask & capability;
}

}  // namespace

int main(int argc, char** argv) {
  QString plugins, script;
  std::vector<QString> inputs, outputs;
  bool toOutputs = false;
  for (int i = 1; i < argc; ++i) {
    const QString a = QString::fromLocal8Bit(argv[i]);
    if (a == "-h" || a == "--help") return usage(nullptr);
    if (a == "--plugins") {
      if (++i >= argc) return usage("--plugins needs a folder");
      plugins = QString::fromLocal8Bit(argv[i]);
    } else if (a == "-o") {
      toOutputs = true;
    } else if (a.startsWith("-") && a != "-") {
      return usage(("unknown option " + a.toStdString()).c_str());
    } else if (script.isEmpty()) {
      script = a;
    } else {
      (toOutputs ? outputs : inputs).push_back(a);
    }
  }
  if (script.isEmpty() || inputs.empty()) return usage("a filter script and at least one input are needed");
  if (outputs.size() > inputs.size() + 8) return usage("more outputs than layers a script can make");

  // Plugins create QActions and icons: a QApplication must exist; no display is needed.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  std::setlocale(LC_ALL, "C");  // as MeshLab's main(): numbers in files with '.'
  QLocale::setDefault(QLocale::C);

  PluginManager& pm = meshlab::pluginManagerInstance();
  if (plugins.isEmpty()) {
    const QString beside = QCoreApplication::applicationDirPath() + "/plugins";
    plugins = QDir(beside).exists() ? beside : QCoreApplication::applicationDirPath();
  }
  try {
    pm.loadPlugins(QDir(plugins));
  } catch (const MLException& e) {  // after loading the others, lists the ones that failed
    std::fprintf(stderr, "cbd-meshlab-run: warning: %s\n", e.what());
  }

  MeshDocument md;
  GLLogStream& log = md.Log;
  for (const QString& in : inputs) {
    try {
      const std::list<MeshModel*> loaded = meshlab::loadMeshWithStandardParameters(in, md);
      for (MeshModel* m : loaded) {
        const QString pp = QFileInfo(in).absolutePath() + "/" + PickedPoints::getSuggestedPickedPointsFileName(*m);
        if (!QFileInfo(pp).isFile()) continue;
        PickedPoints file;
        if (!file.open(pp)) {
          std::fprintf(stderr, "cbd-meshlab-run: cannot read the picked points '%s'\n", qUtf8Printable(pp));
          return 1;
        }
        auto* points = new PickedPoints();  // owned by the layer, as Edit > PickPoints leaves it
        for (const PickedPoint* p : file.getPickedPointVector()) points->addPoint(p->name, p->point, p->present);
        vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<PickedPoints*>(m->cm, PickedPoints::Key)() = points;
        std::printf("layer %d '%s': %zu picked points from %s\n", m->id(), qUtf8Printable(m->label()),
                    points->getPickedPointVector().size(), qUtf8Printable(pp));
      }
    } catch (const MLException& e) {
      std::fprintf(stderr, "cbd-meshlab-run: cannot open '%s': %s\n", qUtf8Printable(in), e.what());
      return 1;
    }
  }

  FilterScript steps;
  if (!steps.open(script)) {
    std::fprintf(stderr, "cbd-meshlab-run: cannot read the filter script '%s'\n", qUtf8Printable(script));
    return 1;
  }
  for (FilterNameParameterValuesPair& step : steps) {
    QAction* action = pm.filterAction(step.filterName());
    FilterPlugin* filter = action ? pm.getFilterPluginFromAction(action) : nullptr;
    if (filter == nullptr) {
      std::fprintf(stderr, "cbd-meshlab-run: no filter named '%s' in %s\n", qUtf8Printable(step.filterName()),
                   qUtf8Printable(plugins));
      return 1;
    }
    std::printf("filter: %s\n", qUtf8Printable(step.filterName()));
    filter->setLog(&log);
    if (md.mm()) md.mm()->updateDataMask(filter->getRequirements(action));
    unsigned int postCondition = MeshModel::MM_UNKNOWN;
    try {
      filter->applyFilter(action, step.second, md, postCondition, nullptr);
      printLog(log);
    } catch (const MLException& e) {
      printLog(log);
      std::fprintf(stderr, "cbd-meshlab-run: filter '%s' failed: %s\n", qUtf8Printable(step.filterName()), e.what());
      return 1;
    }
  }

  std::vector<MeshModel*> layers;
  for (MeshModel& m : md.meshIterator()) layers.push_back(&m);
  for (size_t k = 0; k < outputs.size(); ++k) {
    if (outputs[k] == "-") continue;
    if (k >= layers.size()) {
      std::fprintf(stderr, "cbd-meshlab-run: no layer %zu to save as '%s' (%zu layers)\n", k, qUtf8Printable(outputs[k]),
                   layers.size());
      return 1;
    }
    const QString ext = QFileInfo(outputs[k]).suffix().toLower();
    IOPlugin* io = pm.outputMeshPlugin(ext);
    if (io == nullptr) {
      std::fprintf(stderr, "cbd-meshlab-run: no plugin saves .%s files\n", qUtf8Printable(ext));
      return 1;
    }
    int capability = 0, defaults = 0;
    io->exportMaskCapability(ext, capability, defaults);
    try {
      io->setLog(&log);
      io->save(ext, outputs[k], *layers[k], saveMask(*layers[k], ext, capability), io->initSaveParameter(ext, *layers[k]));
    } catch (const MLException& e) {
      std::fprintf(stderr, "cbd-meshlab-run: cannot save layer %zu as '%s': %s\n", k, qUtf8Printable(outputs[k]), e.what());
      return 1;
    }
    if (!QFileInfo(outputs[k]).isFile()) {
      std::fprintf(stderr, "cbd-meshlab-run: layer %zu was not saved as '%s'\n", k, qUtf8Printable(outputs[k]));
      return 1;
    }
    std::printf("saved layer %zu '%s' as %s\n", k, qUtf8Printable(layers[k]->label()), qUtf8Printable(outputs[k]));
  }
  return 0;
}
