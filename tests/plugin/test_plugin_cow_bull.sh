#!/usr/bin/env bash
# The cbd MeshLab plugin end to end on a real pair (cow -> bull, 28 named anchors, 52 patches),
# through Debian's meshlabserver in a no-root prefix (scripts/meshlab_prefix.sh):
#   1. meshlab_scripts/cross_parameterize.sh succeeds; M_st (mst.ply) has the cow's vertex and
#      face counts and lies on the bull (largest vertex-to-surface distance <= 1e-4 of the bull's
#      bbox diagonal); the saved cow and bull carry the same set of 52 face colours (one per
#      patch, corresponding patches alike);
#   2. meshlab_scripts/voronoi_base_domain.mlx (anchors found as <mesh>_picked_points.pp next to
#      the meshes): the same 52 colours on both layers, two path layers, the report in the log;
#      with "Colour by Voronoi cluster": 28 colours (one per anchor), the same set on both;
#   3. failures: an anchor file that does not exist (the plugin's error text in the log, exit
#      255, nothing saved); anchor names that do not match (the wrapper fails with the plugin's
#      error, no mst.ply); a wrong argument to the wrapper;
#   4. the input files are byte-identical afterwards and nothing was added next to them.
# Usage: tests/plugin/test_plugin_cow_bull.sh BUILD_DIR
#   (BUILD_DIR/plugin/libfilter_cbd.so and BUILD_DIR/plugin/cbd_plugin_check). KEEP_TMP=1 keeps
#   the temporary folder.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
NAME="test_plugin_cow_bull"
fail() { printf '[%s] FAIL: %s\n' "$NAME" "$*" >&2; exit 1; }
info() { printf '[%s] %s\n' "$NAME" "$*"; }

[ $# -eq 1 ] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
BUILD_DIR="$(cd "$1" 2>/dev/null && pwd)" || fail "build folder '$1' does not exist"
PLUGIN_SO="$BUILD_DIR/plugin/libfilter_cbd.so"
CHECK="$BUILD_DIR/plugin/cbd_plugin_check"
[ -f "$PLUGIN_SO" ] || fail "$PLUGIN_SO not found (build the filter_cbd target first)"
[ -x "$CHECK" ] || fail "$CHECK not found (build the cbd_plugin_check target first)"
command -v Xvfb >/dev/null || fail "Xvfb not found (apt-get install xvfb)"
# shellcheck source=../../meshlab_scripts/headless.sh
. "$ROOT/meshlab_scripts/headless.sh"   # cbd_headless: like xvfb-run -a
MESHES="$ROOT/third_party/cgal-data/meshes"
EXAMPLES="$ROOT/examples"
for f in "$MESHES/cow.off" "$MESHES/bull.off" "$EXAMPLES/cow_picked_points.pp" "$EXAMPLES/bull_picked_points.pp"; do
  [ -f "$f" ] || fail "test input $f missing"
done
WRAPPER="$ROOT/meshlab_scripts/cross_parameterize.sh"
VORONOI_MLX="$ROOT/meshlab_scripts/voronoi_base_domain.mlx"
CROSS_MLX="$ROOT/meshlab_scripts/cross_parameterize.mlx"

TMP="$(mktemp -d "${TMPDIR:-/tmp}/cbd_cow_bull.XXXXXX")" || fail "cannot create a temporary folder"
cleanup() { if [ "${KEEP_TMP:-0}" = 1 ]; then info "kept $TMP"; else rm -rf "$TMP"; fi; }
trap cleanup EXIT
PREFIX="$TMP/prefix"
DATA="$TMP/data"   # the inputs; nothing may change here
RUNS="$TMP/runs"
mkdir -p "$DATA" "$RUNS"
export CBD_PLUGIN_SO="$PLUGIN_SO" CBD_MESHLAB_PREFIX="$PREFIX" CBD_MESHLAB=2020

# Inputs, under names that are not PickPoints' (the wrapper must stage them itself).
cp "$MESHES/cow.off" "$MESHES/bull.off" "$DATA/"
cp "$EXAMPLES/cow_picked_points.pp" "$DATA/cow_anchors.pp"
cp "$EXAMPLES/bull_picked_points.pp" "$DATA/bull_anchors.pp"
sed 's/name="chin"/name="jaw"/' "$EXAMPLES/bull_picked_points.pp" >"$DATA/bull_renamed.pp"
grep -q 'name="jaw"' "$DATA/bull_renamed.pp" || fail "could not rename an anchor in the test input"
(cd "$DATA" && sha256sum -- * >"$RUNS/inputs.sha256" && ls -A >"$RUNS/inputs.list")

"$ROOT/scripts/meshlab_prefix.sh" "$PREFIX" "$PLUGIN_SO" >"$RUNS/prefix.log" 2>&1 ||
  { cat "$RUNS/prefix.log" >&2; fail "scripts/meshlab_prefix.sh failed"; }
SERVER="$PREFIX/bin/meshlabserver"

check() {  # plugin_check arguments...
  "$CHECK" "$@" >"$RUNS/check.out" 2>&1
  local rc=$?
  sed "s/^/[$NAME]   /" "$RUNS/check.out"
  [ $rc -eq 0 ] || fail "plugin_check $1 failed"
}

# run_server TAG ARGS... : meshlabserver in RUNS, log first on the command line; sets RC.
run_server() {
  local tag="$1"; shift
  rm -f "$RUNS/$tag.log"
  (cd "$RUNS" && cbd_headless timeout 120 "$SERVER" -l "$RUNS/$tag.log" "$@" >"$RUNS/$tag.out" 2>&1)
  RC=$?
  [ -f "$RUNS/$tag.log" ] || touch "$RUNS/$tag.log"
  cat "$RUNS/$tag.log" "$RUNS/$tag.out" >"$RUNS/$tag.all"
  [ "$RC" -ne 124 ] || fail "$tag: meshlabserver timed out"
  if [ "$RC" -ge 128 ] && [ "$RC" -ne 255 ]; then tail -20 "$RUNS/$tag.all" >&2; fail "$tag: meshlabserver crashed (exit $RC)"; fi
}
expect() {  # file fixed-string what
  grep -qF -- "$2" "$1" || { tail -30 "$1" >&2; fail "$3 (no line containing '$2' in $1)"; }
}

# --- 1. The wrapper: Cross-parameterize cow onto bull.
OUT="$TMP/out"
"$WRAPPER" "$DATA/cow.off" "$DATA/cow_anchors.pp" "$DATA/bull.off" "$DATA/bull_anchors.pp" "$OUT" \
  >"$RUNS/wrapper.out" 2>&1 || { cat "$RUNS/wrapper.out" >&2; fail "cross_parameterize.sh failed"; }
for f in source_patches.ply target_patches.ply mst.ply meshlab.log; do
  [ -s "$OUT/$f" ] || fail "cross_parameterize.sh did not write $f"
done
T="cbd: Cross-parameterize: "
expect "$OUT/meshlab.log" "${T}28 anchors matched by name" "anchors not matched"
expect "$OUT/meshlab.log" "${T}layout voronoi: " "no layout report"
expect "$OUT/meshlab.log" "${T}map E_ang " "no distortion report"
expect "$OUT/meshlab.log" "${T}time voronoi " "no timings"
# The summary comes first: the plugin's first line gives the distortion and the new layer.
first=$(grep -m1 -F "$T" "$OUT/meshlab.log")
case "$first" in
  *"${T}'cow' onto 'bull': E_ang "*" flipped triangle"*"; new layer 'cow onto bull' (M_st)"*) ;;
  *) fail "the first line of the plugin's log is not the summary: $first" ;;
