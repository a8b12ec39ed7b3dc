#!/usr/bin/env bash
# Cross-parameterize two meshes with the cbd MeshLab plugin, headless (MeshLab 2020.09's
# meshlabserver on a private Xvfb, or cbd-meshlab-run with MeshLab 2025.07), and save the
# results. Run with --help for the details.
set -uo pipefail

NAME="cross_parameterize"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/.." && pwd)"

usage() {
  cat <<EOF
Usage: meshlab_scripts/cross_parameterize.sh SOURCE SOURCE.pp TARGET TARGET.pp OUTDIR

Runs MeshLab's "Cross-parameterize" filter (cbd plugin) on SOURCE onto TARGET with the
corresponding anchors of the two PickPoints files (MeshLab .pp; points matched by name) and
writes, into OUTDIR (created when missing):
  source_patches.ply   SOURCE coloured per face by patch of the common base domain
  target_patches.ply   TARGET coloured per face by patch (corresponding patches, same colour)
  mst.ply              M_st: SOURCE's triangles at the images of its vertices on TARGET;
                       face quality = L2 stretch, face colour blue-white-red by stretch,
                       vertex colour (and quality) transferred from TARGET when it has them
  meshlab.log          MeshLab's log (the cbd report: summary, anchors, layout, distortion, timings)
The input files are never modified: meshes and anchor files are copied into a temporary folder
under MeshLab's PickPoints naming (<mesh name>_picked_points.pp) and run from there. The
filter's parameters are those of meshlab_scripts/cross_parameterize.mlx (edit it to change
the method, the edge nodes or the smoothing; M_st must stay layer 2).

Two MeshLabs can run it, whichever is present (CBD_MESHLAB=2020 or 2025 chooses):
  2020  Debian's MeshLab 2020.09: meshlabserver on a private virtual X server (Xvfb, see
        meshlab_scripts/headless.sh) with the plugin build/plugin/libfilter_cbd.so;
  2025  MeshLab 2025.07 (no meshlabserver since 2022.02): cbd-meshlab-run, built with the
        plugin into build/plugin-2025/ once scripts/meshlab_2025.sh has built MeshLab 2025.07.
Environment:
  CBD_MESHLAB         2020 or 2025 (default: 2020 when Debian's meshlabserver and the plugin
                      are there, else 2025)
  CBD_PLUGIN_SO       2020: the plugin (default: the newer of build/plugin/libfilter_cbd.so
                      and build-plugin/plugin/libfilter_cbd.so in the repository)
  CBD_MESHLAB_PREFIX  2020: the no-root MeshLab prefix made by scripts/meshlab_prefix.sh
                      (default: \${XDG_CACHE_HOME:-\$HOME/.cache}/cbd/meshlab-prefix)
  CBD_MESHLAB_RUN     2025: the runner (default: build/plugin-2025/cbd-meshlab-run, which
                      loads the plugins beside it)
  KEEP_TMP=1          keep the temporary folder
Exit status: 0 all outputs written; 1 MeshLab or the filter failed (the reason is printed);
2 bad arguments.
EOF
}

die() { printf '[%s] error: %s\n' "$NAME" "$*" >&2; exit 1; }
bad() { printf '[%s] error: %s\n(see %s --help)\n' "$NAME" "$*" "$0" >&2; exit 2; }
info() { printf '[%s] %s\n' "$NAME" "$*"; }

for a in "$@"; do
  case "$a" in -h|--help) usage; exit 0 ;; esac
