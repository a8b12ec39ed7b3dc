#pragma once
/// @file map_io.h
/// Outputs of a cross-parameterization: M_st / M_ts as meshes (with per-face stretch and the
/// other surface's attributes transferred through the map), the per-vertex correspondence as
/// text, and a morph sequence.

#include <array>
#include <string>
#include <vector>

#include "cbd/mesh.h"
#include "cbd/parameterization.h"

namespace cbd {

/// The files a cross-parameterization's output folder holds (the CLI's `map`): M_st, M_ts, the
/// correspondence, and the morph frames `kMorphPrefix` + three digits + ".ply" (`writeMorph`).
inline constexpr const char* kMstFile = "mst.ply";
inline constexpr const char* kMtsFile = "mts.ply";
inline constexpr const char* kCorrespondenceFile = "correspondence.txt";
inline constexpr const char* kMorphPrefix = "morph_";
/// The name of morph frame k: "morph_000.ply", ...
std::string morphFileName(int k);

/// The colour of a stretch value: blue (compressed, <= 1/2) - white (1) - red (stretched, >= 2),
/// on a log scale; grey for NaN. Used for mst.ply and by the plugin.
std::array<unsigned char, 3> stretchColor(double stretch);

/// Per-vertex values of a mesh (up to four channels: a colour, a quality, texture coordinates).
using VertexValues = std::vector<Eigen::Vector4d>;

/// `values` (one per vertex of the mesh whose faces are `faces`) at each of `points`: the
/// barycentric blend of the three values of the point's face; `outside` for a point with face -1.
/// How M_st gets the target's colours, and M_ts the source's (here and in the plugin).
VertexValues interpolateAtPoints(const std::vector<std::array<int, 3>>& faces, const std::vector<FacePoint>& points,
                                 const VertexValues& values, const Eigen::Vector4d& outside = Eigen::Vector4d::Zero());

/// A colour channel in 0..255 from a blended value.
unsigned char colorByte(double value);

/// Which attributes of the mesh the image lies on are transferred to the mapped mesh.
struct TransferOptions {
  bool vertexColor = false;
  bool vertexQuality = false;
  bool vertexTexCoord = false;
};

/// M_st: the connectivity of `from` with every vertex at its image, per-face quality = stretch
/// (and a blue-white-red face colour for it, 1 = white), plus the chosen per-vertex attributes of
/// `onto` interpolated at the images (`points`, faces of `onto`). `from` is copied, not changed.
void buildMappedMesh(const Mesh& from, const std::vector<Vec3>& image, const std::vector<FacePoint>& points,
                     const Mesh& onto, const TransferOptions& transfer, const std::vector<double>& faceStretch,
                     Mesh& out);

/// Write the correspondence: one line per vertex of the source, `vertex face b0 b1 b2 x y z`
/// (unreferenced vertices: face -1, zeros, their own position). OutputError on failure.
Status writeCorrespondence(const std::string& path, const std::vector<FacePoint>& points,
                           const std::vector<Vec3>& image);

/// Write `count` meshes `dir/morph_000.ply` ... blending `from` (t = 0) into its image (t = 1)
/// linearly, as in the paper's Fig. 10-11. `from` is first moved onto the image by the
/// similarity (rotation, uniform scale, translation) that best fits its anchors onto theirs
/// (Umeyama 1991), so models posed in different frames blend without collapsing. Frames
/// `count`, `count + 1`, ... of an earlier, longer sequence in `dir` are removed (their number in
/// `staleRemoved`), so the folder holds one sequence. OutputError on failure.
Status writeMorph(const std::string& dir, const Mesh& from, const std::vector<Vec3>& image,
                  const std::vector<int>& anchors, int count, int* staleRemoved = nullptr);

/// The frames `count`, `count + 1`, ... of an earlier, longer morph sequence in `dir`: the
/// regular files `morphFileName(k)` up to the first k without one. writeMorph removes them.
std::vector<std::string> staleMorphFrames(const std::string& dir, int count);

}  // namespace cbd
