# Sourced by the bench scripts that read bench/manifest.txt (ROOT is the repository).
# manifest_pair S T SA TA: sets FILES to the line's four paths (relative ones under the
# repository, $SHREC as ../shared/data/shrec07-fourleg beside it); returns 1 when one is missing.
manifest_pair() {
  local shrec f
  shrec="$(cd "$ROOT/.." && pwd)/shared/data/shrec07-fourleg"
  FILES=()
  for f in "$@"; do
    f="${f/\$SHREC/$shrec}"
    [[ "$f" = /* ]] || f="$ROOT/$f"
    [ -f "$f" ] || return 1
    FILES+=("$f")
  done
}
