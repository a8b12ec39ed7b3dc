#!/usr/bin/env bash
# Set everything up, build, and run the main job on the bundled example:
# the cow and bull from Debian's libcgal-demo with the anchors in examples/.
# Usage: scripts/demo.sh [OUT_DIR]   (default: out/cow_bull)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/out/cow_bull}"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/build.sh" "$ROOT/build"
MESHES="$ROOT/third_party/cgal-data/meshes"
mkdir -p "$OUT"
set -x
"$ROOT/build/cli/cbd" check \
  --source "$MESHES/cow.off" --source-anchors "$ROOT/examples/cow_picked_points.pp" \
  --target "$MESHES/bull.off" --target-anchors "$ROOT/examples/bull_picked_points.pp" \
  --json "$OUT/check.json"
"$ROOT/build/cli/cbd" layout \
  --source "$MESHES/cow.off" --source-anchors "$ROOT/examples/cow_picked_points.pp" \
  --out "$OUT/source" --json "$OUT/source_layout.json"
{ set +x; } 2>/dev/null
echo "reports: $OUT/check.json, $OUT/source_layout.json"
echo "open in MeshLab: $OUT/source/layout.ply (patches), $OUT/source/paths.ply, $OUT/source/clusters.ply"