esac
expect "$OUT/meshlab.log" "${T}new layer 'cow onto bull' (M_st): 2904 vertices" "no M_st layer"
check mst "$OUT/mst.ply" "$DATA/bull.off" 2904 1e-4
check counts "$OUT/mst.ply" 2904 5804
check counts "$OUT/source_patches.ply" 2904 5804
check counts "$OUT/target_patches.ply" 6200 12396
check colours "$OUT/source_patches.ply" "$OUT/target_patches.ply" 52
info "ok: cross_parameterize.sh: M_st on the bull, 52 shared patch colours"

# --- 2. Voronoi common base domain with the shipped script; anchors by PickPoints' naming.
VOR="$TMP/vor"
mkdir -p "$VOR"
cp "$DATA/cow.off" "$DATA/bull.off" "$VOR/"
cp "$DATA/cow_anchors.pp" "$VOR/cow_picked_points.pp"
cp "$DATA/bull_anchors.pp" "$VOR/bull_picked_points.pp"
run_server voronoi -i "$VOR/cow.off" "$VOR/bull.off" -s "$VORONOI_MLX" \
  -o "$RUNS/vor_cow.ply" -l 0 -m fc -o "$RUNS/vor_bull.ply" -l 1 -m fc -o "$RUNS/vor_cow_paths.ply" -l 2
