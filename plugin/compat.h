#pragma once
/// @file compat.h
/// The one place in the plugin's source that knows MeshLab's version. CMake sets
/// CBD_MESHLAB_VERSION from the SDK it builds against (202009, 202202 or 202507); everything
/// else in plugin/ is written once, against the names defined here:
///  * the filter base class and the entry points MeshLab calls, whose signatures changed in
///    2022.02 (CBD_FILTER_ENTRY_POINTS forwards them to version-neutral members the plugin
///    implements: filterClass, arity, preconditions, postconditions, requirements, parameters, run);
///  * reading and making parameters (a mesh parameter holds a MeshModel* before 2022.02, a layer
///    id since; a file parameter is a FileValue before, a string since; RichOpenFile is RichFileOpen
///    since 2025.07);
///  * the layers of a document, and how a failure reaches the user (errorMessage and false before
///    2022.02, an MLException since; anything else escaping applyFilter aborts MeshLab 2022+).

#include <string>
#include <vector>

#include <QAction>
#include <QString>
#include <QStringList>

#ifndef CBD_MESHLAB_VERSION
#error "CBD_MESHLAB_VERSION must be set (202009, 202202 or 202507): see plugin/CMakeLists.txt"
#endif

#if CBD_MESHLAB_VERSION >= 202202
#include <map>
#include <QVariant>
#include <common/mlexception.h>
#include <common/ml_document/mesh_document.h>
#include <common/plugins/interfaces/filter_plugin.h>
#else
#include <common/interfaces.h>
#include <common/meshmodel.h>
#endif

namespace cbdplugin {

#if CBD_MESHLAB_VERSION >= 202202
using FilterBase = FilterPlugin;
#define CBD_FILTER_IID FILTER_PLUGIN_IID
#define CBD_FILTER_INTERFACE FilterPlugin
using Arity = FilterPlugin::FilterArity;
using FilterClassType = FilterPlugin::FilterClass;
#else
using FilterBase = MeshFilterInterface;
#define CBD_FILTER_IID MESH_FILTER_INTERFACE_IID
#define CBD_FILTER_INTERFACE MeshFilterInterface
using Arity = MeshFilterInterface::FILTER_ARITY;
using FilterClassType = MeshFilterInterface::FilterClass;
#endif

/// What `run` tells MeshLab: empty on success, else the whole error text.
struct Outcome {
  std::string error;
  bool ok() const { return error.empty(); }
};

#if CBD_MESHLAB_VERSION >= 202202
/// The entry points of MeshLab 2022.02 and later, forwarded to the plugin's own members. A
/// failure becomes the MLException MeshLab shows in its dialog (and PyMeshLab raises).
#define CBD_FILTER_ENTRY_POINTS                                                                            \
 public:                                                                                                   \
  FilterClass getClass(const QAction* a) const override { return filterClass(ID(a)); }                    \
  FilterArity filterArity(const QAction* a) const override { return arity(ID(a)); }                       \
  int getRequirements(const QAction* a) override { return requirements(ID(a)); }                         \
  int getPreConditions(const QAction* a) const override { return preconditions(ID(a)); }                  \
  int postCondition(const QAction* a) const override { return postconditions(ID(a)); }                    \
  RichParameterList initParameterList(const QAction* a, const MeshDocument& md) override {                \
    RichParameterList list;                                                                                \
    parameters(ID(a), md, list);                                                                           \
    return list;                                                                                           \
  }                                                                                                        \
  std::map<std::string, QVariant> applyFilter(const QAction* a, const RichParameterList& par,              \
                                              MeshDocument& md, unsigned int& /*postConditionMask*/,       \
                                              vcg::CallBackPos* cb) override {                             \
    const cbdplugin::Outcome o = run(ID(a), md, par, cb);                                                  \
    if (!o.ok()) throw MLException(QString::fromStdString(o.error));                                       \
    return {};                                                                                             \
  }                                                                                                        \
  void logLine(GLLogStream::Levels level, const std::string& text) { log(level, text); }                  \
                                                                                                           \
 private:
#else
/// The entry points of MeshLab 2020.09, forwarded to the plugin's own members. A failure is
/// errorMessage (the GUI's dialog) and the log (meshlabserver prints the log only).
#define CBD_FILTER_ENTRY_POINTS                                                                            \
 public:                                                                                                   \
  FilterClass getClass(QAction* a) override { return filterClass(ID(a)); }                                \
  FILTER_ARITY filterArity(QAction* a) const override { return arity(ID(a)); }                            \
  int getRequirements(QAction* a) override { return requirements(ID(a)); }                                \
  int getPreConditions(QAction* a) const override { return preconditions(ID(a)); }                        \
  int postCondition(QAction* a) const override { return postconditions(ID(a)); }                          \
  void initParameterSet(QAction* a, MeshDocument& md, RichParameterList& list) override {                 \
    parameters(ID(a), md, list);                                                                           \
  }                                                                                                        \
  bool applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb)      \
      override {                                                                                           \
    errorMessage.clear();                                                                                  \
    const cbdplugin::Outcome o = run(ID(a), md, par, cb);                                                  \
    if (o.ok()) return true;                                                                               \
    errorMessage = QString::fromStdString(o.error);                                                        \
    return false;                                                                                          \
  }                                                                                                        \
  using MeshFilterInterface::filterInfo;                                                                   \
  using MeshFilterInterface::filterName;                                                                   \
  using MeshFilterInterface::initParameterSet;                                                             \
  void logLine(GLLogStream::Levels level, const std::string& text) { Log(level, text); }                  \
                                                                                                           \
 private:
