#pragma once
/// @file anchor_sampling.h
/// Farthest-point sampling of anchors by geodesic (edge-graph) distance: evenly spread anchor
/// sets for tests, benchmarks and stress runs.

#include <vector>

#include "cbd/mesh.h"

namespace cbd {

/// `count` vertices, the first `seed`, each next one the vertex farthest (along mesh edges)
/// from those already chosen; ties go to the lower index. Unreferenced vertices are never
/// chosen. Returns fewer when the mesh has fewer referenced vertices.
std::vector<int> farthestPointSampling(const IndexedMesh& mesh, int count, int seed = 0);

}  // namespace cbd
