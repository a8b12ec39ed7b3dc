#pragma once
/// @file layers.h
/// MeshLab layers in and out of cbd's core: a layer as a cbd::IndexedMesh (and where each of its
/// elements came from), a layer's anchors (PickPoints or a file), and the result layers (face
/// colours of the inputs, the layout paths as edge meshes, M_st). Results are computed into plain
/// structs first and written into the document only after every stage succeeded.

#include <string>
#include <vector>

#include <QString>

#include "cbd/anchors.h"
#include "cbd/mesh.h"
#include "cbd/pipeline.h"
#include "compat.h"

namespace cbdplugin {

/// The name the layer panel shows: the label without its extension ("bull" for "bull.off").
QString panelName(const MeshModel& layer);
/// A layer's name for the labels of derived layers: the panel name without dots (MeshLab's panel
/// would cut "bull.off onto cow" at the last dot).
QString stem(const MeshModel& layer);

/// Where the compact mesh's elements are in the layer: `vertex[i]` / `face[i]` is the position in
/// `cm.vert` / `cm.face` of compact vertex / face i (deleted elements skipped).
struct LayerIndex {
  std::vector<int> vertex;
  std::vector<int> face;
};

/// A compact double-precision copy of a layer (deleted elements skipped, vertices renumbered in
/// order). MalformedMesh when a face refers to a deleted or foreign vertex. The layer is only read.
cbd::Status toIndexed(const MeshModel& layer, cbd::IndexedMesh& out, LayerIndex& where, int& deletedVertices);

/// A layer's anchors and where they came from ("PickPoints of layer 'cow'", "file '...'").
struct GatheredAnchors {
  cbd::AnchorSet set;
  std::string origin;
};
/// In this order: the explicit file when given; else the layer's PickPoints points (the per-mesh
/// attribute "PickedPoints"); else `<mesh name>_picked_points.pp` next to the layer's file.
GatheredAnchors gatherAnchors(MeshModel& layer, const QString& explicitPath, const std::string& role);

/// The layout paths as an edge mesh: every layout edge a polyline of its own, vertex colour =
/// paletteColor(edge), vertex quality = edge index.
struct PathLayer {
  std::vector<cbd::Vec3> positions;
  std::vector<std::array<unsigned char, 3>> colours;
  std::vector<int> edgeOfVertex;
  std::vector<std::array<int, 2>> segments;
};
PathLayer pathLayer(const cbd::Layout& layout);

/// M_st: the source's triangles at the images of its vertices on the target; face quality = L2
/// stretch with its colour ramp; the target's vertex colour and quality, when it has them,
/// interpolated at the images.
struct MstLayer {
  std::vector<cbd::Vec3> positions;
  std::vector<std::array<int, 3>> faces;
  std::vector<double> faceQuality;
  std::vector<std::array<unsigned char, 3>> faceColours;
  bool hasVertexColour = false, hasVertexQuality = false;
  std::vector<std::array<unsigned char, 4>> vertexColours;
  std::vector<float> vertexQuality;
};
MstLayer mstLayer(const cbd::IndexedMesh& source, const cbd::CrossParameterizationResult& result,
                  const MeshModel& targetLayer, const cbd::IndexedMesh& target, const LayerIndex& targetIndex);

// --- writing into the document (nothing can fail here but memory)

/// Per-face colours by label (patch or cluster; paletteColor, grey for -1).
void colourFaces(MeshModel& layer, const LayerIndex& index, const std::vector<int>& labels);
/// New layers; MeshLab may make the label unique ("bull onto cow(1)"): read it back from the layer.
MeshModel* addPathLayer(MeshDocument& md, const QString& label, const PathLayer& paths);
MeshModel* addMstLayer(MeshDocument& md, const QString& label, const MstLayer& mst);

}  // namespace cbdplugin