done
[ $# -eq 5 ] || bad "expected 5 arguments (SOURCE SOURCE.pp TARGET TARGET.pp OUTDIR), got $#"
SOURCE="$1" SOURCE_PP="$2" TARGET="$3" TARGET_PP="$4" OUTDIR="$5"
for f in "$SOURCE" "$SOURCE_PP" "$TARGET" "$TARGET_PP"; do
  [ -f "$f" ] && [ -r "$f" ] || bad "input file '$f' does not exist or is not readable"
done
MLX="$HERE/cross_parameterize.mlx"
[ -f "$MLX" ] || bad "filter script '$MLX' not found"
# Which MeshLab.
# shellcheck source=../scripts/plugin_path.sh
. "$ROOT/scripts/plugin_path.sh"
ENGINE="${CBD_MESHLAB:-}"
RUNNER="${CBD_MESHLAB_RUN:-$ROOT/build/plugin-2025/cbd-meshlab-run}"
PLUGIN_SO="${CBD_PLUGIN_SO:-}"
[ -n "$PLUGIN_SO" ] || PLUGIN_SO="$(cbd_built_plugin "$ROOT")" || PLUGIN_SO=""
if [ -z "$ENGINE" ]; then
  if command -v meshlabserver >/dev/null && [ -n "$PLUGIN_SO" ]; then ENGINE=2020
  elif [ -x "$RUNNER" ]; then ENGINE=2025
  else die "no MeshLab to run: build the plugin (scripts/build.sh) with Debian's meshlab installed, or MeshLab 2025.07 (scripts/meshlab_2025.sh) and then the plugin"
  fi
fi
case "$ENGINE" in
  2020)
    command -v Xvfb >/dev/null || die "Xvfb not found (apt-get install xvfb)"
    # shellcheck source=headless.sh
    . "$HERE/headless.sh"
    [ -n "$PLUGIN_SO" ] || die "no built plugin: build the filter_cbd target (cmake --build build --target filter_cbd) or set CBD_PLUGIN_SO"
    [ -f "$PLUGIN_SO" ] || die "plugin '$PLUGIN_SO' not found" ;;
  2025) [ -x "$RUNNER" ] || die "'$RUNNER' not found: build MeshLab 2025.07 (scripts/meshlab_2025.sh), then the plugin (scripts/build.sh)" ;;
  *) bad "CBD_MESHLAB must be 2020 or 2025, not '$ENGINE'" ;;
esac
PREFIX="${CBD_MESHLAB_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/cbd/meshlab-prefix}"

mkdir -p "$OUTDIR" || die "cannot create the output folder '$OUTDIR'"
OUTDIR="$(cd "$OUTDIR" && pwd)"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/cbd_cross.XXXXXX")" || die "cannot create a temporary folder"
cleanup() { if [ "${KEEP_TMP:-0}" = 1 ]; then info "kept $TMP"; else rm -rf "$TMP"; fi; }
trap cleanup EXIT

