#!/usr/bin/env bash
# The benchmark, from scratch, in one command: builds, then runs on this machine
#   1. the comparison table (paper's Table 2): every pair of bench/manifest.txt with the greedy
#      baseline and the Voronoi method in its E1 (one edge node) and C (adaptive) settings;
#      greedy and C also with two more polish vertex orders (the spread of the final numbers),
#      and with 1, 4 and 8 rounds of path straightening besides the default 2 (sensitivity);
#      and where on the source their maps differ (per-anchor regions); and greedy without its
#      path flipping, Voronoi C with it; and every pair again with the source's vertices and
#      faces renumbered, with each map stage (bench/renumber.sh);
#   2. scaling: layout time against anchors (on diplodocus) and against mesh size (the cow
#      subdivided 1-to-4), both methods, next to one full Dijkstra sweep of the edge-node graph;
#   3. random-anchor stress on synthetic genus 0/1/2 pairs;
#   4. plots (gnuplot) and renders (cbd_render), and bench/README.md with every number from
#      this run.
# Usage: bench/run.sh [--quick]   (--quick: fewer scaling points and stress sets, one polish order, no straightening sensitivity, no regions, no path flipping, no renumbering)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"
QUICK=0
if [ "${1:-}" = "--quick" ]; then QUICK=1; shift; fi
cbd_args 0 "$@"
"$ROOT/scripts/setup.sh" >/dev/null
"$ROOT/scripts/build.sh" "$ROOT/build" >/dev/null
B="$ROOT/build/bench/cbd_bench"
R="$ROOT/build/bench/render/cbd_render"
OUT="$ROOT/bench/results"
mkdir -p "$OUT"
MESHES="$ROOT/third_party/cgal-data/meshes"

"$B" defaults "$OUT"   # the settings the report names, as this build has them

echo "== table"
if [ "$QUICK" = 1 ]; then ORDERS=1; else ORDERS=3; fi
"$B" table "$ROOT" "$ROOT/bench/manifest.txt" "$OUT" "$ORDERS" | tee "$OUT/table.log"

if [ "$QUICK" = 0 ]; then
  echo "== sensitivity to the straightening"
  "$B" sensitivity "$ROOT" "$ROOT/bench/manifest.txt" "$OUT" 1,4,8 | tee "$OUT/sensitivity.log"
else
  rm -f "$OUT/sensitivity.csv"  # not this run's: the report must not mix runs
fi

if [ "$QUICK" = 0 ]; then
  echo "== where on the source the two methods' maps differ"
  "$B" regions "$ROOT" "$ROOT/bench/manifest.txt" "$OUT" | tee "$OUT/regions.log"
else
  rm -f "$OUT/regions.csv"
fi

if [ "$QUICK" = 0 ]; then
  echo "== path flipping for each method"
  "$B" flipping "$ROOT" "$ROOT/bench/manifest.txt" "$OUT" | tee "$OUT/flipping.log"
else
  rm -f "$OUT/flipping.csv"
fi

if [ "$QUICK" = 0 ]; then
  echo "== the source renumbered"
  bash "$ROOT/bench/renumber.sh" "$OUT" | tee "$OUT/renumber_untangle.log"
  bash "$ROOT/bench/renumber.sh" "$OUT" -- --map-stage optimize | tee "$OUT/renumber_optimize.log"
else
  rm -f "$OUT"/renumber_*.csv
fi

echo "== scaling"
if [ "$QUICK" = 1 ]; then COUNTS=8,16,32; LEVELS=2; else COUNTS=8,16,32,64,128; LEVELS=3; fi
"$B" scaling "$MESHES/diplodocus.off" "$OUT/scaling_anchors" 0 "$COUNTS" | tee "$OUT/scaling_anchors.log"
"$B" scaling "$MESHES/cow.off" "$OUT/scaling_size" "$LEVELS" 32 | tee "$OUT/scaling_size.log"

echo "== stress"
if [ "$QUICK" = 1 ]; then SETS=2; else SETS=5; fi
"$B" stress "$OUT" "$SETS" 4,8,16,32,64,150 | tee "$OUT/stress.log"

echo "== plots and renders"
python3 "$ROOT/bench/report.py" "$ROOT" "$OUT"
for dir in "$OUT"/plots/*.gp; do gnuplot "$dir"; done
if [ -x "$R" ]; then
  "$ROOT/build/cli/cbd" map --source "$MESHES/bull.off" --source-anchors "$ROOT/examples/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$ROOT/examples/cow_picked_points.pp" --out "$OUT/render_voronoi" >/dev/null
  "$ROOT/build/cli/cbd" map --source "$MESHES/bull.off" --source-anchors "$ROOT/examples/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$ROOT/examples/cow_picked_points.pp" --method greedy \
    --out "$OUT/render_greedy" >/dev/null
  for m in voronoi greedy; do
    "$R" --out "$OUT/plots/layout_$m.png" --size 1280x420 --flip --title "$m: base domains on the cow (target) and M_st" \
      --lines "$OUT/render_$m/target/paths.ply" "$OUT/render_$m/target/layout.ply" "$OUT/render_$m/mst.ply"
  done
fi
# Into place only when complete: a report that refuses its data leaves the old page as it was.
python3 "$ROOT/bench/report.py" "$ROOT" "$OUT" --readme > "$OUT/README.md.tmp"
mv "$OUT/README.md.tmp" "$ROOT/bench/README.md"
echo "wrote $ROOT/bench/README.md, $OUT/*.csv, $OUT/plots/*.png"
