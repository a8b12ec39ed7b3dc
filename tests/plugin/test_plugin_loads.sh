#!/usr/bin/env bash
# Checks that Debian's MeshLab 2020.09 loads the cbd plugin and runs its filters, through a
# no-root prefix (scripts/meshlab_prefix.sh) and meshlabserver on a private Xvfb (meshlab_scripts/headless.sh):
#   1. `meshlabserver -d FILE` (dump of every registered filter) lists both cbd filters;
#   2. a .mlx calling "Voronoi common base domain" on two subdivided octahedra (anchors from the
#      <mesh>_picked_points.pp files next to the meshes) logs the cbd report;
#   3. the same for "Cross-parameterize" with explicit anchor file parameters;
#   4. a missing anchor file: the error text is in meshlabserver's log, the script fails;
#   5. no anchors at all / an open surface: cbd's validation errors, naming the layer;
#   6. the input files are byte-identical afterwards and no file was added next to them.
# Usage: tests/plugin/test_plugin_loads.sh BUILD_DIR   (BUILD_DIR/plugin/libfilter_cbd.so)
# Set KEEP_TMP=1 to keep the temporary folder for inspection.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
NAME="test_plugin_loads"
fail() { printf '[%s] FAIL: %s\n' "$NAME" "$*" >&2; exit 1; }
info() { printf '[%s] %s\n' "$NAME" "$*"; }

