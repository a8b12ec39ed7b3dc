#!/usr/bin/env bash
# The CLI end to end: `cbd check` passes the bundled real pair and gives every bad input its documented
# status and exit code, one line on stderr; `cbd layout` and `cbd map` run on the bundled pair;
# no input file is ever changed.
# Usage: test_cli_check.sh CBD_BINARY EXAMPLES_DIR WORK_DIR
set -uo pipefail
CBD="$1"; EXAMPLES="$2"; WORK="$3"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
MESHES="$ROOT/third_party/cgal-data/meshes"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"
fails=0; passes=0
ok()   { passes=$((passes+1)); echo "ok   - $*"; }
bad()  { fails=$((fails+1));  echo "FAIL - $*"; }

code_of() { "$CBD" exit-codes | awk -v n="$1" '$2==n {print $1}'; }

# expect NAME STATUS -- args...
expect() {
  local name="$1" status="$2"; shift 3
  local want; want=$(code_of "$status")
  [ -n "$want" ] || { bad "$name: unknown status $status"; return; }
  local before; before=$(cat "$@" 2>/dev/null | md5sum)
  "$CBD" check "$@" --json "$WORK/$name.json" >"$WORK/$name.out" 2>"$WORK/$name.err"
  local rc=$?
  local got; got=$(sed -n 's/.*"status": "\([a-z_]*\)".*/\1/p' "$WORK/$name.json" 2>/dev/null)
  local lines; lines=$(wc -l <"$WORK/$name.err")
  if [ "$rc" = "$want" ] && [ "$got" = "$status" ]; then
    if [ "$status" != ok ] && [ "$lines" != 1 ]; then bad "$name: expected one line on stderr, got $lines"; return; fi
    ok "$name: exit $rc, status $got $( [ "$status" != ok ] && head -c 160 "$WORK/$name.err")"
  else
    bad "$name: expected exit $want/status $status, got exit $rc/status '$got': $(cat "$WORK/$name.err")"
  fi
}

# --- procedural inputs -------------------------------------------------------------
cat > octa.off <<'MESH'
OFF
6 8 0
1 0 0
-1 0 0
0 1 0
0 -1 0
0 0 1
0 0 -1
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
MESH
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\nym 0 -1 0\nzp 0 0 1\nzm 0 0 -1\n' > octa.txt
sed '$d' octa.off > open.off; sed -i 's/^6 8 0$/6 7 0/' open.off                     # one face removed
sed 's/^3 0 2 4$/3 2 0 4/' octa.off > flipped.off                                   # one face reversed
sed 's/^0 0 -1$/0 0 nan/' octa.off > nan.off
printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n' > trunc.off
: > empty.off
printf 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' > quads.off
{ echo OFF; echo "12 16 0"; sed -n '3,8p' octa.off; sed -n '3,8p' octa.off | awk '{print $1+5, $2, $3}';
  sed -n '9,16p' octa.off; sed -n '9,16p' octa.off | awk '{print 3, $2+6, $3+6, $4+6}'; } > two.off
cat > fan.off <<'MESH'
OFF
5 3 0
0 0 0
0 0 1
1 0 0.5
-0.5 0.8 0.5
-0.5 -0.8 0.5
3 0 1 2
3 1 0 3
3 0 1 4
MESH
# genus 1: a 4x4 torus grid
python3 - <<'PY'
import math
nu,nv=8,6
with open('torus.off','w') as f:
    f.write('OFF\n%d %d 0\n'%(nu*nv,2*nu*nv))
    for i in range(nu):
        for j in range(nv):
            u=2*math.pi*i/nu; v=2*math.pi*j/nv
            f.write('%r %r %r\n'%((2+0.7*math.cos(v))*math.cos(u),(2+0.7*math.cos(v))*math.sin(u),0.7*math.sin(v)))
    idx=lambda i,j: (i%nu)*nv+(j%nv)
    for i in range(nu):
        for j in range(nv):
            f.write('3 %d %d %d\n3 %d %d %d\n'%(idx(i,j),idx(i+1,j),idx(i+1,j+1),idx(i,j),idx(i+1,j+1),idx(i,j+1)))
PY
printf '0\n10\n20\n' > torus.vts
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\n' > octa3.txt
printf 'xp 1 0 0\nxm -1 0 0\n' > octa2.txt
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\nym 0 -1 0\nzp 0 0 1\nWRONG 0 0 -1\n' > octa_wrong.txt
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\nxp 0 -1 0\n' > octa_dup.txt
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\nym 0 -1 0\nzp 0 0 1\nzm 0 0 -3\n' > octa_far.txt
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\nym 0 -1 0\nzp 0 0 1\nzm 0.99 0 0.01\n' > octa_share.txt
printf '0\n1\n2\n99\n' > octa_range.vts
printf '0\n1\n2\n' > octa_idx.vts
printf '<!DOCTYPE PickedPoints>\n<PickedPoints>\n <point x="1" y="0" z="0" name="xp"/>\n <point x="1" y="0\n</PickedPoints>\n' > malformed.pp

# degenerate face: a vertex moved onto the midpoint of the opposite edge of a face
sed 's/^0 0 1$/0.5 0.5 0/' octa.off > degenerate.off
# duplicate face
{ sed '2s/.*/6 9 0/' octa.off; echo "3 0 2 4"; } > duplicate.off
# non-manifold vertex: an octahedron and its point reflection through its vertex 0 (1 0 0)
python3 - <<'PY'
V=[(1,0,0),(-1,0,0),(0,1,0),(0,-1,0),(0,0,1),(0,0,-1)]
F=[(0,2,4),(2,1,4),(1,3,4),(3,0,4),(2,0,5),(1,2,5),(3,1,5),(0,3,5)]
V2=V+[(2-x,-y,-z) for (x,y,z) in V[1:]]
m=lambda v: 0 if v==0 else v+5
F2=F+[(m(a),m(c),m(b)) for (a,b,c) in F]
with open('nmv.off','w') as f:
    f.write('OFF\n%d %d 0\n'%(len(V2),len(F2)))
    for p in V2: f.write('%g %g %g\n'%p)
    for t in F2: f.write('3 %d %d %d\n'%t)