#endif

#if CBD_MESHLAB_VERSION >= 202202
#define CBD_REGISTER_FILTERS(...)                                               \
  do {                                                                          \
    typeList = {__VA_ARGS__};                                                   \
    for (ActionIDType t : types()) actionList.push_back(new QAction(filterName(t), this)); \
  } while (0)
#else
#define CBD_REGISTER_FILTERS(...)                                               \
  do {                                                                          \
    for (int t : {__VA_ARGS__}) typeList << t;                                  \
    for (FilterIDType t : types()) actionList << new QAction(filterName(t), this); \
  } while (0)
#endif

/// The layers of a document, in the order of the layer panel.
inline std::vector<MeshModel*> layers(MeshDocument& md) {
  std::vector<MeshModel*> out;
#if CBD_MESHLAB_VERSION >= 202202
  for (MeshModel& m : md.meshIterator()) out.push_back(&m);
#else
  for (MeshModel* m : md.meshList) out.push_back(m);
#endif
  return out;
}

inline std::vector<const MeshModel*> layers(const MeshDocument& md) {
  std::vector<const MeshModel*> out;
#if CBD_MESHLAB_VERSION >= 202202
  for (const MeshModel& m : md.meshIterator()) out.push_back(&m);
#else
  for (const MeshModel* m : md.meshList) out.push_back(m);
#endif
  return out;
}

/// A layer chooser whose default is `layer` (may be null: the current one).
inline RichMesh meshParameter(const char* name, const MeshModel* layer, const MeshDocument& md, const QString& label,
                              const QString& help) {
#if CBD_MESHLAB_VERSION >= 202202
  return RichMesh(name, layer ? layer->id() : 0u, &md, label, help);
#else
  return RichMesh(name, const_cast<MeshModel*>(layer), const_cast<MeshDocument*>(&md), label, help);
#endif
}

/// A file chooser, empty by default.
#if CBD_MESHLAB_VERSION >= 202507
using RichFileParameter = RichFileOpen;
#else
using RichFileParameter = RichOpenFile;
#endif
inline RichFileParameter fileParameter(const char* name, const QStringList& extensions, const QString& label,
                                       const QString& help) {
  return RichFileParameter(name, QString(), extensions, label, help);
}

/// The parameter `name` when it holds a value of the kind asked for; null (or false) otherwise:
/// a hand-written .mlx may give a parameter the wrong type, and MeshLab's own getters assert.
inline const Value* valueOf(const RichParameterList& par, const char* name) {
  return par.hasParameter(name) ? &par.getParameterByName(name).value() : nullptr;
}

inline MeshModel* layerParameter(const RichParameterList& par, const char* name, MeshDocument& md) {
#if CBD_MESHLAB_VERSION >= 202202
  if (!par.hasParameter(name) || !par.getParameterByName(name).isOfType<RichMesh>()) return nullptr;
  return md.getMesh(par.getMeshId(name));
#else
  (void)md;
  const Value* v = valueOf(par, name);
  return v && v->isMesh() ? v->getMesh() : nullptr;
#endif
}

inline bool fileParameterValue(const RichParameterList& par, const char* name, QString& out) {
  const Value* v = valueOf(par, name);
  if (!v) return false;
#if CBD_MESHLAB_VERSION < 202202
  if (v->isFileName()) return out = v->getFileName(), true;
#endif
  if (v->isString()) return out = v->getString(), true;
  return false;
}

inline bool intParameterValue(const RichParameterList& par, const char* name, int& out) {
  const Value* v = valueOf(par, name);
  if (!v) return false;
#if CBD_MESHLAB_VERSION < 202202
  if (v->isEnum()) return out = v->getEnum(), true;
#endif
  if (v->isInt()) return out = v->getInt(), true;
  return false;
}

inline bool boolParameterValue(const RichParameterList& par, const char* name, bool& out) {
  const Value* v = valueOf(par, name);
  if (!v || !v->isBool()) return false;
  out = v->getBool();
  return true;
}

}  // namespace cbdplugin