[ "$RC" -eq 0 ] || { tail -30 "$RUNS/voronoi.all" >&2; fail "voronoi: meshlabserver exited $RC"; }
T="cbd: Voronoi common base domain: "
expect "$RUNS/voronoi.all" "${T}28 anchors matched by name (source: file '$VOR/cow_picked_points.pp', target: file '$VOR/bull_picked_points.pp')" "anchors not found next to the meshes"
expect "$RUNS/voronoi.all" "${T}78 paths, 52 patches on 'cow' and 'bull'" "no summary"
expect "$RUNS/voronoi.all" "${T}layout voronoi: 78 edges (" "no layout report"
expect "$RUNS/voronoi.all" "${T}time voronoi " "no timings"
expect "$RUNS/voronoi.all" "${T}new layers 'cow base domain' and 'bull base domain'" "no path layers"
expect "$RUNS/voronoi.all" "saved as $RUNS/vor_cow_paths.ply" "path layer not saved"
check colours "$RUNS/vor_cow.ply" "$RUNS/vor_bull.ply" 52
sed 's/value="false" name="ColourByCluster"/value="true" name="ColourByCluster"/' "$VORONOI_MLX" >"$RUNS/clusters.mlx"
grep -q 'value="true" name="ColourByCluster"' "$RUNS/clusters.mlx" || fail "could not switch on ColourByCluster"
run_server clusters -i "$VOR/cow.off" "$VOR/bull.off" -s "$RUNS/clusters.mlx" \
  -o "$RUNS/cl_cow.ply" -l 0 -m fc -o "$RUNS/cl_bull.ply" -l 1 -m fc
[ "$RC" -eq 0 ] || { tail -30 "$RUNS/clusters.all" >&2; fail "clusters: meshlabserver exited $RC"; }
expect "$RUNS/clusters.all" "coloured per face by Voronoi cluster (28 / 28 colours" "not coloured by cluster"
check colours "$RUNS/cl_cow.ply" "$RUNS/cl_bull.ply" 28
info "ok: voronoi_base_domain.mlx: 52 shared patch colours, 28 shared cluster colours, path layers"

# --- 3. Failures.
# An anchor file that does not exist: the plugin's message in the log, the script fails, no output.
sed "s|value=\"\" name=\"SourceAnchors\"|value=\"$DATA/no_such.pp\" name=\"SourceAnchors\"|" "$CROSS_MLX" >"$RUNS/missing.mlx"
run_server missing -i "$DATA/cow.off" "$DATA/bull.off" -s "$RUNS/missing.mlx" -o "$RUNS/missing_cow.ply" -l 0 -m fc
[ "$RC" -ne 0 ] || fail "missing: meshlabserver exited 0 although the filter must fail"
expect "$RUNS/missing.all" "cbd: Cross-parameterize: cannot read anchor file '$DATA/no_such.pp': no such file (check the path) [file_not_found]" "error text not in the log"
[ ! -e "$RUNS/missing_cow.ply" ] || fail "missing: a layer was saved after the failed filter"
info "ok: missing anchor file: exit $RC, error in the log, nothing saved"

# Anchor names that do not match: the wrapper fails with the plugin's message, writes no M_st.
OUT2="$TMP/out_mismatch"
"$WRAPPER" "$DATA/cow.off" "$DATA/cow_anchors.pp" "$DATA/bull.off" "$DATA/bull_renamed.pp" "$OUT2" \
  >"$RUNS/mismatch.out" 2>&1
RC=$?
[ "$RC" -eq 1 ] || { cat "$RUNS/mismatch.out" >&2; fail "mismatch: cross_parameterize.sh exited $RC (expected 1)"; }
expect "$RUNS/mismatch.out" "[anchor_name_mismatch]" "the wrapper did not report the plugin's error"
expect "$RUNS/mismatch.out" "chin" "the error does not name the unmatched anchor"
expect "$OUT2/meshlab.log" "[anchor_name_mismatch]" "the error is not in the MeshLab log"
[ ! -e "$OUT2/mst.ply" ] || fail "mismatch: mst.ply written after a failure"
info "ok: mismatched anchor names: $(grep -F '[anchor_name_mismatch]' "$RUNS/mismatch.out" | head -1 | cut -c1-160)"

# A wrong argument to the wrapper.
"$WRAPPER" "$DATA/cow.off" "$DATA/nothing.pp" "$DATA/bull.off" "$DATA/bull_anchors.pp" "$TMP/out_bad" >"$RUNS/bad.out" 2>&1
RC=$?
[ "$RC" -eq 2 ] || { cat "$RUNS/bad.out" >&2; fail "bad argument: cross_parameterize.sh exited $RC (expected 2)"; }
expect "$RUNS/bad.out" "input file '$DATA/nothing.pp' does not exist" "no message about the missing input"
info "ok: wrapper argument errors (exit 2)"

# --- 4. Inputs untouched.
(cd "$DATA" && sha256sum --quiet -c "$RUNS/inputs.sha256") >"$RUNS/sha.out" 2>&1 ||
  { cat "$RUNS/sha.out" >&2; fail "input files changed"; }
(cd "$DATA" && ls -A) | cmp -s - "$RUNS/inputs.list" || fail "files were added or removed next to the inputs: $(cd "$DATA" && ls -A | tr '\n' ' ')"
info "ok: input files byte-identical, nothing added next to them"
info "PASS"
