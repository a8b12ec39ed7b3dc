#pragma once
/// @file layout_io.h
/// Writing layouts for viewing in MeshLab: the refined mesh coloured per patch, the paths as an
/// edge mesh, the Voronoi clusters coloured per face. Patch k gets the same colour on every
/// surface, so corresponding patches of a source and a target layout match.

#include <string>
#include <vector>

#include "cbd/layout.h"

namespace cbd {

/// The files `writeLayout` writes into its folder.
inline constexpr const char* kLayoutFile = "layout.ply";
inline constexpr const char* kPathsFile = "paths.ply";
inline constexpr const char* kClustersFile = "clusters.ply";
/// The subfolders a pair's two layouts are written into (by `cbd layout` and `cbd map`).
inline constexpr const char* kSourceLayoutFolder = "source";
inline constexpr const char* kTargetLayoutFolder = "target";

/// A well-separated colour for index k (golden-ratio hues), as 8-bit RGB.
std::array<unsigned char, 3> paletteColor(int k);

/// Write `dir/layout.ply` (refined mesh, per-face colour by patch, face quality = patch index),
/// `dir/paths.ply` (every layout edge as a polyline; vertex quality = layout edge index) and,
/// when `layout.faceCluster` is not empty, `dir/clusters.ply` (per-face colour by cluster; else an
/// earlier run's clusters.ply there is removed, so the folder holds one layout). The folder is
/// created when missing. Errors: OutputError.
Status writeLayout(const Layout& layout, const std::string& dir);

}  // namespace cbd
