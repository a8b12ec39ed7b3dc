#!/usr/bin/env bash
# Regenerate the MeshLab 2025.07 evidence in docs/: the real GUI (built by scripts/meshlab_2025.sh)
# on a virtual X server, with the plugin installed as a user of the official MeshLab would
# install it (the per-user folder MeshLabExtraPlugins/2025.07, under a private HOME):
#   docs/meshlab2025_filters.png   Filters > Remeshing, Simplification and Reconstruction lists
#                                  both cbd filters;
#   docs/meshlab2025_progress.png  half way through Cross-parameterize on the bundled pair (cow
#                                  onto bull, anchors from <mesh>_picked_points.pp): the progress
#                                  bar and the stage's name in the status bar.
# Usage: scripts/screenshot_2025.sh [BUILD_DIR]      (default: build)
# Needs: xvfb, xdotool, imagemagick.
set -uo pipefail
NAME="screenshot_2025"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 1 "$@"
BUILD="${1:-$ROOT/build}"
die() { printf '[%s] error: %s\n' "$NAME" "$*" >&2; exit 1; }
for tool in xvfb-run xdotool import convert; do
  command -v "$tool" >/dev/null || die "$tool not found (apt-get install xvfb xdotool imagemagick)"
done
MESHLAB="$ROOT/third_party/meshlab-2025/prefix/bin/meshlab"
PLUGIN="$BUILD/plugin-2025/libfilter_cbd.so"
[ -x "$MESHLAB" ] || die "$MESHLAB not found (scripts/meshlab_2025.sh)"
[ -f "$PLUGIN" ] || die "$PLUGIN not found (build after scripts/meshlab_2025.sh)"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/cbd_gui2025.XXXXXX")" || die "cannot create a temporary folder"
trap 'rm -rf "$TMP"' EXIT
export HOME="$TMP/home" XDG_RUNTIME_DIR="$TMP/home/run"
mkdir -p "$XDG_RUNTIME_DIR" "$TMP/data" "$HOME/.config/VCG" && chmod 700 "$XDG_RUNTIME_DIR"
# MeshLab 2025.07 reads extra plugins from QStandardPaths::AppDataLocation/MeshLabExtraPlugins/<version>.
EXTRA="$HOME/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07"
mkdir -p "$EXTRA" && cp "$PLUGIN" "$EXTRA/"
printf '[General]\ninformativeShown=true\n' >"$HOME/.config/VCG/MeshLab_64bit_fp.conf"
cp "$ROOT/third_party/cgal-data/meshes/cow.off" "$ROOT/third_party/cgal-data/meshes/bull.off" "$TMP/data/"
cp "$ROOT/examples/cow_picked_points.pp" "$ROOT/examples/bull_picked_points.pp" "$TMP/data/"
cat >"$TMP/run.sh" <<RUN
"$MESHLAB" "$TMP/data/bull.off" "$TMP/data/cow.off" >"$TMP/meshlab.log" 2>&1 &
pid=\$!
for i in \$(seq 1 60); do wid=\$(xdotool search --name "^MeshLab 2025" 2>/dev/null | head -n1); [ -n "\$wid" ] && break; sleep 0.5; done
sleep 4
xdotool key Escape; sleep 1                      # a first-start question, if any
xdotool windowfocus --sync "\$wid" 2>/dev/null
xdotool key --window "\$wid" alt+l; sleep 1       # Fi&lters
xdotool key --delay 200 Down Down Down Down; sleep 0.5; xdotool key Right; sleep 1.5
import -window root "$TMP/filters.png"
xdotool key Return; sleep 2                      # Cross-parameterize: its dialog
xdotool mousemove 617 788 click 1                # Apply (a 1400x900 screen, MeshLab's default size)
sleep 2.5
import -window root "$TMP/progress.png"
sleep 12
kill \$pid; sleep 1; kill -9 \$pid 2>/dev/null
RUN
timeout 120 xvfb-run -a -s "-screen 0 1400x900x24" bash "$TMP/run.sh"
grep -q "cbd: Cross-parameterize: 'cow' onto 'bull': E_ang" "$TMP/meshlab.log" ||
  die "Cross-parameterize did not run from the GUI (see the log: $(tail -3 "$TMP/meshlab.log"))"
convert "$TMP/filters.png" -crop 932x760+0+0 +repage "$ROOT/docs/meshlab2025_filters.png"
convert "$TMP/progress.png" -crop 932x760+0+0 +repage "$ROOT/docs/meshlab2025_progress.png"
echo "[$NAME] wrote docs/meshlab2025_filters.png and docs/meshlab2025_progress.png"
