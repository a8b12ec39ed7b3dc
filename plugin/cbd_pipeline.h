#pragma once
/// @file cbd_pipeline.h
/// The one place where the MeshLab plugin hands validated input to the cbd algorithm stages.
/// Everything before this call (layer conversion, anchor gathering, validation, logging) is in
/// filter_cbd.cpp; swap the body of `runPipeline` (cbd_pipeline.cpp) for the real pipeline.

#include <functional>
#include <string>

#include "cbd/mesh.h"
#include "cbd/status.h"
#include "cbd/validate_input.h"

#include <wrap/callback.h>  // vcg::CallBackPos: bool (const int percent, const char* text)

class MeshDocument;
class MeshModel;


namespace cbdplugin {

/// Which filter the user ran.
enum class FilterKind { VoronoiBaseDomain, CrossParameterize };

/// How the base-domain edges are traced (the "Method" parameter, in this order).
enum class LayoutMethod { Voronoi = 0, GreedyShortestPaths = 1 };

/// The filter parameters other than the layers and the anchor files.
struct PipelineOptions {
  LayoutMethod method = LayoutMethod::Voronoi;
  int minEdgeNodes = 3;          ///< "Minimum edge nodes"
  bool adaptiveEdgeNodes = true; ///< "Adaptive edge nodes"
  int smoothingIterations = 0;   ///< "Smoothing iterations" (Cross-parameterize only; 0 otherwise)
};

/// Everything the pipeline gets. The input layers must not be modified: results go into new
/// layers of `document` (e.g. `document.addNewMesh("", label, false)`).
struct PipelineRequest {
  FilterKind filter;
  std::string filterName;            ///< e.g. "Voronoi common base domain"
  const cbd::IndexedMesh& source;    ///< compact copy of the source layer (double precision)
  const cbd::IndexedMesh& target;
  const cbd::InputReport& report;    ///< validateInput's result; report.status is ok here
  PipelineOptions options;
  MeshDocument& document;
  const MeshModel& sourceLayer;
  const MeshModel& targetLayer;
  std::function<void(const std::string&)> log;  ///< one line into MeshLab's log
};

/// Run the algorithm stages. Return success, or an error whose message is the complete text the
/// caller puts into MeshLab's error dialog and log verbatim (start it with "cbd: <filter name>").
/// May throw: the caller catches everything.
/// @param[in] cb MeshLab's progress callback (may be null); call as cb(percent, "text").
cbd::Status runPipeline(const PipelineRequest& request, vcg::CallBackPos* cb);

}  // namespace cbdplugin
