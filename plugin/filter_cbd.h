#pragma once
/// @file filter_cbd.h
/// MeshLab 2020.09 filter plugin of cbd: "Voronoi common base domain" and "Cross-parameterize"
/// (Filters > Remeshing, Simplification and Reconstruction). A thin adapter: it copies two
/// layers into cbd::IndexedMesh, gathers their anchors (PickPoints attribute or .pp files),
/// runs cbd::validateInput, logs a report and hands over to runPipeline (cbd_pipeline.h), which
/// colours the input layers per face and adds result layers, only once every stage succeeded.
/// On failure nothing is modified; no exception ever reaches MeshLab.

#include <string>

#include <QObject>

#include <common/interfaces.h>

class FilterCbdPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_VORONOI_BASE_DOMAIN, FP_CROSS_PARAMETERIZE };

  FilterCbdPlugin();
  ~FilterCbdPlugin() override;

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int getRequirements(QAction* action) override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& par) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                   vcg::CallBackPos* cb) override;

  // Bring the base-class overloads back into scope (hidden by the overrides above).
  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;
  using MeshFilterInterface::initParameterSet;

 private:
  /// The body of applyFilter; may throw (applyFilter catches everything).
  bool apply(int filter, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
  /// Set errorMessage and log the same text; returns false.
  bool fail(const std::string& text);
  void logLine(const std::string& text);
};
