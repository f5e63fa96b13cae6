#!/usr/bin/env bash
# The lowstretch tool: exit codes, one line on stderr, and no output file unless it succeeded.
# Usage: tool_exit_codes.sh path/to/lowstretch [shared-meshes-folder]
set -u
tool=$1
shared=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
check() {  # check NAME EXPECTED-EXIT ARGS...
  local name=$1 want=$2
  shift 2
  rm -f "$work/out.ply" "$work/out.obj" "$work/out.obj.mtl" "$work/uv.svg"
  "$tool" "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  local ok=1
  [ "$got" = "$want" ] || { echo "FAIL $name: exit $got, wanted $want"; ok=0; }
  if [ "$want" != 0 ]; then
    [ "$(wc -l <"$work/stderr")" -ge 1 ] || { echo "FAIL $name: nothing on stderr"; ok=0; }
    ls "$work"/out.* "$work/uv.svg" >/dev/null 2>&1 && { echo "FAIL $name: an output file was created"; ok=0; }
  fi
  if [ $ok = 1 ]; then passed=$((passed + 1)); echo "ok   $name"; else failed=$((failed + 1)); cat "$work/stderr"; fi
}

# A small disk: a 3x3 grid as OFF.
cat >"$work/disk.off" <<'MESH'
OFF
9 8 0
0 0 0
1 0 0
2 0 0.5
0 1 0
1 1 1
2 1 0
0 2 0
1 2 0.3
2 2 0
3 0 1 4
3 0 4 3
3 1 2 5
3 1 5 4
3 3 4 7
3 3 7 6
3 4 5 8
3 4 8 7
MESH
# Two separate triangles: two components.
cat >"$work/two.off" <<'MESH'
OFF
6 2 0
0 0 0
1 0 0
0 1 0
5 0 0
6 0 0
5 1 0
3 0 1 2
3 3 4 5
MESH
printf 'OFF\n99999999 5 0\n0 0 0\n' >"$work/huge.off"
: >"$work/empty.off"
printf 'v 0 0 0\nv 1 0 0\nf 1 2 7\n' >"$work/badindex.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan inf 1\nf 1 2 3\n' >"$work/unused_nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >"$work/used_nan.obj"