# Copies of the inputs, each mesh in a folder of its own with its anchors under PickPoints'
# name: the mesh file name minus its last 4 characters (".off") + "_picked_points.pp".
stage() {  # mesh pp folder
  local base; base="$(basename "$1")"
  [ ${#base} -gt 4 ] || bad "mesh file name '$base' is too short (expected NAME.ext)"
  mkdir -p "$3"
  cp -- "$1" "$3/$base" && cp -- "$2" "$3/${base:0:${#base}-4}_picked_points.pp" || die "cannot copy '$1' / '$2'"
  printf '%s' "$3/$base"
}
SRC_COPY="$(stage "$SOURCE" "$SOURCE_PP" "$TMP/source")" || exit $?
TGT_COPY="$(stage "$TARGET" "$TARGET_PP" "$TMP/target")" || exit $?

# Outputs. Layers: 0 source, 1 target, 2 M_st.
LOG="$OUTDIR/meshlab.log"
rm -f "$LOG" "$OUTDIR/source_patches.ply" "$OUTDIR/target_patches.ply" "$OUTDIR/mst.ply"
info "running Cross-parameterize on $(basename "$SOURCE") onto $(basename "$TARGET") ..."
if [ "$ENGINE" = 2020 ]; then
  "$ROOT/scripts/meshlab_prefix.sh" "$PREFIX" "$PLUGIN_SO" >"$TMP/prefix.log" 2>&1 ||
    { cat "$TMP/prefix.log" >&2; die "scripts/meshlab_prefix.sh failed"; }
  SERVER="$PREFIX/bin/meshlabserver"
  info "MeshLab 2020.09: $SERVER (plugin $PLUGIN_SO)"
  # meshlabserver writes what the mask asks for even when the layer lacks it, so M_st is saved
  # with and without vertex colour / quality and the variant matching what the filter
  # transferred is kept.
  (cd "$TMP" && cbd_headless timeout "${CBD_TIMEOUT:-1800}" "$SERVER" -l "$LOG" \
     -i "$SRC_COPY" "$TGT_COPY" -s "$MLX" \
     -o "$OUTDIR/source_patches.ply" -l 0 -m fc \
     -o "$OUTDIR/target_patches.ply" -l 1 -m fc \
     -o "$TMP/mst_f.ply" -l 2 -m fc fq \
     -o "$TMP/mst_fc.ply" -l 2 -m vc fc fq \
     -o "$TMP/mst_fq.ply" -l 2 -m vq fc fq \
     -o "$TMP/mst_fcq.ply" -l 2 -m vc vq fc fq) >"$TMP/server.out" 2>&1
  RC=$?
  { echo "--- meshlabserver output"; cat "$TMP/server.out"; } >>"$LOG"
else
  info "MeshLab 2025.07: $RUNNER"
  # The runner saves every attribute a layer has.
  (cd "$TMP" && timeout "${CBD_TIMEOUT:-1800}" "$RUNNER" "$MLX" "$SRC_COPY" "$TGT_COPY" \
     -o "$OUTDIR/source_patches.ply" "$OUTDIR/target_patches.ply" "$TMP/mst_run.ply") >"$LOG" 2>&1
  RC=$?
fi

# The log names the staged copies: name the user's files instead (they were copied verbatim).
SRC_PP_COPY="$(dirname "$SRC_COPY")/$(b="$(basename "$SRC_COPY")"; echo "${b:0:${#b}-4}")_picked_points.pp"
TGT_PP_COPY="$(dirname "$TGT_COPY")/$(b="$(basename "$TGT_COPY")"; echo "${b:0:${#b}-4}")_picked_points.pp"
while IFS= read -r line || [ -n "$line" ]; do
  line="${line//"$SRC_PP_COPY"/"$SOURCE_PP"}"; line="${line//"$TGT_PP_COPY"/"$TARGET_PP"}"
  line="${line//"$SRC_COPY"/"$SOURCE"}"; line="${line//"$TGT_COPY"/"$TARGET"}"
  printf '%s\n' "$line"
done <"$LOG" >"$TMP/log.fixed" && mv -f "$TMP/log.fixed" "$LOG"

TAG="cbd: Cross-parameterize: "
if [ $RC -ne 0 ]; then
  reason="$(grep "^cbd: " "$LOG" | grep -F '[' | tail -1)"
  [ -n "$reason" ] || reason="$(grep -E "Problem with filter|Failed to apply|not possible|Assertion|cbd-meshlab-run:" "$LOG" | tail -3)"
  printf '[%s] error: MeshLab failed (exit %d): %s\n' "$NAME" "$RC" "${reason:-see $LOG}" >&2
  printf '[%s] MeshLab log: %s\n' "$NAME" "$LOG" >&2
  exit 1
fi
grep "^$TAG" "$LOG" | sed "s/^/  /"

if [ "$ENGINE" = 2020 ]; then
  variant=f
  grep -qF "vertex colour transferred from the target" "$LOG" && variant="${variant}c"
  grep -qF "vertex quality transferred from the target" "$LOG" && variant="${variant}q"
  [ -s "$TMP/mst_$variant.ply" ] && mv -f "$TMP/mst_$variant.ply" "$OUTDIR/mst.ply"
else
  [ -s "$TMP/mst_run.ply" ] && mv -f "$TMP/mst_run.ply" "$OUTDIR/mst.ply"
fi

missing=""
for f in source_patches.ply target_patches.ply mst.ply meshlab.log; do
  [ -s "$OUTDIR/$f" ] || missing="$missing $f"
done
[ -z "$missing" ] || die "MeshLab exited 0 but did not write:$missing (see $LOG)"
info "wrote $OUTDIR/{source_patches,target_patches,mst}.ply and meshlab.log"
