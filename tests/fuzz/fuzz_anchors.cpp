// libFuzzer target: the anchor parsers (PickPoints XML, vertex lists, named points).
#include <cstdint>
#include <string>

#include "cbd/anchors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const cbd::AnchorSet set = cbd::parseAnchors(text, "fuzz");
  // Snapping must cope with whatever parsed: a tiny tetrahedron as the mesh.
  cbd::IndexedMesh m;
  m.positions = {cbd::Vec3(1, 1, 1), cbd::Vec3(1, -1, -1), cbd::Vec3(-1, 1, -1), cbd::Vec3(-1, -1, 1)};
  m.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  std::vector<cbd::SnappedAnchor> out;
  if (set.status) (void)cbd::snapAnchors(m, set, 0.5, "fuzz", out);
  std::vector<int> a, b;
  (void)cbd::matchAnchors(set, set, a, b);
  return 0;
}
