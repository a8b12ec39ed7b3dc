#pragma once
/// @file cbd_pipeline.h
/// The one place where the MeshLab plugin hands validated input to the cbd algorithm stages
/// (cbd::buildLayouts / cbd::crossParameterize) and turns their results into MeshLab layers.
/// Everything before this call (layer conversion, anchor gathering, validation, logging) is in
/// filter_cbd.cpp.

#include <functional>
#include <string>
#include <vector>

#include "cbd/layout.h"
#include "cbd/path_straightening.h"
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
  /// "Straighten paths (rounds)" (Cross-parameterize only; the layout filter shows paths as traced)
  int straightenRounds = cbd::PathStraighteningOptions{}.rounds;
  bool colourByCluster = false;  ///< "Colour by Voronoi cluster" (Voronoi common base domain only)
  bool colourByPatch = true;     ///< "Colour layers by patch" (Cross-parameterize; always on for Voronoi)
  bool addMstLayer = true;       ///< "Add M_st layer" (Cross-parameterize)
  bool addPathLayers = true;     ///< "Add path layers" (Cross-parameterize; always on for Voronoi)
};

/// Where the compact cbd::IndexedMesh elements are in the layer: `vertex[i]` / `face[i]` is the
/// position in `cm.vert` / `cm.face` of compact vertex / face i (deleted elements skipped).
struct LayerIndex {
  std::vector<int> vertex;
  std::vector<int> face;
};

/// Everything the pipeline gets. On failure nothing is modified; on success the input layers
/// get per-face colours (MM_FACECOLOR) and new layers are appended to `document`.
struct PipelineRequest {
  FilterKind filter;
  std::string filterName;            ///< e.g. "Voronoi common base domain"
  const cbd::IndexedMesh& source;    ///< compact copy of the source layer (double precision)
  const cbd::IndexedMesh& target;
  const LayerIndex& sourceIndex;
  const LayerIndex& targetIndex;
  const cbd::InputReport& report;    ///< validateInput's result; report.status is ok here
  PipelineOptions options;
  MeshDocument& document;
  MeshModel& sourceLayer;
  MeshModel& targetLayer;
  std::function<void(const std::string&)> log;  ///< one line into MeshLab's log
};

/// Run the algorithm stages and write the results into the document. Return success, or an
/// error whose message is the complete text the caller puts into MeshLab's error dialog and log
/// verbatim (it starts with "cbd: <filter name>: "). May throw: the caller catches everything.
/// @param[in] cb MeshLab's progress callback (may be null); called as cb(percent, "text").
cbd::Status runPipeline(const PipelineRequest& request, vcg::CallBackPos* cb);

}  // namespace cbdplugin
