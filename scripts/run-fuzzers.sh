#!/usr/bin/env bash
# Runs every libFuzzer target of BUILD (configured with IMASIM_FUZZ=ON) for SECONDS each, two at
# a time, starting from the committed corpus (fuzz/corpus/TARGET, read only) plus what earlier
# runs in BUILD found (BUILD/fuzz-found/TARGET). A crash, a leak, a broken property or an input
# slower than 10 s fails the run and leaves the input in BUILD/fuzz-artifacts, with the
# command that reproduces it. Prints executions per second per target.
# Usage: scripts/run-fuzzers.sh BUILD SECONDS
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?build directory}
seconds=${2:?seconds per target}
targets=(scene_file input_script command_line mesh_obj mesh_stl mesh_ply mesh_gltf igtl_message
  input_stream point_csv)
mkdir -p "$build/fuzz-artifacts" "$build/fuzz-logs"
export ASAN_OPTIONS="allocator_may_return_null=0:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

run_one() {
  local t=$1 found="$build/fuzz-found/$1" log="$build/fuzz-logs/$1.log"
  mkdir -p "$found"
  if "$build/fuzz/${t}_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 \
      -max_len=16384 -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$t-" \
      "$found" "fuzz/corpus/$t" >"$log" 2>&1; then
    local execs per_s
    execs=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$log" | tail -1)
    per_s=$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+)/\1/p' "$log" | tail -1)
    echo "fuzz: $t: ${execs:-?} executions, ${per_s:-?}/s, nothing found"
  else
    echo "fuzz: $t: FOUND A FAILURE (log: $log; input in $build/fuzz-artifacts/)" >&2
    grep -E "^==[0-9]+==ERROR|fuzz property broken|SUMMARY|Test unit written" "$log" | head -8 >&2
    echo "fuzz: reproduce with: $build/fuzz/${t}_fuzz $build/fuzz-artifacts/$t-*" >&2
    return 1
  fi
}
export -f run_one
export build seconds
printf '%s\n' "${targets[@]}" | xargs -P 2 -I{} bash -c 'run_one {}'
