#!/usr/bin/env bash
# How far `cbd map`'s result moves when only the source's vertex and face numbering changes:
# for every pair of bench/manifest.txt and every method, the source mesh is written again with
# its vertices and faces shuffled (a fixed seed; each face's corners rotated, so its orientation
# is kept) and its anchors renumbered with it (a `.pp` file names positions and stays as it is),
# then both numberings run, with the map stage the arguments choose (untangle by default) and
# with --no-untangle (the composed map: the layouts' and the patch maps' share). Each source
# vertex's image is compared across the two runs: the largest and the median distance, as a
# fraction of the target's bounding-box diagonal, and each run's E_ang, E_L2 and M_st's flipped
# count. Writes OUT/renumber_STAGE.csv. Set PAIRS="cow-bull bull-cow" to run only those pairs.
# Usage: bench/renumber.sh [OUT] [-- cbd map arguments]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case "${1:-}" in -h | --help) sed -n 's/^# Usage: //p' "$0"; exit 0 ;; esac
OUT="$ROOT/bench/results"
if [ "$#" -gt 0 ] && [ "$1" != "--" ]; then OUT="$1"; shift; fi
[ "${1:-}" = "--" ] && shift
EXTRA=("$@")
STAGE=untangle
for ((i = 0; i < ${#EXTRA[@]}; ++i)); do
  [ "${EXTRA[$i]}" = --map-stage ] && [ $((i + 1)) -lt ${#EXTRA[@]} ] && STAGE="${EXTRA[$((i + 1))]}"
done
"$ROOT/scripts/setup.sh" >/dev/null
"$ROOT/scripts/build.sh" "$ROOT/build" >/dev/null
CBD="$ROOT/build/cli/cbd"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

# renumber MESH ANCHORS OUTDIR: writes OUTDIR/source.off, OUTDIR/anchors.<ext>, OUTDIR/order
# (the new index of every old vertex).
renumber() {
  python3 - "$@" <<'PY'
import os, random, sys
mesh, anchors, out = sys.argv[1:4]
tok = []
for line in open(mesh):
    line = line.split('#')[0].split()
    tok += line
assert tok[0].endswith('OFF'), 'renumber.sh reads OFF meshes only'
nv, nf = int(tok[1]), int(tok[2])
i = 4
verts = [tok[i + 3 * k:i + 3 * k + 3] for k in range(nv)]
i += 3 * nv
faces = []
for _ in range(nf):
    n = int(tok[i]); faces.append([int(x) for x in tok[i + 1:i + 1 + n]]); i += 1 + n
rng = random.Random(20261207)
new = list(range(nv)); rng.shuffle(new)          # new[old] = new index
old = [0] * nv
for o, n in enumerate(new): old[n] = o
order = list(range(nf)); rng.shuffle(order)
with open(os.path.join(out, 'source.off'), 'w') as f:
    f.write('OFF\n%d %d 0\n' % (nv, nf))
    for n in range(nv): f.write(' '.join(verts[old[n]]) + '\n')
    for k in order:
        t = [new[v] for v in faces[k]]
        r = rng.randrange(len(t)); t = t[r:] + t[:r]
        f.write('%d %s\n' % (len(t), ' '.join(map(str, t))))
ext = os.path.splitext(anchors)[1]
with open(os.path.join(out, 'anchors' + ext), 'w') as f:
    for line in open(anchors):
        s = line.split()
        if ext != '.pp' and s and not s[0].startswith('#'):
            s[0] = str(new[int(s[0])]); line = ' '.join(s) + '\n'
        f.write(line)
open(os.path.join(out, 'order'), 'w').write(' '.join(map(str, new)))
PY
}

# compare A B ORDER TARGET_MESH: "max median" image distance over the target's diagonal.
compare() {
  python3 - "$@" <<'PY'
import math, sys
a_file, b_file, order_file, target = sys.argv[1:5]
new = list(map(int, open(order_file).read().split()))
def images(path):
    d = {}
    for line in open(path):
        if line.startswith('#'): continue
        s = line.split(); d[int(s[0])] = tuple(map(float, s[5:8]))
    return d
tok = []
for line in open(target): tok += line.split('#')[0].split()
nv = int(tok[1]); p = [tuple(map(float, tok[4 + 3 * k:7 + 3 * k])) for k in range(nv)]
diag = math.dist([min(c[i] for c in p) for i in range(3)], [max(c[i] for c in p) for i in range(3)])
a, b = images(a_file), images(b_file)
d = sorted(math.dist(a[v], b[new[v]]) / diag for v in a)
print('%.2e %.2e' % (d[-1], d[len(d) // 2]))
PY
}

# run JSON OUTDIR args...: "e_ang e_l2 flipped", or "fail" when cbd map fails.
run() {
  local json="$1" out="$2"; shift 2
  if "$CBD" map "$@" --out "$out" --json "$json" >/dev/null 2>&1; then
    python3 -c 'import json,sys; m=json.load(open(sys.argv[1]))["metrics"]
print("%.4f %.4f %d" % (m["e_ang"], m["e_l2"], m["flipped"]))' "$json"
  else
    echo "fail"
  fi
}

. "$ROOT/bench/manifest.sh"
mkdir -p "$OUT"
CSV="$OUT/renumber_$STAGE.csv"
echo "pair,method,map,max_moved,median_moved,e_ang,e_ang_renumbered,e_l2,e_l2_renumbered,flipped,flipped_renumbered" >"$CSV"
echo "| pair | method | map | largest / median move (of the diagonal) | E_ang | E_L2 | flipped |"
echo "|---|---|---|---|---|---|---|"
while read -r name s t sa ta; do
  case "$name" in "" | \#*) continue ;; esac
  if [ -n "${PAIRS:-}" ] && [[ " $PAIRS " != *" $name "* ]]; then continue; fi
  manifest_pair "$s" "$t" "$sa" "$ta" || { echo "| $name | skipped: input missing | | | | | |"; continue; }
  files=("${FILES[@]}")
  rm -rf "$WORK/r" && mkdir -p "$WORK/r"
  renumber "${files[0]}" "${files[2]}" "$WORK/r"
  ra=("$WORK"/r/anchors.*)
  for method in voronoi greedy; do
    for stage in "$STAGE" composed; do
      flag=("${EXTRA[@]}")
      [ "$stage" = composed ] && flag=(--no-untangle)
      common=(--target "${files[1]}" --target-anchors "${files[3]}" --method "$method" "${flag[@]}")
      one=$(run "$WORK/a.json" "$WORK/a" --source "${files[0]}" --source-anchors "${files[2]}" "${common[@]}")
      two=$(run "$WORK/b.json" "$WORK/b" --source "$WORK/r/source.off" --source-anchors "${ra[0]}" "${common[@]}")
      if [ "$one" = fail ] || [ "$two" = fail ]; then
        echo "| $name | $method | $stage | failed: $one / $two | | | |"
        continue
      fi
      read -r mx md <<<"$(compare "$WORK/a/correspondence.txt" "$WORK/b/correspondence.txt" "$WORK/r/order" "${files[1]}")"
      read -r a1 l1 f1 <<<"$one"
      read -r a2 l2 f2 <<<"$two"
      echo "| $name | $method | $stage | $mx / $md | $a1 / $a2 | $l1 / $l2 | $f1 / $f2 |"
      echo "$name,$method,$stage,$mx,$md,$a1,$a2,$l1,$l2,$f1,$f2" >>"$CSV"
    done
  done
done <"$ROOT/bench/manifest.txt"
echo "wrote $CSV"
