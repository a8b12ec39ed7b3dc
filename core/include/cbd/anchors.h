#pragma once
/// @file anchors.h
/// Corresponding anchor points: reading MeshLab PickPoints `.pp` files, vertex-index lists
/// (SHREC `.vts` style) and `name x y z` text; writing `.pp`; snapping to mesh vertices;
/// matching source and target anchors by name.

#include <string>
#include <vector>

#include "cbd/mesh.h"
#include "cbd/status.h"

namespace cbd {

/// How an anchor file is written.
enum class AnchorFormat {
  PickedPoints,  ///< MeshLab PickPoints XML: <point x= y= z= name= active=/>
  VertexList,    ///< one `index [x y z]` per line (0-based index); names are the line ordinals 1, 2, ...
  NamedPoints    ///< one `name x y z` per line
};

/// One anchor as read from a file.
struct Anchor {
  std::string name;
  Vec3 position = Vec3::Zero();  ///< the given point (for VertexList: the coordinates when given)
  bool hasPosition = false;      ///< false for a VertexList line with the index only
  int vertex = -1;               ///< the given vertex index (VertexList only)
  int line = 0;                  ///< 1-based line in the file, for messages
};

/// The anchors of one file.
struct AnchorSet {
  Status status;
  std::string source;            ///< file path (or a label) for messages
  AnchorFormat format = AnchorFormat::NamedPoints;
  std::vector<Anchor> anchors;   ///< active anchors in file order
  int skippedInactive = 0;       ///< PickPoints points with active="0"
};

/// Read an anchor file; the format is detected from the content (XML -> PickedPoints; lines
/// starting with an integer -> VertexList; otherwise NamedPoints). Errors: FileNotFound,
/// MalformedAnchors (with the line number), DuplicateAnchorName.
AnchorSet readAnchors(const std::string& path);

/// Parse anchor text already in memory; `label` names it in messages.
AnchorSet parseAnchors(const std::string& text, const std::string& label);

/// Write a MeshLab PickPoints file (all points active) that MeshLab's PickPoints tool opens.
/// @param[in] dataFileName the mesh file the points belong to (stored in DocumentData).
Status writePickedPoints(const std::string& path, const std::vector<Anchor>& anchors,
                         const std::string& dataFileName);

/// An anchor placed on a mesh vertex.
struct SnappedAnchor {
  std::string name;
  int vertex = -1;            ///< the mesh vertex it stands on
  double snapDistance = 0.0;  ///< |given point - vertex| / bbox diagonal (0 for index-only anchors)
};

/// Snap every anchor to its nearest referenced vertex (VertexList: the given index).
/// Errors: AnchorIndexOutOfRange, AnchorOffSurface (snap distance above `tolerance` of the
/// bbox diagonal), AnchorsShareVertex. `meshName` appears in messages.
Status snapAnchors(const IndexedMesh& mesh, const AnchorSet& anchors, double tolerance,
                   const std::string& meshName, std::vector<SnappedAnchor>& out);

/// Source and target anchors matched by name, in the source file's order.
struct AnchorPairs {
  std::vector<std::string> names;
  std::vector<SnappedAnchor> source, target;  ///< same length and order as `names`
  int size() const { return static_cast<int>(names.size()); }
};

/// Match two anchor sets by name. Errors: AnchorNameMismatch (a name on one side only, the
/// first such name and the count in the message), DuplicateAnchorName, TooFewAnchors (a set
/// whose points are all inactive, `skippedInactive`, said as such).
/// On success `sourceIndex[k]`/`targetIndex[k]` are the positions of pair k in each set.
Status matchAnchors(const AnchorSet& source, const AnchorSet& target, std::vector<int>& sourceIndex,
                    std::vector<int>& targetIndex);

}  // namespace cbd
