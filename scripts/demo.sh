#!/usr/bin/env bash
# Set everything up, build, and run the main job on the bundled example: the cross-
# parameterization of the bull onto the cow (Debian's libcgal-demo) with the anchors in examples/.
# Usage: scripts/demo.sh [OUT_DIR]   (default: out/bull_cow)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 1 "$@"
OUT="${1:-$ROOT/out/bull_cow}"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/build.sh" "$ROOT/build"
MESHES="$ROOT/third_party/cgal-data/meshes"
mkdir -p "$OUT"
set -x
"$ROOT/build/cli/cbd" check \
  --source "$MESHES/cow.off" --source-anchors "$ROOT/examples/cow_picked_points.pp" \
  --target "$MESHES/bull.off" --target-anchors "$ROOT/examples/bull_picked_points.pp" \
  --json "$OUT/check.json"
"$ROOT/build/cli/cbd" map \
  --source "$MESHES/bull.off" --source-anchors "$ROOT/examples/bull_picked_points.pp" \
  --target "$MESHES/cow.off" --target-anchors "$ROOT/examples/cow_picked_points.pp" \
  --out "$OUT" --morph 5 --json "$OUT/map.json"
{ set +x; } 2>/dev/null
echo "metrics and timings: $OUT/map.json"
echo "open in MeshLab: $OUT/mst.ply (the bull's mesh on the cow; face quality = stretch),"
echo "  $OUT/morph_000.ply ... morph_004.ply (bull -> cow), $OUT/source/layout.ply and $OUT/target/layout.ply"
echo "  (corresponding patches in the same colour), paths.ply and clusters.ply beside them"
