#!/usr/bin/env bash
# Make a no-root MeshLab prefix that loads the cbd plugin next to Debian's own plugins. Idempotent.
#
# Debian's MeshLab 2020.09 loads plugins only from
#   <folder of the real executable>/../lib/x86_64-linux-gnu/meshlab/plugins
# (no environment variable, no per-user folder), and resolves symlinks to the executable. So
# the prefix holds COPIES of the executables and symlinks to Debian's library and plugins:
#
#   PREFIX/bin/meshlab, PREFIX/bin/meshlabserver          copies of /usr/bin/...
#   PREFIX/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so -> Debian's
#   PREFIX/lib/x86_64-linux-gnu/meshlab/plugins/lib*.so      -> Debian's plugins
#   PREFIX/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_cbd.so   our plugin (copied)
#
# The copied executables find libmeshlab-common.so through their RUNPATH
# ($ORIGIN/../lib/x86_64-linux-gnu/meshlab). Run PREFIX/bin/meshlab or PREFIX/bin/meshlabserver
# (meshlabserver needs an X display: xvfb-run -a PREFIX/bin/meshlabserver ...).
#
# Usage: scripts/meshlab_prefix.sh PREFIX [PLUGIN_SO]
#   PLUGIN_SO  the built plugin; default: the newer of build/plugin/libfilter_cbd.so and
#              build-plugin/plugin/libfilter_cbd.so under the repository. Without one found, the
#              prefix is made without our plugin (a warning says so).
# Environment: MESHLAB_BIN_DIR (default /usr/bin), MESHLAB_LIB_DIR
#              (default /usr/lib/x86_64-linux-gnu/meshlab) to take MeshLab from elsewhere.
set -euo pipefail

log() { printf '[meshlab_prefix] %s\n' "$*"; }
die() { printf '[meshlab_prefix] error: %s\n' "$*" >&2; exit 1; }

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 2 "$@"
if [ $# -lt 1 ]; then die "usage: $0 PREFIX [PLUGIN_SO]"; fi
PREFIX="$1"
PLUGIN_SO="${2:-}"
ML_BIN="${MESHLAB_BIN_DIR:-/usr/bin}"
ML_LIB="${MESHLAB_LIB_DIR:-/usr/lib/x86_64-linux-gnu/meshlab}"
PLUGIN_NAME=libfilter_cbd.so

for exe in meshlab meshlabserver; do
  [ -x "$ML_BIN/$exe" ] || die "$ML_BIN/$exe not found (install Debian's meshlab package: apt-get install meshlab)"
done
[ -f "$ML_LIB/libmeshlab-common.so" ] || die "$ML_LIB/libmeshlab-common.so not found (install Debian's meshlab package)"
[ -d "$ML_LIB/plugins" ] || die "$ML_LIB/plugins not found (install Debian's meshlab package)"

if [ -z "$PLUGIN_SO" ]; then
  # The newer of the two build trees' plugins (as meshlab_scripts/cross_parameterize.sh picks).
  # shellcheck source=plugin_path.sh
  . "$ROOT/scripts/plugin_path.sh"
  PLUGIN_SO="$(cbd_built_plugin "$ROOT")" || PLUGIN_SO=""
  [ -n "$PLUGIN_SO" ] || log "warning: no built $PLUGIN_NAME found; making the prefix without the cbd plugin"
else
  [ -f "$PLUGIN_SO" ] || die "plugin '$PLUGIN_SO' not found (build it: cmake --build <build dir> --target filter_cbd)"
fi

mkdir -p "$PREFIX"
PREFIX="$(cd "$PREFIX" && pwd)"
LIBDIR="$PREFIX/lib/x86_64-linux-gnu/meshlab"
PLUGDIR="$LIBDIR/plugins"
mkdir -p "$PREFIX/bin" "$PLUGDIR"

# Executables: real copies (a symlink would make MeshLab look for plugins under /usr).
for exe in meshlab meshlabserver; do
  if ! cmp -s "$ML_BIN/$exe" "$PREFIX/bin/$exe"; then
    rm -f "$PREFIX/bin/$exe"
    cp "$ML_BIN/$exe" "$PREFIX/bin/$exe"
    chmod 0755 "$PREFIX/bin/$exe"
  fi
done

ln -sfn "$ML_LIB/libmeshlab-common.so" "$LIBDIR/libmeshlab-common.so"

# Debian's plugins, as symlinks; drop stale links (e.g. after a MeshLab upgrade removed one).
for link in "$PLUGDIR"/*.so; do
  if [ -L "$link" ] && [ ! -e "$link" ]; then rm -f "$link"; fi
done
for so in "$ML_LIB/plugins"/*.so; do
  name="$(basename "$so")"
  if [ "$name" = "$PLUGIN_NAME" ]; then continue; fi  # a system-wide install of ours: PLUGIN_SO wins
  ln -sfn "$so" "$PLUGDIR/$name"
done

if [ -n "$PLUGIN_SO" ]; then
  rm -f "$PLUGDIR/$PLUGIN_NAME.tmp"
  cp "$PLUGIN_SO" "$PLUGDIR/$PLUGIN_NAME.tmp"
  chmod 0755 "$PLUGDIR/$PLUGIN_NAME.tmp"
  mv -f "$PLUGDIR/$PLUGIN_NAME.tmp" "$PLUGDIR/$PLUGIN_NAME"   # atomic: a running MeshLab keeps its copy
  log "cbd plugin: $PLUGDIR/$PLUGIN_NAME (from $PLUGIN_SO)"
fi

log "MeshLab prefix ready: $PREFIX ($(ls "$PLUGDIR" | wc -l) plugins)"
log "run: $PREFIX/bin/meshlab   or   xvfb-run -a $PREFIX/bin/meshlabserver -i a.off -i b.off -s script.mlx"
