#pragma once
// Random-anchor stress runs on synthetic pairs of genus 0, 1 and 2 with a known deformation:
// shared by the capped test (tests/test_robustness.cpp) and the full run (cbd_bench stress).

#include <string>
#include <vector>

#include "cbd/pipeline.h"

namespace cbd::stress {

/// A source surface and a deformed, re-triangulated target with the known correspondence of
/// vertices (`targetOf`: the target vertex matching each source vertex).
struct SyntheticPair {
  std::string name;
  int genus = 0;
  IndexedMesh source, target;
  std::vector<int> targetOf;
};

/// The pair for genus 0 (sphere -> bumpy ellipsoid), 1 (torus -> twisted bumpy torus) or
/// 2 (holed plate -> bent plate).
SyntheticPair makePair(int genus);

/// One random anchor set: `count` anchors by farthest-point sampling from a random seed
/// (`farthest`) or uniformly at random, from a seeded generator.
std::vector<int> randomAnchors(const IndexedMesh& mesh, int count, unsigned seed, bool farthest);

/// What one stress run gave.
struct Outcome {
  bool ok = false;
  ErrorCode code = ErrorCode::Ok;
  std::string message;
  int flipped = 0;
  bool invariantsHold = false;  ///< both layouts valid and isomorphic, images on the target
};

/// Run the Voronoi method (or `method`) on one anchor set and check every invariant.
Outcome run(const SyntheticPair& pair, const std::vector<int>& sourceAnchors, LayoutMethod method = LayoutMethod::Voronoi);

}  // namespace cbd::stress
