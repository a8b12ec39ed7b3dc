# shellcheck shell=bash
# Sourced by meshlab_scripts/cross_parameterize.sh and the plugin tests: run a command (e.g.
# meshlabserver, which needs an X display even without a window) on a private virtual X server.
#
#   cbd_headless COMMAND [ARGS...]
#
# Starts Xvfb on a free display (Xvfb picks it: -displayfd), runs COMMAND with DISPLAY set,
# stops that Xvfb by its process id and returns COMMAND's exit status (3 if Xvfb did not start).
# Equivalent to `xvfb-run -a COMMAND`, without xvfb-run's shared temporary folder: xvfb-run
# exits 5 instead of COMMAND's status, and leaves its Xvfb running, when that folder is removed
# under it (seen with several X servers started in parallel).
cbd_headless() {
  command -v Xvfb >/dev/null || { echo "cbd_headless: Xvfb not found (apt-get install xvfb)" >&2; return 3; }
  local dfile n="" i xpid rc
  dfile="$(mktemp "${TMPDIR:-/tmp}/cbd_xvfb.XXXXXX")" || return 3
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dfile" >/dev/null 2>&1 &
  xpid=$!
  for i in $(seq 200); do
    if [ "$(wc -l <"$dfile" 2>/dev/null)" -ge 1 ]; then n="$(tr -dc '0-9' <"$dfile")"; break; fi
    kill -0 "$xpid" 2>/dev/null || break
    sleep 0.05
  done
  rm -f "$dfile"
  if [ -z "$n" ]; then
    kill "$xpid" 2>/dev/null; wait "$xpid" 2>/dev/null
    echo "cbd_headless: Xvfb did not start" >&2
    return 3
  fi
  DISPLAY=":$n" "$@"
  rc=$?
  kill "$xpid" 2>/dev/null
  wait "$xpid" 2>/dev/null
  return $rc
}
