#!/usr/bin/env bash
# Scripted runs of the cbd plugin with MeshLab 2025.07, where meshlabserver no longer exists:
# meshlab_scripts/cross_parameterize.sh through cbd-meshlab-run (CBD_MESHLAB=2025) on the
# bundled pair (cow -> bull, 28 anchors):
#   1. M_st (mst.ply) has the cow's counts and lies on the bull; the saved cow and bull share
#      the same 52 face colours; the log starts with the summary;
#   2. voronoi_base_domain.mlx through cbd-meshlab-run: 52 shared colours, a path layer saved;
#   3. anchor names that do not match: the wrapper fails with the plugin's error, no mst.ply;
#   4. the inputs are byte-identical afterwards.
# Usage: tests/plugin/test_plugin_2025_scripts.sh BUILD_DIR   (KEEP_TMP=1 keeps the temporary folder)
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
NAME="test_plugin_2025_scripts"
fail() { printf '[%s] FAIL: %s\n' "$NAME" "$*" >&2; exit 1; }
info() { printf '[%s] %s\n' "$NAME" "$*"; }
[ $# -eq 1 ] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
BUILD_DIR="$(cd "$1" 2>/dev/null && pwd)" || fail "build folder '$1' does not exist"
RUNNER="$BUILD_DIR/plugin-2025/cbd-meshlab-run"
CHECK="$BUILD_DIR/plugin/cbd_plugin_check"
[ -x "$RUNNER" ] || fail "$RUNNER not found (scripts/meshlab_2025.sh, then build)"
[ -x "$CHECK" ] || fail "$CHECK not found"
MESHES="$ROOT/third_party/cgal-data/meshes"
EXAMPLES="$ROOT/examples"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/cbd_2025.XXXXXX")" || fail "cannot create a temporary folder"
cleanup() { if [ "${KEEP_TMP:-0}" = 1 ]; then info "kept $TMP"; else rm -rf "$TMP"; fi; }
trap cleanup EXIT
DATA="$TMP/data"
mkdir -p "$DATA"
cp "$MESHES/cow.off" "$MESHES/bull.off" "$DATA/"
cp "$EXAMPLES/cow_picked_points.pp" "$DATA/cow_anchors.pp"
cp "$EXAMPLES/bull_picked_points.pp" "$DATA/bull_anchors.pp"
sed 's/name="chin"/name="jaw"/' "$EXAMPLES/bull_picked_points.pp" >"$DATA/bull_renamed.pp"
(cd "$DATA" && sha256sum -- * >"$TMP/inputs.sha256")
export CBD_MESHLAB=2025 CBD_MESHLAB_RUN="$RUNNER"
check() { "$CHECK" "$@" || fail "cbd_plugin_check $*"; }

# 1. The wrapper.
OUT="$TMP/out"
"$ROOT/meshlab_scripts/cross_parameterize.sh" "$DATA/cow.off" "$DATA/cow_anchors.pp" "$DATA/bull.off" \
  "$DATA/bull_anchors.pp" "$OUT" >"$TMP/wrapper.out" 2>&1 || { cat "$TMP/wrapper.out" >&2; fail "cross_parameterize.sh failed"; }
grep -q "MeshLab 2025.07" "$TMP/wrapper.out" || fail "the wrapper did not use MeshLab 2025.07: $(cat "$TMP/wrapper.out")"
check mst "$OUT/mst.ply" "$DATA/bull.off" 2904 1e-4
check counts "$OUT/source_patches.ply" 2904 5804
check colours "$OUT/source_patches.ply" "$OUT/target_patches.ply" 52
first=$(grep -m1 "^cbd: Cross-parameterize: " "$OUT/meshlab.log")
case "$first" in
  "cbd: Cross-parameterize: 'cow' onto 'bull': E_ang "*"; new layer 'cow onto bull' (M_st)") ;;
  *) fail "the log does not start with the summary: $first" ;;
esac
info "ok: cross_parameterize.sh with MeshLab 2025.07: M_st on the bull, 52 shared patch colours"

# 2. The Voronoi filter script, anchors as <mesh>_picked_points.pp beside the meshes.
VOR="$TMP/vor"
mkdir -p "$VOR"
cp "$DATA/cow.off" "$DATA/bull.off" "$VOR/"
cp "$DATA/cow_anchors.pp" "$VOR/cow_picked_points.pp"
cp "$DATA/bull_anchors.pp" "$VOR/bull_picked_points.pp"
"$RUNNER" "$ROOT/meshlab_scripts/voronoi_base_domain.mlx" "$VOR/cow.off" "$VOR/bull.off" \
  -o "$TMP/vor_cow.ply" "$TMP/vor_bull.ply" "$TMP/vor_cow_paths.ply" >"$TMP/vor.out" 2>&1 ||
  { tail -20 "$TMP/vor.out" >&2; fail "cbd-meshlab-run voronoi_base_domain.mlx failed"; }
grep -q "saved layer 2 'cow base domain'" "$TMP/vor.out" || fail "the path layer was not saved: $(tail -3 "$TMP/vor.out")"
check colours "$TMP/vor_cow.ply" "$TMP/vor_bull.ply" 52
[ "$(grep -a -m1 '^element edge' "$TMP/vor_cow_paths.ply" | awk '{print $3}')" -gt 0 ] 2>/dev/null ||
  fail "the saved path layer has no edges"
info "ok: cbd-meshlab-run voronoi_base_domain.mlx: 52 shared colours, the path layer saved with its edges"

# 3. Anchor names that do not match.
OUT2="$TMP/out2"
if "$ROOT/meshlab_scripts/cross_parameterize.sh" "$DATA/cow.off" "$DATA/cow_anchors.pp" "$DATA/bull.off" \
     "$DATA/bull_renamed.pp" "$OUT2" >"$TMP/mismatch.out" 2>&1; then
  fail "the wrapper succeeded with anchors that do not match"
fi
grep -qF "[anchor_name_mismatch]" "$TMP/mismatch.out" || fail "no anchor_name_mismatch error: $(tail -3 "$TMP/mismatch.out")"
[ ! -e "$OUT2/mst.ply" ] || fail "mst.ply written although the filter failed"
info "ok: mismatched anchors: $(grep -F '[anchor_name_mismatch]' "$TMP/mismatch.out" | head -1 | cut -c1-150)"

# 4. The inputs.
(cd "$DATA" && sha256sum -c --quiet "$TMP/inputs.sha256") || fail "an input file changed"
info "ok: inputs unchanged"
