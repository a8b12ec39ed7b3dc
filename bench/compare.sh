#!/usr/bin/env bash
# This build's `cbd map` against the one of an earlier commit, side by side on the bench pairs:
# the commit REF is exported into a temporary folder and its CLI built there (against this
# checkout's third_party/), then for every pair of bench/manifest.txt and every method both
# binaries run one after the other, alternating which goes first, so the machine's drift hits
# both alike. Prints one table row per pair and method (both totals, their ratio, and each
# side's E_ang, E_L2 and M_st's flipped count) and writes them to OUT/compare.csv. Extra
# arguments go to this build's `cbd map` only (e.g. --map-stage optimize); REF runs its defaults.
# Usage: bench/compare.sh REF [OUT] [-- cbd map arguments for this build]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case "${1:-}" in "" | -h | --help) sed -n 's/^# Usage: //p' "$0"; exit 0 ;; esac
REF="$1"; shift
OUT="$ROOT/bench/results"
if [ "$#" -gt 0 ] && [ "$1" != "--" ]; then OUT="$1"; shift; fi
[ "${1:-}" = "--" ] && shift
EXTRA=("$@")
git -C "$ROOT" rev-parse --verify --quiet "$REF^{commit}" >/dev/null || { echo "compare.sh: no commit '$REF'" >&2; exit 2; }
"$ROOT/scripts/setup.sh" >/dev/null
"$ROOT/scripts/build.sh" "$ROOT/build" >/dev/null
NEW="$ROOT/build/cli/cbd"

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
mkdir "$WORK/ref"
git -C "$ROOT" archive "$REF" | tar -x -C "$WORK/ref"
GEN=()
command -v ninja >/dev/null 2>&1 && GEN=(-G Ninja)
cmake -S "$WORK/ref" -B "$WORK/ref/build" "${GEN[@]}" -DCMAKE_BUILD_TYPE=Release -DCBD_BUILD_TESTS=OFF \
  -DCBD_BUILD_PLUGIN=OFF -DCBD_MESHLAB_SOURCE="$ROOT/third_party/meshlab" >/dev/null
cmake --build "$WORK/ref/build" --target cbd --parallel "$(nproc)" >/dev/null
OLD="$WORK/ref/build/cli/cbd"

# One run: prints "total e_ang e_l2 flipped" from its JSON report, or "fail status".
run() {
  local bin="$1" json="$2"; shift 2
  if "$bin" map "$@" --json "$json" >/dev/null 2>&1; then
    python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); m=j["metrics"]
print("%.3f %.4f %.4f %d" % (j["timing_s"]["total"], m["e_ang"], m["e_l2"], m["flipped"]))' "$json"
  else
    python3 -c 'import json,sys
try: print("fail", json.load(open(sys.argv[1]))["status"])
except Exception: print("fail", "no_report")' "$json"
  fi
}

. "$ROOT/bench/manifest.sh"
mkdir -p "$OUT"
CSV="$OUT/compare.csv"
echo "pair,method,ref,ref_total_s,new_total_s,ratio,ref_e_ang,new_e_ang,ref_e_l2,new_e_l2,ref_flipped,new_flipped" >"$CSV"
echo "| pair | method | $REF s | this build s | ratio | E_ang $REF / this | E_L2 $REF / this | flipped $REF / this |"
echo "|---|---|---|---|---|---|---|---|"
first=0
while read -r name s t sa ta; do
  case "$name" in "" | \#*) continue ;; esac
  manifest_pair "$s" "$t" "$sa" "$ta" || { echo "| $name | skipped: input missing | | | | | | |"; continue; }
  files=("${FILES[@]}")
  args=(--source "${files[0]}" --target "${files[1]}" --source-anchors "${files[2]}" --target-anchors "${files[3]}")
  for method in voronoi greedy; do
    if [ "$first" = 0 ]; then
      old=$(run "$OLD" "$WORK/old.json" "${args[@]}" --method "$method" --out "$WORK/old")
      new=$(run "$NEW" "$WORK/new.json" "${args[@]}" --method "$method" --out "$WORK/new" "${EXTRA[@]}")
    else
      new=$(run "$NEW" "$WORK/new.json" "${args[@]}" --method "$method" --out "$WORK/new" "${EXTRA[@]}")
      old=$(run "$OLD" "$WORK/old.json" "${args[@]}" --method "$method" --out "$WORK/old")
    fi
    first=$((1 - first))
    read -r ot oa ol of <<<"$old"
    read -r nt na nl nf <<<"$new"
    if [ "$ot" = fail ] || [ "$nt" = fail ]; then
      echo "| $name | $method | $old | $new | | | | |"
      echo "$name,$method,$REF,$old,$new,,,,,,," >>"$CSV"
      continue
    fi
    ratio=$(python3 -c "print('%.2f' % ($nt / $ot))")
    echo "| $name | $method | $ot | $nt | $ratio | $oa / $na | $ol / $nl | $of / $nf |"
    echo "$name,$method,$REF,$ot,$nt,$ratio,$oa,$na,$ol,$nl,$of,$nf" >>"$CSV"
  done
done <"$ROOT/bench/manifest.txt"
echo "wrote $CSV"
