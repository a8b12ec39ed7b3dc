#pragma once
/// @file filter_cbd.h
/// The cbd filter plugin for MeshLab (2020.09, 2022.02, 2025.07 from this one source; compat.h
/// holds what differs): "Voronoi common base domain" and "Cross-parameterize", under Filters >
/// Remeshing, Simplification and Reconstruction. As thin as MeshLab's own filters: parameters in
/// (two layers, their anchors), one core call (cbd::buildLayouts / cbd::crossParameterize),
/// layers out (layers.h), and the core's report (cbd/report.h) in the log, its summary first.
/// On failure nothing is modified and the error names the problem and the fix; no exception
/// reaches MeshLab.

#include <string>

#include <QObject>

#include "compat.h"

class FilterCbdPlugin : public QObject, public cbdplugin::FilterBase {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(CBD_FILTER_IID)
  Q_INTERFACES(CBD_FILTER_INTERFACE)
  CBD_FILTER_ENTRY_POINTS

 public:
  enum { FP_VORONOI_BASE_DOMAIN, FP_CROSS_PARAMETERIZE };

  FilterCbdPlugin();
  ~FilterCbdPlugin() override;

  QString pluginName() const override;
  QString filterName(int filter) const override;
  QString filterInfo(int filter) const override;

 private:
  cbdplugin::FilterClassType filterClass(int filter) const;
  cbdplugin::Arity arity(int filter) const;
  int requirements(int filter) const;
  int preconditions(int filter) const;
  int postconditions(int filter) const;
  void parameters(int filter, const MeshDocument& md, RichParameterList& list);
  /// The filter; every exception is caught and turned into the outcome's error.
  cbdplugin::Outcome run(int filter, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
  cbdplugin::Outcome apply(int filter, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
};
