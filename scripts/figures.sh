#!/usr/bin/env bash
# Regenerate the README figure docs/bull_cow_layouts.png from the demo's outputs:
# the bull's and the cow's layouts seen from the same flank (corresponding patches share
# colours) and M_st (the bull's mesh on the cow, coloured by stretch).
# Usage: scripts/figures.sh   (runs scripts/demo.sh first when its outputs are missing)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 0 "$@"
OUT="$ROOT/out/bull_cow"
[ -f "$OUT/mst.ply" ] || "$ROOT/scripts/demo.sh" "$OUT"
R="$ROOT/build/bench/render/cbd_render"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$R" --out "$tmp/a.png" --size 640x420 --lines "$OUT/source/paths.ply" "$OUT/source/layout.ply"
"$R" --out "$tmp/b.png" --size 640x420 --flip --lines "$OUT/target/paths.ply" "$OUT/target/layout.ply"
"$R" --out "$tmp/c.png" --size 640x420 --flip "$OUT/mst.ply"
mkdir -p "$ROOT/docs"
convert "$tmp/a.png" "$tmp/b.png" "$tmp/c.png" +append "$ROOT/docs/bull_cow_layouts.png"
echo "wrote $ROOT/docs/bull_cow_layouts.png"
