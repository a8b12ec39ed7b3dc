# Sourced by the scripts in scripts/ and bench/: `--help` prints the script's "# Usage:" line,
# and an argument the script does not take stops it before it sets up, builds or writes
# anything (an option taken for a path would otherwise become a directory named after it).
# cbd_args MAX_POSITIONAL "$@"
cbd_usage() { sed -n 's/^# Usage: //p' "$0"; }
cbd_args() {
  local max="$1" a
  shift
  for a in "$@"; do
    case "$a" in -h | --help) cbd_usage; exit 0 ;; esac
  done
  for a in "$@"; do
    case "$a" in -*) printf '%s: unknown option %s (see --help)\n' "$(basename "$0")" "$a" >&2; cbd_usage >&2; exit 2 ;; esac
  done
  if [ "$#" -gt "$max" ]; then
    printf '%s: expected at most %d argument(s), got %d (see --help)\n' "$(basename "$0")" "$max" "$#" >&2
    cbd_usage >&2
    exit 2
  fi
}