check "good disk to PLY" 0 "$work/disk.off" -o "$work/out.ply" --svg "$work/uv.svg"
[ -s "$work/out.ply" ] && [ -s "$work/uv.svg" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL good disk: no PLY or SVG"; }
check "good disk to OBJ" 0 "$work/disk.off" -o "$work/out.obj"
grep -q '^vt ' "$work/out.obj" && grep -q 'map_Kd' "$work/out.obj.mtl" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL OBJ: no vt or no texture in the .mtl"; }
check "json is one object" 0 "$work/disk.off" --json --boundary circle --max-passes 2
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert {"vertices","faces","boundary","weights","exponent","passes","chosen_pass","seconds_total"} <= d.keys(); assert all({"pass","l2_stretch","linf_stretch","edge_distortion","angle_distortion","area_distortion","flipped","degenerate","seconds"} <= p.keys() for p in d["passes"])' "$work/stdout" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL json keys"; }
check "two components rejected when disk only" 3 "$work/two.off" --non-disk reject -o "$work/out.ply"
grep -q "2 connected components" "$work/stderr" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL message"; }
grep -q -- "--non-disk charts" "$work/stderr" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL message names --non-disk charts"; }
check "two components as charts by default" 0 "$work/two.off" -o "$work/out.obj" --svg "$work/uv.svg" --json
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["chart_count"] == 2 and d["input_is_disk"] is False and d["seam_length"] == 0 and d["layout"]["flipped"] == 0 and 0 < d["coverage"] <= 1 and len(d["charts"]) == 2' "$work/stdout" \
  && [ "$(grep -c '^vt ' "$work/out.obj")" -ge 6 ] && [ -s "$work/uv.svg" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL charts: json, vt or svg"; }
check "bad --non-disk value" 1 "$work/two.off" --non-disk maybe -o "$work/out.ply"
check "bad --non-disk value after --atlas" 1 "$work/two.off" --atlas --non-disk bogus -o "$work/out.ply"
check "disk as an atlas" 0 "$work/disk.off" --atlas --max-stretch 1.05 -o "$work/out.obj" --json
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["non_disk"] == "atlas" and d["max_stretch"] == 1.05 and d["layout"]["flipped"] == 0 and abs(d["efficiency"] - d["coverage"] / d["layout"]["l2_stretch"] ** 2) < 1e-6 and d["max_chart_stretch"] == max(c["l2_stretch"] for c in d["charts"])' "$work/stdout" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL atlas json"; }
check "max stretch below 1" 1 "$work/disk.off" --atlas --max-stretch 0.9 -o "$work/out.ply"
grep -q -- "--max-stretch must be at least 1, got 0.9" "$work/stderr" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL message names --max-stretch"; }
check "huge header refused" 2 "$work/huge.off" -o "$work/out.ply"
check "empty file refused" 2 "$work/empty.off" -o "$work/out.ply"
check "bad OBJ index refused" 2 "$work/badindex.obj" -o "$work/out.ply"
check "unused NaN vertex in OBJ ignored" 0 "$work/unused_nan.obj" -o "$work/out.ply"
check "used NaN vertex in OBJ named" 3 "$work/used_nan.obj" -o "$work/out.ply"
check "missing file" 2 "$work/nothing.off" -o "$work/out.ply"
check "bad option" 1 "$work/disk.off" --boundary triangle -o "$work/out.ply"
check "bad exponent" 1 "$work/disk.off" --exponent 2 -o "$work/out.ply"
grep -q -- "--exponent must be in (0, 1\], got 2" "$work/stderr" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL message names --exponent"; }
check "too many passes" 1 "$work/disk.off" --max-passes 1001 -o "$work/out.ply"
grep -q -- "--max-passes must be from 0 to 1000, got 1001" "$work/stderr" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL message names --max-passes"; }
check "bad solver" 1 "$work/disk.off" --solver cg -o "$work/out.ply"
check "direct solver" 0 "$work/disk.off" --solver direct -o "$work/out.ply"
# Every bad value of every option exits 1 with nothing written (the option table, CLI11, the core).
for bad in "--weights cotan" "--exponent 0" "--exponent nan" "--exponent abc" "--max-passes -1" "--max-passes 2.5" \
           "--max-stretch inf" "--texture-size 4" "--texture-size 1e9" "--gutter 0.1" "--gutter 200" "--max-charts 0" \
           "--non-disk" "--boundary" "--atlas --non-disk reject" "--frobnicate" "--refine=maybe"; do
  # shellcheck disable=SC2086
  check "bad value: $bad" 1 "$work/disk.off" $bad -o "$work/out.ply"
done
check "no input" 1 -o "$work/out.ply"
check "two inputs" 1 "$work/disk.off" "$work/two.off" -o "$work/out.ply"
check "unwritable output" 4 "$work/disk.off" -o "$work/no/such/folder/out.ply"
# The pack stage alone: an atlas the tool wrote (OBJ, PLY) packed again at another size and gutter,
# its two charts kept; a mesh without texture coordinates refused, with what to do.
"$tool" "$work/two.off" -o "$work/atlas.obj" >/dev/null && "$tool" "$work/two.off" -o "$work/atlas.ply" >/dev/null
for atlas in atlas.obj atlas.ply; do
  check "repack $atlas" 0 "$work/$atlas" --repack --texture-size 256 --gutter 8 -o "$work/out.obj" --json
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["chart_count"] == 2 and d["texture_size"] == 256 and d["gutter"] == 8 and d["layout"]["flipped"] == 0 and d["layout"]["degenerate"] == 0 and list(d["stage_seconds"]) == ["charts from texture coordinates", "charts packed by outline", "valid as stored"]' "$work/stdout" \
    && python3 -c 'import sys; uv=[tuple(map(float, l.split()[1:3])) for l in open(sys.argv[1]) if l.startswith("vt ")]; g=8/256; assert uv and all(g*(1-1e-6) <= c <= 1-g*(1-1e-6) for p in uv for c in p)' "$work/out.obj" \
    && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL repack $atlas: json or UV outside the gutter"; }
done
check "repack without texture coordinates" 3 "$work/two.off" --repack -o "$work/out.obj"
grep -q "no atlas to pack again" "$work/stderr" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL repack message"; }
# An existing output stays untouched when the input is bad.
echo keep >"$work/keep.ply"
"$tool" "$work/two.off" --non-disk reject -o "$work/keep.ply" 2>/dev/null
[ "$(cat "$work/keep.ply")" = keep ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL existing output changed"; }

if [ -d "$shared/bad" ]; then
  for f in "$shared"/bad/* "$shared"/parse_errors/*; do
    case $f in */parse_errors/*) want=2 ;; *) want=3 ;; esac
    check "$(basename "$f") disk only" $want "$f" --non-disk reject -o "$work/out.ply"
  done
  # By default every one gets charts (non-manifold, misoriented and non-orientable ones cut open
  # for them).
  for f in "$shared"/bad/*; do
    check "$(basename "$f") by default" 0 "$f" -o "$work/out.ply"
  done
fi
echo "tool_exit_codes: $passed passed, $failed failed"
[ $failed = 0 ]