PY
printf 'xp 1 0 0\nxm -1 0 0\nyp 0 1 0\nym 0 -1 0\nzp 0 0 1\nzm 0 0 -1\nxp2 1 0 0\n' > octa7.txt

P=(--source-anchors octa.txt --target-anchors octa.txt)
expect ok_octahedron        ok                   -- --source octa.off --target octa.off "${P[@]}"
expect ok_index_lists       ok                   -- --source octa.off --target octa.off --source-anchors octa_idx.vts --target-anchors octa_idx.vts
expect missing_mesh         file_not_found       -- --source nowhere.off --target octa.off "${P[@]}"
expect missing_anchors      file_not_found       -- --source octa.off --target octa.off --source-anchors nowhere.pp --target-anchors octa.txt
expect unsupported          unsupported_format   -- --source octa.txt --target octa.off "${P[@]}"
expect empty_file           malformed_mesh       -- --source empty.off --target octa.off "${P[@]}"
expect truncated            malformed_mesh       -- --source trunc.off --target octa.off "${P[@]}"
expect quads                not_triangles        -- --source quads.off --target octa.off "${P[@]}"
expect nan                  invalid_coordinates  -- --source octa.off --target nan.off "${P[@]}"
expect open                 open_boundary        -- --source open.off --target octa.off "${P[@]}"
# sample-anchors validates its mesh as check does: no "nan" anchors, no anchors on an open surface.
for c in "nan.off invalid_coordinates 1 vertex with NaN" "open.off open_boundary 3 boundary edges"; do
  set -- $c; m=$1; st=$2; shift 2; msg="$*"
  rm -f "sample_$m.pp"; "$CBD" sample-anchors -m "$m" -n 3 -o "sample_$m.pp" >/dev/null 2>"sample_$m.err"; rc=$?
  if [ "$rc" = "$(code_of "$st")" ] && [ ! -e "sample_$m.pp" ] && grep -q "mesh '$m': $msg" "sample_$m.err"; then
    ok "sample-anchors on $m: exit $rc, $(cat "sample_$m.err")"
  else
    bad "sample-anchors on $m: exit $rc (want $st), $(cat "sample_$m.err")"
  fi
done
# A vertex no face uses: the warnings name the file (check, layout, sample-anchors), and
# sample-anchors refuses it as --seed rather than start elsewhere.
sed 's/^6 8 0$/7 8 0/; s/^0 0 -1$/0 0 -1\n3 3 3/' octa.off > unref.off
"$CBD" check --source unref.off --target octa.off "${P[@]}" >unref_check.out 2>&1; rc=$?
[ "$rc" = 0 ] && grep -q "source mesh 'unref.off': 1 unreferenced vertex ignored (e.g. vertex 6)" unref_check.out &&
  ok "unreferenced vertex: check names the file, $(grep unreferenced unref_check.out)" || bad "unreferenced vertex: check exit $rc, $(cat unref_check.out)"
"$CBD" layout --source unref.off --source-anchors octa.txt -o unref_layout >/dev/null 2>unref_layout.err; rc=$?
[ "$rc" = 0 ] && grep -q "warning: source mesh 'unref.off': 1 unreferenced vertex ignored" unref_layout.err &&
  ok "unreferenced vertex: layout names the file" || bad "unreferenced vertex: layout exit $rc, $(cat unref_layout.err)"
"$CBD" sample-anchors -m unref.off -n 3 -o unref.pp >unref_sample.out 2>unref_sample.err; rc=$?
[ "$rc" = 0 ] && grep -q "warning: mesh 'unref.off': 1 unreferenced vertex ignored" unref_sample.err &&
  grep -q "wrote 3 anchors" unref_sample.out && ok "unreferenced vertex: sample-anchors names the file" ||
  bad "unreferenced vertex: sample-anchors exit $rc, $(cat unref_sample.out unref_sample.err)"
"$CBD" sample-anchors -m unref.off -n 1 -o one.pp >one.out 2>&1; rc=$?
[ "$rc" = 0 ] && grep -q "wrote 1 anchor to one.pp" one.out && ok "sample-anchors -n 1: $(cat one.out)" || bad "sample-anchors -n 1: exit $rc, $(cat one.out)"
rm -f unref_seed.pp; "$CBD" sample-anchors -m unref.off -n 3 --seed 6 -o unref_seed.pp >/dev/null 2>unref_seed.err; rc=$?
[ "$rc" = 2 ] && [ ! -e unref_seed.pp ] && grep -q -- "seed vertex 6 is an unreferenced vertex of 'unref.off'" unref_seed.err &&
  ok "sample-anchors --seed on an unreferenced vertex: exit 2, $(cat unref_seed.err)" ||
  bad "sample-anchors --seed on an unreferenced vertex: exit $rc, $(cat unref_seed.err)"
printf 'xp 1 0 0\n' > octa1.txt
"$CBD" check --source octa.off --target octa.off --source-anchors octa1.txt --target-anchors octa1.txt >/dev/null 2>one_anchor.err
grep -q "1 corresponding anchor given" one_anchor.err && ok "one anchor: counted in the singular" || bad "one anchor: $(cat one_anchor.err)"
printf 'OFF\n1 0 0\n0 0 0\n' > point.off
"$CBD" check --source point.off --target octa.off "${P[@]}" >/dev/null 2>point.err; rc=$?
[ "$rc" = "$(code_of empty_mesh)" ] && grep -q "mesh 'point.off' has 1 vertex and 0 faces" point.err &&
  ok "one vertex, no face: exit $rc, $(cat point.err)" || bad "one vertex, no face: exit $rc, $(cat point.err)"
