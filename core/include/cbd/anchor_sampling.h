#pragma once
/// @file anchor_sampling.h
/// Farthest-point sampling of anchors by geodesic (edge-graph) distance: evenly spread anchor
/// sets for tests, benchmarks and stress runs.

#include <vector>

#include "cbd/mesh.h"

namespace cbd {

/// `count` vertices, the first `seed`, each next one the vertex farthest (along mesh edges)
/// from those already chosen; ties go to the lower index. Unreferenced vertices are never
/// chosen: a `seed` that is out of range or unreferenced is replaced by the first referenced
/// vertex (front ends refuse such a seed instead). Returns fewer when the mesh has fewer
/// referenced vertices.
std::vector<int> farthestPointSampling(const IndexedMesh& mesh, int count, int seed = 0);

}  // namespace cbd
