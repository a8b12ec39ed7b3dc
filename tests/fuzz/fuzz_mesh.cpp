// libFuzzer target: the mesh loaders (OFF/COFF, OBJ, STL, PLY by the first byte) and the
// validation that follows every load.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "cbd/validate_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* ext[] = {".off", ".obj", ".stl", ".ply"};
  const std::string path = "/tmp/cbd_fuzz_mesh_" + std::to_string(getpid()) + ext[data[0] % 4];
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  cbd::Mesh mesh;
  const cbd::LoadResult r = cbd::loadMesh(path, mesh);
  if (r.status) {
    const cbd::IndexedMesh m = cbd::toIndexed(mesh);
    (void)cbd::validateMesh(m, "fuzz", r.hadPolygons);
  }
  std::remove(path.c_str());
  return 0;
}