expect nonmanifold_edge     non_manifold_edge    -- --source fan.off --target octa.off "${P[@]}"
expect orientation          inconsistent_orientation -- --source flipped.off --target octa.off "${P[@]}"
expect components           multiple_components  -- --source two.off --target octa.off "${P[@]}"
expect genus                genus_mismatch       -- --source octa.off --target torus.off --source-anchors octa_idx.vts --target-anchors torus.vts
awk 'NF == 4 && $1 == 3 { print 3, $2, $4, $3; next } { print }' octa.off > inside_out.off  # every face reversed
expect inside_out           orientation_mismatch -- --source inside_out.off --target octa.off "${P[@]}"
expect both_inside_out      ok                   -- --source inside_out.off --target inside_out.off "${P[@]}"
expect malformed_pp         malformed_anchors    -- --source octa.off --target octa.off --source-anchors malformed.pp --target-anchors octa.txt
expect name_mismatch        anchor_name_mismatch -- --source octa.off --target octa.off --source-anchors octa.txt --target-anchors octa_wrong.txt
expect duplicate_name       duplicate_anchor_name -- --source octa.off --target octa.off --source-anchors octa_dup.txt --target-anchors octa.txt
expect index_range          anchor_index_out_of_range -- --source octa.off --target octa.off --source-anchors octa_range.vts --target-anchors octa_range.vts
expect off_surface          anchor_off_surface   -- --source octa.off --target octa.off --source-anchors octa.txt --target-anchors octa_far.txt
expect share_vertex         anchors_share_vertex -- --source octa.off --target octa.off --source-anchors octa.txt --target-anchors octa_share.txt
expect too_few              too_few_anchors      -- --source octa.off --target octa.off --source-anchors octa2.txt --target-anchors octa2.txt
expect degenerate           degenerate_face      -- --source degenerate.off --target octa.off "${P[@]}"
expect duplicate_face       duplicate_face       -- --source duplicate.off --target octa.off "${P[@]}"
expect nonmanifold_vertex   non_manifold_vertex  -- --source nmv.off --target octa.off "${P[@]}"
expect too_many             too_many_anchors     -- --source octa.off --target octa.off --source-anchors octa7.txt --target-anchors octa7.txt

# Argument errors: exit 2 and a line on stderr.
"$CBD" check --source octa.off >/dev/null 2>args.err; rc=$?
[ "$rc" = 2 ] && [ -s args.err ] && ok "missing arguments: exit 2" || bad "missing arguments: exit $rc"
"$CBD" check --help >help.out 2>&1; rc=$?
[ "$rc" = 0 ] && grep -q -- --source-anchors help.out && ok "check --help" || bad "check --help: exit $rc"
# An unwritable JSON path is an output error and the check result is not reported as ok.
"$CBD" check --source octa.off --target octa.off "${P[@]}" --json /nonexistent/dir/r.json >/dev/null 2>json.err; rc=$?
[ "$rc" = "$(code_of output_error)" ] && ok "unwritable --json: exit $rc" || bad "unwritable --json: exit $rc"

# Words and values CLI11 alone would misname: an unknown command, a NaN tolerance (which
# passes a range check), one edge node together with a b.
"$CBD" frobnicate >/dev/null 2>cmd.err; rc=$?
[ "$rc" = 2 ] && grep -q "unknown command 'frobnicate': one of check, layout, map" cmd.err &&
  ok "unknown command: exit 2, $(cat cmd.err)" || bad "unknown command: exit $rc, $(cat cmd.err)"
# A misspelt option among missing required ones is named (CLI11 names the first missing one).
"$CBD" map --source octa.off --srouce-anchors octa.txt >/dev/null 2>misspelt.err; rc=$?
[ "$rc" = 2 ] && grep -q "unknown option '--srouce-anchors' of 'map'" misspelt.err &&
  ok "misspelt option: exit 2, $(cat misspelt.err)" || bad "misspelt option: exit $rc, $(cat misspelt.err)"
# ... whatever CLI11 would have said first: options that need one another, an option with its
# value after '=', an option before the command.
for c in "layout|--taget-anchors|layout --source octa.off --target octa.off --taget-anchors octa.txt" \
         "map|--bogus|map --bogus=x --json -" "|--bogus|--bogus map" "check|--frobnicate|check --source octa.off --frobnicate"; do
  IFS='|' read -r cmd opt line <<<"$c"
  "$CBD" $line >/dev/null 2>unknown_opt.err; rc=$?
  if [ -n "$cmd" ]; then want="unknown option '$opt' of '$cmd'"; else want="unknown option '$opt' (options go after the command"; fi
  [ "$rc" = 2 ] && grep -qF "$want" unknown_opt.err && ok "cbd $line: exit 2, $(cat unknown_opt.err)" ||
    bad "cbd $line: exit $rc, $(cat unknown_opt.err)"
done
# After "--" a word is no option: CLI11's own message stands.
"$CBD" map --source octa.off -- --bogus >/dev/null 2>dashdash.err; rc=$?
[ "$rc" = 2 ] && ! grep -q "unknown option" dashdash.err && grep -q "is required" dashdash.err &&
  ok "a word after --: exit 2, $(cat dashdash.err)" || bad "a word after --: exit $rc, $(cat dashdash.err)"
# sample-anchors has no --json: naming one is the error, and no report is written.
rm -f sample_report.json; "$CBD" sample-anchors -m octa.off -n 3 -o s.pp --json sample_report.json >/dev/null 2>sample_json.err; rc=$?
[ "$rc" = 2 ] && [ ! -e sample_report.json ] && [ ! -e s.pp ] && grep -q "unknown option '--json' of 'sample-anchors'" sample_json.err &&
  ok "sample-anchors --json: exit 2, no report" || bad "sample-anchors --json: exit $rc, $(ls sample_report.json 2>&1), $(cat sample_json.err)"
"$CBD" check --source octa.off --target octa.off "${P[@]}" --snap-tolerance nan >/dev/null 2>nan_tol.err; rc=$?
[ "$rc" = 2 ] && grep -q -- "--snap-tolerance: 'nan' is not a number in \[0, 1\]" nan_tol.err &&
  ok "--snap-tolerance nan: exit 2, $(cat nan_tol.err)" || bad "--snap-tolerance nan: exit $rc, $(cat nan_tol.err)"
