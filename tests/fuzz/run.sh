#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for SECONDS (default 60):
# fuzz_read_off, fuzz_read_obj, fuzz_read_ply_ascii, fuzz_read_ply_binary, fuzz_parameterize.
# Prints per target the executions and the coverage (cov = edges, ft = features) of libFuzzer's
# final lines; exits non-zero if any target crashes, hangs (> 10 s on one input), leaks or runs
# out of memory (> 2 GB). Crashing inputs are kept in BUILD/artifacts/TARGET/.
#
# usage: tests/fuzz/run.sh [SECONDS] [TARGET...]
#   FUZZ_BUILD=folder   build folder (default: build-fuzz in the repository root)
#   FUZZ_PARALLEL=n     targets run at a time (default 1)
#   FUZZ_SHARED=folder  shared meshes for seeds (default: ../shared/meshes beside the repository)
# The corpus each run grows is kept in BUILD/corpus/TARGET/ and reused by the next run; the seeds
# are made afresh every time by make_seeds.py into BUILD/seeds/. A crash reproduces with
# BUILD/TARGET BUILD/artifacts/TARGET/crash-...
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
seconds="${1:-60}"
shift $(( $# > 0 ? 1 : 0 ))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_read_off fuzz_read_obj fuzz_read_ply_ascii fuzz_read_ply_binary fuzz_parameterize)
build="${FUZZ_BUILD:-$root/build-fuzz}"
parallel="${FUZZ_PARALLEL:-1}"
shared="${FUZZ_SHARED:-$root/../shared/meshes}"

cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER="${CXX:-clang++}" >/dev/null || exit 2
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}" >"$build/build.log" 2>&1 || { tail -50 "$build/build.log"; exit 2; }
python3 "$here/make_seeds.py" "$build/seeds" "$shared" || exit 2

seeds_of() {  # the seed folder of a target
  case "$1" in fuzz_read_*) echo "$build/seeds/${1#fuzz_read_}" ;; *) echo "$build/seeds/${1#fuzz_}" ;; esac
}
dict_of() {
  case "$1" in fuzz_read_off) echo "$here/off.dict" ;; fuzz_read_obj) echo "$here/obj.dict" ;;
    fuzz_read_ply_*) echo "$here/ply.dict" ;; *) echo "" ;; esac
}

run_one() {
  local t=$1 corpus="$build/corpus/$1" artifacts="$build/artifacts/$1/" log="$build/logs/$1.log" dict
  mkdir -p "$corpus" "$artifacts" "$build/logs" "$build/tmp"
  dict=$(dict_of "$t")
  # UBSan halts on its first report (the code is built with -fno-sanitize-recover=all).
  TMPDIR="$build/tmp" ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:print_stacktrace=1:allocator_may_return_null=1" \
  UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" \
  "$build/$t" "$corpus" "$(seeds_of "$t")" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=8192 -print_final_stats=1 -artifact_prefix="$artifacts" ${dict:+-dict="$dict"} >"$log" 2>&1
  echo $? >"$build/logs/$t.rc"
}

rm -f "$build"/logs/*.rc
running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$parallel" ]; then wait -n; running=$((running - 1)); fi
done
wait

status=0
printf '%-22s %12s %8s %8s %8s  %s\n' target execs cov ft corpus result
for t in "${targets[@]}"; do
  log="$build/logs/$t.log"
  rc=$(cat "$build/logs/$t.rc" 2>/dev/null || echo 99)
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -1 | awk '{print $2}')
  last=$(grep -E '^#[0-9]+' "$log" | grep -E 'cov: ' | tail -1)
  cov=$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.*ft: \([0-9]*\).*/\1/p' <<<"$last")
  files=$(find "$build/corpus/$t" -type f | wc -l)
  if [ "$rc" = 0 ]; then result=ok; else
    result="FAILED (exit $rc; $(grep -m1 -oE 'ERROR: [A-Za-z]+: [^ ]+( [^ ]+)?|runtime error: .*|Assertion .* failed|deadly signal|timeout|out-of-memory' "$log" | head -1)): see $log"
    status=1
  fi
  printf '%-22s %12s %8s %8s %8s  %s\n' "$t" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$files" "$result"
done
exit $status