[ $# -eq 1 ] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
BUILD_DIR="$(cd "$1" 2>/dev/null && pwd)" || fail "build folder '$1' does not exist"
PLUGIN_SO="$BUILD_DIR/plugin/libfilter_cbd.so"
[ -f "$PLUGIN_SO" ] || fail "$PLUGIN_SO not found (build the filter_cbd target first)"
command -v Xvfb >/dev/null || fail "Xvfb not found (apt-get install xvfb)"
# shellcheck source=../../meshlab_scripts/headless.sh
. "$ROOT/meshlab_scripts/headless.sh"   # cbd_headless: like xvfb-run -a
command -v sha256sum >/dev/null || fail "sha256sum not found"

TMP="$(mktemp -d "${TMPDIR:-/tmp}/cbd_plugin_test.XXXXXX")" || fail "cannot create a temporary folder"
cleanup() { if [ "${KEEP_TMP:-0}" = 1 ]; then info "kept $TMP"; else rm -rf "$TMP"; fi; }
trap cleanup EXIT
PREFIX="$TMP/prefix"
DATA="$TMP/data"      # the inputs; nothing else is written here
RUNS="$TMP/runs"      # scripts and logs
mkdir -p "$DATA" "$RUNS"

"$ROOT/scripts/meshlab_prefix.sh" "$PREFIX" "$PLUGIN_SO" >"$RUNS/prefix.log" 2>&1 ||
  { cat "$RUNS/prefix.log" >&2; fail "scripts/meshlab_prefix.sh failed"; }
SERVER="$PREFIX/bin/meshlabserver"
[ -x "$SERVER" ] || fail "$SERVER missing after meshlab_prefix.sh"
[ -f "$PREFIX/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_cbd.so" ] || fail "plugin not installed in the prefix"

# --- inputs: an octahedron and a scaled, shifted copy, each with 4 named anchors on vertices.
write_octahedron() {  # file scale dx : an octahedron, each face split into 16 (66 vertices, 128 faces)
  python3 - "$1" "$2" "$3" <<'PY'
import sys
path, s, d = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
for _ in range(2):  # midpoint subdivision: the 6 original vertices stay where they are
    mid, G = {}, []
    def m(a, b):
        k = (min(a, b), max(a, b))
        if k not in mid:
            mid[k] = len(V)
            V.append(tuple((x + y) / 2 for x, y in zip(V[a], V[b])))
        return mid[k]
    for a, b, c in F:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        G += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    F = G
with open(path, "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
    for x, y, z in V:
        f.write("%.9g %.9g %.9g\n" % (x * s + d, y * s, z * s))
    for t in F:
        f.write("3 %d %d %d\n" % t)
PY
}
write_pp() {  # file meshname scale dx
  local f="$1" m="$2" s="$3" d="$4"
  {
    echo '<!DOCTYPE PickedPoints>'
    echo '<PickedPoints>'
    echo ' <DocumentData>'
    echo "  <DataFileName name=\"$m\"/>"
    echo '  <templateName name=""/>'
    echo ' </DocumentData>'
    awk -v s="$s" -v d="$d" 'BEGIN {
      split("nose:1 0 0|top:0 0 1|left:0 1 0|bottom:0 0 -1", p, "|");
      for (i = 1; i <= 4; i++) { split(p[i], nc, ":"); split(nc[2], c, " ");
        printf " <point x=\"%g\" y=\"%g\" z=\"%g\" active=\"1\" name=\"%s\"/>\n", c[1]*s + d, c[2]*s, c[3]*s, nc[1] } }'
    echo '</PickedPoints>'
  } >"$f"
}
write_octahedron "$DATA/octa.off" 1 0
write_octahedron "$DATA/big.off" 2 5
write_pp "$DATA/octa_picked_points.pp" octa.off 1 0
write_pp "$DATA/big_picked_points.pp" big.off 2 5
write_octahedron "$DATA/lonely.off" 1 0                # no lonely_picked_points.pp
head -n 195 "$DATA/octa.off" | sed '2s/^66 128 0$/66 127 0/' >"$DATA/open.off"   # one face missing
cp "$DATA/octa_picked_points.pp" "$DATA/open_picked_points.pp"
cp "$DATA/octa_picked_points.pp" "$DATA/source_anchors.pp"
cp "$DATA/big_picked_points.pp" "$DATA/target_anchors.pp"
(cd "$DATA" && sha256sum -- * >"$RUNS/inputs.sha256" && ls -A >"$RUNS/inputs.list")

# --- .mlx writer: every parameter of the filter must be present (else meshlabserver asserts).
write_mlx() {  # file filter source_anchors target_anchors [smoothing]
  local f="$1" filter="$2" sa="$3" ta="$4" smooth="${5:-}"
  {
    echo '<!DOCTYPE FilterScript>'
    echo '<FilterScript>'
    echo " <filter name=\"$filter\">"
    echo '  <Param type="RichMesh" value="0" name="SourceMesh"/>'
    echo '  <Param type="RichMesh" value="1" name="TargetMesh"/>'
    echo "  <Param type=\"RichOpenFile\" value=\"$sa\" name=\"SourceAnchors\" exts_cardinality=\"0\"/>"
    echo "  <Param type=\"RichString\" value=\"$ta\" name=\"TargetAnchors\"/>"
    echo '  <Param type="RichEnum" value="0" name="Method" enum_cardinality="2" enum_val0="Voronoi" enum_val1="Greedy shortest paths"/>'
    echo '  <Param type="RichInt" value="3" name="MinEdgeNodes"/>'
    echo '  <Param type="RichBool" value="true" name="AdaptiveEdgeNodes"/>'
    if [ -n "$smooth" ]; then
      echo '  <Param type="RichInt" value="2" name="StraightenRounds"/>'
      echo "  <Param type=\"RichInt\" value=\"$smooth\" name=\"SmoothingIterations\"/>"
      echo '  <Param type="RichBool" value="true" name="AddMstLayer"/>'
      echo '  <Param type="RichBool" value="true" name="ColourByPatch"/>'
      echo '  <Param type="RichBool" value="false" name="AddPathLayers"/>'
    else
      echo '  <Param type="RichBool" value="false" name="ColourByCluster"/>'
    fi
    echo ' </filter>'
    echo '</FilterScript>'
  } >"$f"
}

# run_server TAG ARGS... : runs meshlabserver (cwd = RUNS), output in RUNS/TAG.{log,out}; sets RC.
run_server() {
  local tag="$1"; shift
  (cd "$RUNS" && cbd_headless timeout 300 "$SERVER" "$@" -l "$RUNS/$tag.log" >"$RUNS/$tag.out" 2>&1)
  RC=$?
  [ -f "$RUNS/$tag.log" ] || touch "$RUNS/$tag.log"
  cat "$RUNS/$tag.out" "$RUNS/$tag.log" >"$RUNS/$tag.all"
  if [ "$RC" -eq 124 ]; then fail "$tag: meshlabserver timed out"; fi
  if [ "$RC" -ge 128 ] && [ "$RC" -ne 255 ]; then
    tail -20 "$RUNS/$tag.all" >&2; fail "$tag: meshlabserver crashed (exit $RC)"
  fi
}
expect() {  # tag fixed-string what
  grep -qF -- "$2" "$RUNS/$1.all" || { tail -30 "$RUNS/$1.all" >&2; fail "$1: $3 (no line containing '$2')"; }
}
reject() {  # tag fixed-string what
  if grep -qF -- "$2" "$RUNS/$1.all"; then tail -30 "$RUNS/$1.all" >&2; fail "$1: $3"; fi
}

# A filter run succeeds: meshlabserver exits 0 and the plugin logged the layout.
expect_pipeline_outcome() {  # tag filter
  [ "$RC" -eq 0 ] || { tail -30 "$RUNS/$1.all" >&2; fail "$1: meshlabserver exited $RC"; }
  expect "$1" "cbd: $2: layout voronoi: " "no layout report"
  expect "$1" "cbd: $2: time voronoi " "no timings"
}

# 1. Registration: the dump of all filters names both of ours.
run_server dump -d "$RUNS/filters.txt"
[ "$RC" -eq 0 ] || { tail -20 "$RUNS/dump.all" >&2; fail "dump: meshlabserver exited $RC"; }
expect dump "Current Plugins Dir is: $PREFIX/lib/x86_64-linux-gnu/meshlab/plugins" "plugins not taken from the prefix"
for f in "Voronoi common base domain" "Cross-parameterize"; do
  grep -qF "section f" "$RUNS/filters.txt" || fail "dump: no filter list written"
  grep -qE "^\\\\section f[0-9]+ $f *\$" "$RUNS/filters.txt" || fail "dump: filter '$f' is not registered (plugin not loaded?)"
done
info "ok: both filters registered ($(grep -c '^\\section' "$RUNS/filters.txt") filters in total)"

# 2. Voronoi common base domain, anchors from <mesh>_picked_points.pp next to the meshes.
write_mlx "$RUNS/voronoi.mlx" "Voronoi common base domain" "" ""
run_server voronoi -i "$DATA/octa.off" -i "$DATA/big.off" -s "$RUNS/voronoi.mlx"
T="cbd: Voronoi common base domain: "
expect voronoi "${T}source layer 'octa': 66 vertices, 128 faces, genus 0" "no source report"
expect voronoi "${T}target layer 'big': 66 vertices, 128 faces, genus 0" "no target report"
expect voronoi "${T}4 anchors matched by name (source: file '$DATA/octa_picked_points.pp', target: file '$DATA/big_picked_points.pp')" "anchors not read from the .pp files next to the meshes"
expect voronoi "${T}largest snap distance" "no snap distance"
expect voronoi "${T}6 paths, 4 patches on 'octa' and 'big'" "no summary"
expect_pipeline_outcome voronoi "Voronoi common base domain"
info "ok: Voronoi common base domain ran (exit $RC)"

# 3. Cross-parameterize with explicit anchor files (RichOpenFile and RichString values).
write_mlx "$RUNS/cross.mlx" "Cross-parameterize" "$DATA/source_anchors.pp" "$DATA/target_anchors.pp" 2
run_server cross -i "$DATA/octa.off" -i "$DATA/big.off" -s "$RUNS/cross.mlx"
T="cbd: Cross-parameterize: "
expect cross "${T}4 anchors matched by name (source: file '$DATA/source_anchors.pp', target: file '$DATA/target_anchors.pp')" "explicit anchor files not used"
expect cross "${T}'octa' onto 'big': E_ang " "no summary"
expect_pipeline_outcome cross "Cross-parameterize"
info "ok: Cross-parameterize ran (exit $RC)"

# 4. Missing anchor file: a clear error in the log, the script fails, nothing crashes.
write_mlx "$RUNS/missing.mlx" "Voronoi common base domain" "$DATA/no_such_anchors.pp" ""
run_server missing -i "$DATA/octa.off" -i "$DATA/big.off" -s "$RUNS/missing.mlx"
[ "$RC" -ne 0 ] || fail "missing: meshlabserver exited 0 although the filter must fail"
expect missing "cbd: Voronoi common base domain: cannot read anchor file '$DATA/no_such_anchors.pp': no such file (check the path) [file_not_found]" "error text not in the log"
expect missing "Problem with filter: Voronoi common base domain" "meshlabserver did not report the failed filter"
reject missing "layout voronoi:" "a layout was built with a missing anchor file"
info "ok: missing anchor file reported (exit $RC)"

# 5. No anchors at all (no parameter, no PickPoints, no <mesh>_picked_points.pp), and an open
#    surface: the core's validation messages, naming the layer.
run_server nopp -i "$DATA/lonely.off" -i "$DATA/big.off" -s "$RUNS/voronoi.mlx"
[ "$RC" -ne 0 ] || fail "nopp: meshlabserver exited 0 although the filter must fail"
expect nopp "no source anchors: layer 'lonely' has no picked points and '$DATA/lonely_picked_points.pp' does not exist" "no error about the missing anchors"
run_server open -i "$DATA/open.off" -i "$DATA/big.off" -s "$RUNS/voronoi.mlx"
[ "$RC" -ne 0 ] || fail "open: meshlabserver exited 0 although the filter must fail"
expect open "cbd: Voronoi common base domain: source mesh (layer 'open'): 3 boundary edges" "no error about the open surface"
expect open "[open_boundary]" "no error code"
info "ok: missing anchors and an open surface reported"

# 6. Inputs untouched, nothing added next to them.
(cd "$DATA" && sha256sum --quiet -c "$RUNS/inputs.sha256") >"$RUNS/check.out" 2>&1 ||
  { cat "$RUNS/check.out" >&2; fail "input files changed"; }
(cd "$DATA" && ls -A) | cmp -s - "$RUNS/inputs.list" || fail "files were added or removed next to the inputs: $(cd "$DATA" && ls -A | tr '\n' ' ')"
info "ok: input files unchanged"

info "PASS"