"$CBD" layout --source octa.off --source-anchors octa.txt -o e1_out --single-edge-node --min-edge-nodes 5 >/dev/null 2>e1b.err; rc=$?
[ "$rc" = 2 ] && grep -q "excludes" e1b.err && [ ! -e e1_out ] &&
  ok "--single-edge-node with --min-edge-nodes: exit 2, $(cat e1b.err)" || bad "--single-edge-node with --min-edge-nodes: exit $rc, $(cat e1b.err)"
"$CBD" layout --source octa.off --source-anchors octa.txt -o flip_out --flip-paths >/dev/null 2>flipnt.err; rc=$?
[ "$rc" = 2 ] && grep -q -- "--flip-paths requires --target" flipnt.err && [ ! -e flip_out ] &&
  ok "--flip-paths without a target: exit 2, $(cat flipnt.err)" || bad "--flip-paths without a target: exit $rc, $(cat flipnt.err)"
# Reports and anchors onto a device are written in place: a rename over /dev/null would replace
# it with a file (as root).
"$CBD" check --source octa.off --target octa.off "${P[@]}" --json /dev/null >/dev/null 2>&1; rc=$?
[ "$rc" = 0 ] && [ -c /dev/null ] && ok "--json /dev/null: exit 0, still a device" || bad "--json /dev/null: exit $rc, $(ls -l /dev/null)"
# A command line that does not parse still writes the JSON report it names, but never onto
# another argument (which may be an input).
"$CBD" check --source octa.off --target octa.off "${P[@]}" --snap-tolerance nan --json parse_err.json >/dev/null 2>&1; rc=$?
[ "$rc" = 2 ] && python3 -c "import json,sys; j=json.load(open('parse_err.json')); sys.exit(not (j['status'] == 'invalid_argument' and 'snap-tolerance' in j['message']))" &&
  ok "parse error: exit 2, the JSON report says why" || bad "parse error: exit $rc, report: $(cat parse_err.json 2>&1)"
cp octa.off octa_keep.off
"$CBD" check --source octa_keep.off --target octa.off --frobnicate --json octa_keep.off >/dev/null 2>&1
cmp -s octa.off octa_keep.off && ok "parse error: no report onto an input" || bad "parse error: the report replaced an input"
echo '{"name": "mine"}' > not_a_report.json
"$CBD" check --source octa.off --frobnicate --json not_a_report.json >/dev/null 2>&1
grep -q mine not_a_report.json && ok "parse error: no report onto a JSON file that is not one" ||
  bad "parse error: a JSON file that is not a report was replaced"
"$CBD" chek --json=unknown_cmd.json >/dev/null 2>&1; rc=$?
[ "$rc" = 2 ] && grep -q "unknown command 'chek'" unknown_cmd.json && ok "unknown command: the JSON report says so" ||
  bad "unknown command: exit $rc, report: $(cat unknown_cmd.json 2>&1)"
# An OFF file with a face more than its header counts is read as counted, with a warning.
{ cat octa.off; echo "3 0 2 4"; } > long.off
expect long_off             ok                   -- --source long.off --target octa.off "${P[@]}"
grep -q "warning: 'long.off': 1 line after the header's 6 vertices and 8 faces were not read" long_off.out ||
  bad "long OFF: no warning in $(cat long_off.out)"
grep -q "'long.off': 'long.off'" long_off.out && bad "long OFF: the file is named twice in $(cat long_off.out)"
# The single-surface layout passes the same warning on, naming the file once.
"$CBD" layout --source long.off --source-anchors octa.txt -o long_layout >/dev/null 2>long_layout.err; rc=$?
[ "$rc" = 0 ] && grep -q "cbd: warning: 'long.off': 1 line after" long_layout.err &&
  ! grep -q "'long.off': 'long.off'" long_layout.err &&
  ok "long OFF in a single layout: $(head -1 long_layout.err)" || bad "long OFF in a single layout: exit $rc, $(cat long_layout.err)"
python3 -c "import json,sys; w=json.load(open('long_off.json'))['source']['warnings']; sys.exit(not (len(w) == 1 and 'not read' in w[0]))" ||
  bad "long OFF: no warning in the JSON: $(cat long_off.json)"
# A folder as mesh, and a .pp whose points are all unchecked, are named as such.
expect folder_mesh          file_not_found       -- --source . --target octa.off "${P[@]}"
grep -q "is a folder" folder_mesh.err || bad "folder as mesh: $(cat folder_mesh.err)"
# An empty anchor file: no anchors, not a name mismatch.
: > empty_anchors.txt
expect empty_anchors        too_few_anchors      -- --source octa.off --target octa.off --source-anchors empty_anchors.txt --target-anchors octa.txt
# Names that are not UTF-8 (Latin-1 bytes): the JSON report is still written and valid.
sed 's/^xp /xp\xe9 /' octa.txt > latin1.txt
expect latin1_names         ok                   -- --source octa.off --target octa.off --source-anchors latin1.txt --target-anchors latin1.txt
# A named pipe as anchors: refused at once (opening it would wait for a writer).
rm -f pipe.pp; mkfifo pipe.pp
timeout 20 "$CBD" check --source octa.off --target octa.off --source-anchors pipe.pp --target-anchors octa.txt >/dev/null 2>pipe.err; rc=$?
[ "$rc" = "$(code_of file_not_found)" ] && grep -q "pipe.pp': is not a regular file" pipe.err &&
  ok "a named pipe as anchors: exit $rc, $(cat pipe.err)" || bad "a named pipe as anchors: exit $rc, $(cat pipe.err)"
printf '<PickedPoints>\n<point x="1" y="0" z="0" active="0" name="xp"/>\n<point x="-1" y="0" z="0" active="0" name="xm"/>\n</PickedPoints>\n' > inactive.pp
expect all_inactive         too_few_anchors      -- --source octa.off --target octa.off --source-anchors octa.txt --target-anchors inactive.pp
grep -q "all 2 points are inactive" all_inactive.err || bad "all inactive: $(cat all_inactive.err)"

# Inputs untouched by any run.
[ "$(md5sum < octa.off)" = "$(md5sum < "$WORK/octa.off")" ] || bad "octa.off modified"

# --- the bundled real example --------------------------------------------------------
if [ -f "$MESHES/cow.off" ] && [ -f "$EXAMPLES/cow_picked_points.pp" ]; then
  sum_before=$(md5sum "$MESHES/cow.off" "$MESHES/bull.off" "$EXAMPLES"/*.pp)
  expect cow_bull ok -- --source "$MESHES/cow.off" --target "$MESHES/bull.off" \
    --source-anchors "$EXAMPLES/cow_picked_points.pp" --target-anchors "$EXAMPLES/bull_picked_points.pp"
  n=$(python3 -c "import json;d=json.load(open('cow_bull.json'));print(d['source']['anchors'], d['source']['genus'], d['target']['genus'], d['source']['vertices'])")
  set -- $n
  [ "$1" -ge 20 ] && [ "$2" = 0 ] && [ "$3" = 0 ] && [ "$4" = 2904 ] && ok "cow/bull report: $n" || bad "cow/bull report: $n"
  # --json -: the report alone on stdout (it parses), the log on stderr.
  "$CBD" check --source "$MESHES/cow.off" --target "$MESHES/bull.off" \
    --source-anchors "$EXAMPLES/cow_picked_points.pp" --target-anchors "$EXAMPLES/bull_picked_points.pp" \
    --json - >stdout.json 2>stdout.err; rc=$?
  st=$(python3 -c "import json;print(json.load(open('stdout.json'))['status'])" 2>/dev/null)
  if [ "$rc" = 0 ] && [ "$st" = ok ] && grep -q "pair can be processed" stdout.err; then
    ok "--json -: JSON alone on stdout, log on stderr"
  else
    bad "--json -: exit $rc, status '$st'"
  fi
  # The source layout of the bundled example: outputs exist, counts are those of a triangulation.
  "$CBD" layout --source "$MESHES/cow.off" --source-anchors "$EXAMPLES/cow_picked_points.pp" --out layout_cow \
    --json layout_cow.json >/dev/null 2>layout.err; rc=$?
  counts=$(python3 -c "import json;d=json.load(open('layout_cow.json'));l=d['layout'];print(d['status'],d['source']['anchors'],l['edges'],l['patches'])" 2>/dev/null)
  set -- $counts
  if [ "$rc" = 0 ] && [ "${1:-}" = ok ] && [ "$3" = $((3 * ($2 - 2))) ] && [ "$4" = $((2 * ($2 - 2))) ] \
     && [ -s layout_cow/layout.ply ] && [ -s layout_cow/paths.ply ] && [ -s layout_cow/clusters.ply ]; then
    ok "cbd layout on the cow: $counts"
  else
    bad "cbd layout on the cow: exit $rc, $counts $(cat layout.err)"
  fi
  "$CBD" layout --source "$MESHES/cow.off" --source-anchors "$EXAMPLES/cow_picked_points.pp" --out /proc/nope \
    >/dev/null 2>&1; rc=$?
  [ "$rc" = "$(code_of output_error)" ] && ok "cbd layout into an unwritable folder: exit $rc" || bad "unwritable layout folder: exit $rc"
  # Outputs that cannot be written are refused before the computation (nothing is written):
  # a report under a plain file, an output folder that is a file.
  touch plain_file
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out early_json/a/b \
    --json plain_file/r.json >early_json.out 2>early_json.err; rc=$?
  [ "$rc" = "$(code_of output_error)" ] && grep -q "cannot write JSON report 'plain_file/r.json'" early_json.err &&
    [ ! -e early_json ] && ! grep -q "^map" early_json.out &&
    ok "map with --json under a plain file: exit $rc before computing" ||
    bad "map with --json under a plain file: exit $rc, $(ls early_json 2>&1) $(cat early_json.err)"
  "$CBD" layout --source "$MESHES/cow.off" --source-anchors "$EXAMPLES/cow_picked_points.pp" --out plain_file \
    --json out_is_file.json >/dev/null 2>out_is_file.err; rc=$?
  "$CBD" layout --source "$MESHES/cow.off" --source-anchors "$EXAMPLES/cow_picked_points.pp" --out plain_file \
    --json plain_file/r.json >/dev/null 2>out_is_file2.err
  grep -q "output folder 'plain_file' is a file" out_is_file2.err ||
    bad "layout --out onto a file, report inside it: the folder error is not told: $(cat out_is_file2.err)"
  [ "$rc" = "$(code_of output_error)" ] && grep -q "output folder 'plain_file' is a file" out_is_file.err &&
    grep -q '"status": "output_error"' out_is_file.json && [ ! -s plain_file ] &&
    ok "layout --out onto a file: exit $rc, the report says why" || bad "layout --out onto a file: exit $rc, $(cat out_is_file.err)"
  # The main job: the bull mapped onto the cow, both methods.
  for method in voronoi greedy; do
    "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
      --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --method $method \
      --out map_$method --morph 3 --json map_$method.json >/dev/null 2>map.err; rc=$?
    res=$(python3 - "$method" <<'PY'
import json, sys
m = sys.argv[1]
d = json.load(open('map_%s.json' % m))
def vcount(p):
    with open(p, 'rb') as f:
        for line in f:
            line = line.decode().strip()
            if line.startswith('element vertex'): return int(line.split()[-1])
            if line == 'end_header': return -1
met = d['metrics']
ok = (d['status'] == 'ok' and vcount('map_%s/mst.ply' % m) == 6200 and vcount('map_%s/mts.ply' % m) == 2904
      and met['e_l2'] >= 1.0 and met['e_ang'] >= 0.0 and met['e_l2_inverse'] >= 1.0
      and all(k in d['timing_s'] for k in ('voronoi', 'source_layout', 'target_layout', 'parameterization', 'total'))
      and d['layout']['edges'] == 3 * (28 - 2) and d['layout']['patches'] == 2 * (28 - 2))
# Straightening (on by default, both surfaces) and the composed map's metrics.
st = d.get('straighten', {})
ok = ok and st.get('rounds') == 2 and st.get('failed') is False and 'straighten' in d['timing_s']
ok = ok and all(0 < st[s]['straightened'] <= d['layout']['edges'] and st[s]['splits'] > 0 for s in ('source', 'target'))
ok = ok and met['composed']['e_l2'] >= 1.0 and met['composed']['flipped'] >= 0
lines = open('map_%s/correspondence.txt' % m).read().splitlines()
ok = ok and len(lines) == 6201
print('ok' if ok else 'bad', 'E_L2 %.3f E_ang %.3f flipped %d' % (met['e_l2'], met['e_ang'], met['flipped']))
PY
)
    if [ "$rc" = 0 ] && [ "${res%% *}" = ok ] && [ -s map_$method/morph_002.ply ] && [ -s map_$method/source/layout.ply ]; then
      ok "cbd map bull -> cow ($method): $res"
    else
      bad "cbd map bull -> cow ($method): exit $rc, $res $(cat map.err)"
    fi
  done
  # --flip-paths: the greedy method's path flipping on the Voronoi layouts; the log says how many
  # edges were replaced, as the JSON does, and the layouts differ from the default's.
  "$CBD" layout --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out layout_unflipped >/dev/null 2>&1
  "$CBD" layout --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --flip-paths \
    --out layout_flipped --json layout_flipped.json >layout_flipped.out 2>&1; rc=$?
  flips=$(python3 -c "import json;d=json.load(open('layout_flipped.json'));print(d['layout']['flips'] if d['status'] == 'ok' else -1)" 2>/dev/null)
  if [ "$rc" = 0 ] && [ "${flips:-0}" -gt 0 ] && grep -qF "path flipping: $flips edges replaced" layout_flipped.out &&
     [ -s layout_unflipped/target/paths.ply ] && ! cmp -s layout_flipped/target/paths.ply layout_unflipped/target/paths.ply; then
    ok "cbd layout --flip-paths: $flips edges replaced"
  else
    bad "cbd layout --flip-paths: exit $rc, flips '$flips', $(grep flipping layout_flipped.out)"
  fi
  # --straighten 0: the paths as traced, no straighten report, other paths than the default's.
  # With --smooth 3: its sweeps reported in the log as in the JSON.
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --straighten 0 --smooth 3 \
    --out map_traced --json map_traced.json >map_traced.out 2>&1; rc=$?
  res=$(python3 -c "import json;d=json.load(open('map_traced.json'));print(d['status'], 'straighten' in d, d['layout']['edges'])" 2>/dev/null)
  if [ "$rc" = 0 ] && [ "$res" = "ok False 78" ] && ! cmp -s map_traced/target/paths.ply map_voronoi/target/paths.ply; then
    ok "cbd map --straighten 0: paths as traced ($res)"
  else
    bad "cbd map --straighten 0: exit $rc, $res"
  fi
  smooth=$(python3 -c "import json;s=json.load(open('map_traced.json'))['smoothing'];print('smooth  3 sweeps over M_st: %d moves kept, %d rejected' % (s['moves'], s['rejected']))" 2>/dev/null)
  if [ -n "$smooth" ] && grep -qF "$smooth" map_traced.out; then
    ok "cbd map --smooth 3: $(grep '^smooth' map_traced.out)"
  else
    bad "cbd map --smooth 3: log line missing or unlike the JSON ('$smooth'): $(grep '^smooth' map_traced.out)"
  fi
  # Determinism: the same run again gives byte-identical files.
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out map_again --morph 3 >/dev/null 2>&1
  same=1
  for f in mst.ply mts.ply correspondence.txt morph_001.ply source/layout.ply target/paths.ply; do
    cmp -s "map_voronoi/$f" "map_again/$f" || same=0
  done
  [ "$same" = 1 ] && ok "cbd map twice: byte-identical outputs" || bad "cbd map twice: outputs differ"
  # Ctrl-C half way (once the output folder exists, i.e. the input was valid and the
  # computation began): the status cancelled with its exit code, no output file, no folder.
  rm -rf interrupted interrupted.json
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out interrupted/deep \
    --json interrupted.json >/dev/null 2>interrupted.err &
  pid=$!
  for _ in $(seq 1 600); do [ -d interrupted/deep ] && break; sleep 0.05; done
  sleep 1  # into the untangling, the longest stage
  kill -INT "$pid"; wait "$pid"; rc=$?
  st=$(python3 -c "import json;print(json.load(open('interrupted.json'))['status'])" 2>/dev/null)
  if [ "$rc" = "$(code_of cancelled)" ] && [ "$st" = cancelled ] && [ ! -e interrupted ] &&
     grep -q "nothing was written" interrupted.err; then
    ok "cbd map interrupted half way: exit $rc, no output, $(tail -1 interrupted.err)"
  else
    bad "cbd map interrupted half way: exit $rc, status '$st', $(ls -R interrupted 2>&1 | head -3), $(tail -1 interrupted.err)"
  fi
  # A shorter morph into the same folder leaves one sequence: the earlier run's last frame goes.
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out map_again --morph 2 \
    >morph2.out 2>&1; rc=$?
  [ "$rc" = 0 ] && [ -s map_again/morph_001.ply ] && [ ! -e map_again/morph_002.ply ] &&
    grep -q "removed 1 morph frame after morph_001.ply" morph2.out &&
    ! cmp -s map_again/morph_001.ply map_voronoi/morph_001.ply &&
    ok "cbd map --morph 2 over --morph 3: $(grep removed morph2.out)" ||
    bad "cbd map --morph 2 over --morph 3: exit $rc, $(ls map_again) $(tail -2 morph2.out)"
  # A frame the shorter sequence would remove is refused as an input (it would be deleted).
  cp map_voronoi/morph_002.ply map_voronoi/morph_003.ply
  "$CBD" map --source map_voronoi/morph_003.ply --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out map_voronoi --morph 2 \
    >/dev/null 2>stale_input.err; rc=$?
  [ "$rc" = 2 ] && [ -s map_voronoi/morph_003.ply ] && grep -q "overwrite the input" stale_input.err &&
    ok "a stale morph frame as input: refused, kept" || bad "a stale morph frame as input: exit $rc, $(cat stale_input.err)"
  # Per-vertex texture coordinates of the target carried onto mst.ply (and the source's onto
  # mts.ply): the pair as PLY with u, v a linear function of x, y; each image lies on the other
  # surface, so its interpolated u, v must be that function of its own position.
  python3 - "$MESHES" <<'PY'
import sys
def ply(name):
    lines = [l for l in open('%s/%s.off' % (sys.argv[1], name)) if l.strip() and not l.startswith('#')]
    nv, nf = map(int, lines[1].split()[:2])
    v = [list(map(float, l.split()[:3])) for l in lines[2:2 + nv]]
    lo = [min(p[k] for p in v) for k in range(2)]; hi = [max(p[k] for p in v) for k in range(2)]
    with open('%s_uv.ply' % name, 'w') as o:
        o.write('ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n'
                'property float texture_u\nproperty float texture_v\nelement face %d\n'
                'property list uchar int vertex_indices\nend_header\n' % (nv, nf))
        for p in v:
            o.write('%.17g %.17g %.17g %.8f %.8f\n' % (p[0], p[1], p[2], (p[0] - lo[0]) / (hi[0] - lo[0]), (p[1] - lo[1]) / (hi[1] - lo[1])))
        for l in lines[2 + nv:2 + nv + nf]: o.write('3 ' + ' '.join(l.split()[1:4]) + '\n')
ply('bull'); ply('cow')
PY
  "$CBD" map --source bull_uv.ply --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target cow_uv.ply --target-anchors "$EXAMPLES/cow_picked_points.pp" --out map_uv >/dev/null 2>map_uv.err; rc=$?
  res=$(python3 - "$MESHES" <<'PY' 2>&1
import struct, sys
def worst(mesh, other):
    d = open(mesh, 'rb').read()
    head = d[:d.index(b'end_header\n')].decode().split('\n')
    props = [l.split()[-1] for l in head if l.startswith('property') and 'list' not in l][:5]
    if props != ['x', 'y', 'z', 'texture_u', 'texture_v']: return 'properties %s' % props
    nv = int([l for l in head if l.startswith('element vertex')][0].split()[-1])
    lines = [l for l in open('%s/%s.off' % (sys.argv[1], other)) if l.strip() and not l.startswith('#')]
    v = [list(map(float, l.split()[:3])) for l in lines[2:2 + int(lines[1].split()[0])]]
    lo = [min(p[k] for p in v) for k in range(2)]; hi = [max(p[k] for p in v) for k in range(2)]
    off, err = d.index(b'end_header\n') + len(b'end_header\n'), 0.0
    for _ in range(nv):
        x, y, z, u, w = struct.unpack_from('<dddff', d, off); off += 32
        err = max(err, abs(u - (x - lo[0]) / (hi[0] - lo[0])), abs(w - (y - lo[1]) / (hi[1] - lo[1])))
    return err
a, b = worst('map_uv/mst.ply', 'cow'), worst('map_uv/mts.ply', 'bull')
print('ok' if isinstance(a, float) and isinstance(b, float) and max(a, b) < 1e-5 else 'bad', 'worst u,v error', a, b)
PY
)
  if [ "$rc" = 0 ] && [ "${res%% *}" = ok ]; then
    ok "cbd map carries texture coordinates onto mst.ply and mts.ply: $res"
  else
    bad "cbd map texture coordinates: exit $rc, $res $(cat map_uv.err)"
  fi
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" --out /proc/nope >/dev/null 2>&1; rc=$?
  [ "$rc" = "$(code_of output_error)" ] && ok "cbd map into an unwritable folder: exit $rc" || bad "unwritable map folder: exit $rc"
  # sample-anchors: N points on the mesh; a --seed that is no vertex is refused, nothing written.
  "$CBD" sample-anchors -m "$MESHES/cow.off" -n 5 --seed 7 -o sampled.pp >/dev/null 2>&1; rc=$?
  n=$(grep -c '<point ' sampled.pp 2>/dev/null)
  [ "$rc" = 0 ] && [ "$n" = 5 ] && ok "cbd sample-anchors: 5 points" || bad "cbd sample-anchors: exit $rc, $n points"
  "$CBD" sample-anchors -m "$MESHES/cow.off" -n 5 --seed 2904 -o badseed.pp >/dev/null 2>badseed.err; rc=$?
  if [ "$rc" = "$(code_of invalid_argument)" ] && [ ! -e badseed.pp ] && grep -q "0..2903" badseed.err; then
    ok "cbd sample-anchors --seed out of range: exit $rc, $(cat badseed.err)"
  else
    bad "cbd sample-anchors --seed out of range: exit $rc, $(cat badseed.err)"
  fi
  # No output may replace an input: --json on an anchors file, sample-anchors onto its mesh, an
  # output folder holding an input under a name cbd writes; a --json naming a folder fails.
  cp "$MESHES/cow.off" clobber_cow.off; cp "$EXAMPLES/cow_picked_points.pp" clobber_cow.pp
  mkdir -p clobber_out jsondir; cp "$MESHES/bull.off" clobber_out/mst.ply
  sums=$(md5sum clobber_cow.off clobber_cow.pp clobber_out/mst.ply)
  "$CBD" check -s clobber_cow.off -t "$MESHES/bull.off" --source-anchors clobber_cow.pp \
    --target-anchors "$EXAMPLES/bull_picked_points.pp" --json clobber_cow.pp >/dev/null 2>clobber1.err; rc1=$?
  "$CBD" sample-anchors -m clobber_cow.off -n 5 -o clobber_cow.off >/dev/null 2>clobber2.err; rc2=$?
  "$CBD" map -s clobber_out/mst.ply -t "$MESHES/cow.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target-anchors "$EXAMPLES/cow_picked_points.pp" -o clobber_out >/dev/null 2>clobber3.err; rc3=$?
  "$CBD" check -s "$MESHES/cow.off" -t "$MESHES/bull.off" --source-anchors "$EXAMPLES/cow_picked_points.pp" \
    --target-anchors "$EXAMPLES/bull_picked_points.pp" --json jsondir >/dev/null 2>clobber4.err; rc4=$?
  # The report onto one of the command's own outputs: refused before any work.
  "$CBD" map --source "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" \
    --target "$MESHES/cow.off" --target-anchors "$EXAMPLES/cow_picked_points.pp" -o json_out --json json_out/mst.ply \
    >/dev/null 2>json_self.err; rc=$?
  [ "$rc" = 2 ] && grep -q "is one of the files the command writes" json_self.err && [ ! -e json_out/mst.ply ] &&
    ok "--json onto the command's own mst.ply refused: $(cat json_self.err)" || bad "--json onto mst.ply: exit $rc, $(cat json_self.err)"
  # More anchors asked of sample-anchors than the mesh has vertices: all of them, with a warning.
  "$CBD" sample-anchors -m "$MESHES/cow.off" -n 3000 -o all_cow.pp >/dev/null 2>all_cow.err; rc=$?
  n=$(grep -c '<point ' all_cow.pp 2>/dev/null)
  [ "$rc" = 0 ] && [ "$n" = 2904 ] && grep -q "2904 anchors written, not 3000" all_cow.err &&
    ok "sample-anchors -n 3000 on cow: $n points, $(cat all_cow.err)" || bad "sample-anchors -n 3000: exit $rc, $n points, $(cat all_cow.err)"
  # A pair layout writes OUT/source/ and OUT/target/, a single-surface layout OUT itself.
  mkdir -p clobber_lay/target; cp "$MESHES/cow.off" clobber_lay/target/paths.ply; cp "$MESHES/cow.off" clobber_lay/clusters.ply
  sums="$sums $(md5sum clobber_lay/target/paths.ply clobber_lay/clusters.ply)"
  "$CBD" layout -s "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" -t clobber_lay/target/paths.ply \
    --target-anchors "$EXAMPLES/cow_picked_points.pp" -o clobber_lay >/dev/null 2>clobber5.err; rc5=$?
  "$CBD" layout -s clobber_lay/clusters.ply --source-anchors "$EXAMPLES/cow_picked_points.pp" \
    -o clobber_lay >/dev/null 2>clobber6.err; rc6=$?
  # An input reached through a symlink, and an input where only the other kind of layout writes
  # (a pair layout does not write OUT/layout.ply): the first refused, the second accepted.
  ln -sf "$PWD/clobber_lay/target/paths.ply" clobber_link.ply
  "$CBD" layout -s "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" -t clobber_link.ply \
    --target-anchors "$EXAMPLES/cow_picked_points.pp" -o clobber_lay >/dev/null 2>clobber7.err; rc7=$?
  mkdir -p clobber_ok
  python3 - "$MESHES/cow.off" clobber_ok/layout.ply <<'PY'
import sys
lines = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
nv, nf = int(lines[1][0]), int(lines[1][1])
with open(sys.argv[2], 'w') as f:
    f.write('ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n'
            'element face %d\nproperty list uchar int vertex_indices\nend_header\n' % (nv, nf))
    for l in lines[2:2 + nv]: f.write(' '.join(l[:3]) + '\n')
    for l in lines[2 + nv:2 + nv + nf]: f.write(' '.join(l[:4]) + '\n')
PY
  sum_ok=$(md5sum < clobber_ok/layout.ply)
  "$CBD" layout -s "$MESHES/bull.off" --source-anchors "$EXAMPLES/bull_picked_points.pp" -t clobber_ok/layout.ply \
    --target-anchors "$EXAMPLES/cow_picked_points.pp" -o clobber_ok >/dev/null 2>clobber8.err; rc8=$?
  want=$(code_of invalid_argument)
  if [ "$rc7" = "$want" ] && grep -q "overwrite the input" clobber7.err && [ "$rc8" = 0 ] && \
     [ -s clobber_ok/target/layout.ply ] && [ "$sum_ok" = "$(md5sum < clobber_ok/layout.ply)" ]; then
    ok "an input through a symlink refused; an input beside a pair layout's folders accepted and unchanged"
  else
    bad "clobber through a symlink / beside a pair layout: exits $rc7 $rc8: $(cat clobber7.err clobber8.err)"
  fi
  if [ "$rc5 $rc6" = "$want $want" ] && grep -q "overwrite the input" clobber5.err && grep -q "overwrite the input" clobber6.err; then
    ok "layouts onto their inputs refused (pair: OUT/target/paths.ply, single: OUT/clusters.ply)"
  else
    bad "layouts onto their inputs: exits $rc5 $rc6: $(cat clobber5.err clobber6.err)"
  fi
  if [ "$rc1 $rc2 $rc3" = "$want $want $want" ] && [ "$rc4" = "$(code_of output_error)" ] && \
     [ "$sums" = "$(md5sum clobber_cow.off clobber_cow.pp clobber_out/mst.ply) $(md5sum clobber_lay/target/paths.ply clobber_lay/clusters.ply)" ] && \
     grep -q "overwrite the input" clobber1.err && grep -q "overwrite the input" clobber3.err; then
    ok "outputs onto inputs refused (exit $rc1, $rc2, $rc3), --json onto a folder fails (exit $rc4), inputs unchanged"
  else
    bad "outputs onto inputs: exits $rc1 $rc2 $rc3 $rc4: $(cat clobber1.err clobber2.err clobber3.err clobber4.err)"
  fi
  # No run above changed an input file.
  [ "$sum_before" = "$(md5sum "$MESHES/cow.off" "$MESHES/bull.off" "$EXAMPLES"/*.pp)" ] && ok "real inputs untouched" || bad "real inputs modified"
else
  bad "bundled example missing: run scripts/setup.sh (cow.off) / examples/*.pp"
fi

# README's exit-code table is the output of `cbd exit-codes`.
if diff <(sed -n '/exit-codes:begin/,/exit-codes:end/p' "$ROOT/README.md" | sed '1,2d;$d' | sed '$d') <("$CBD" exit-codes) >/dev/null; then
  ok "README exit-code table matches cbd exit-codes"
else
  bad "README exit-code table differs from cbd exit-codes"
fi

echo "$passes passed, $fails failed"
[ "$fails" = 0 ]
