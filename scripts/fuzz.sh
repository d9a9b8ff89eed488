#!/usr/bin/env bash
# Fuzzes the parsers of untrusted files (scene JSON, OBJ/PLY/STL meshes) with
# libFuzzer under ASan and UBSan: builds fuzz/ with clang into build-fuzz/ (the
# core libraries only, no Qt or VTK), runs the targets side by side, each for
# SECONDS (default 60) on a temporary copy of its seed corpus, prints the executions and exits 1 if
# any target crashed (the input is kept in build-fuzz/crashes/).
# Usage: scripts/fuzz.sh [SECONDS-PER-TARGET]
# VIEWPIPE_FUZZ_BUILD, if set, is the command that builds: it gets the build
# folder and the targets appended (e.g. a wrapper that serializes builds).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
seconds=${1:-60}
root=$PWD
build=$root/build-fuzz
targets=(scene_fuzz mesh_fuzz)

CC=clang CXX=clang++ cmake -S fuzz -B "$build" >/dev/null
if [ -n "${VIEWPIPE_FUZZ_BUILD:-}" ]; then
  $VIEWPIPE_FUZZ_BUILD "$build" "${targets[@]}"
else
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
fi

work=$(mktemp -d)
declare -A pids
# However the script ends, no fuzzer outlives it.
trap 'kill "${pids[@]}" 2>/dev/null || true; wait; rm -rf "$work"' EXIT
mkdir -p "$build/crashes"
# The targets run side by side, each on a core of its own where there are two.
fuzz_target() {
  local target=$1 name=${1%_fuzz}
  cp -r "fuzz/corpus/$name" "$work/$name"
  "$build/$target" "$work/$name" -dict="fuzz/$name.dict" -max_total_time="$seconds" -timeout=25 \
    -artifact_prefix="$build/crashes/$target-" -print_final_stats=1 >"$build/$target.log" 2>&1
}
for target in "${targets[@]}"; do
  fuzz_target "$target" &
  pids[$target]=$!
done
status=0
for target in "${targets[@]}"; do
  name=${target%_fuzz}
  log=$build/$target.log
  if wait "${pids[$target]}"; then
    result=ok
  else
    result="CRASHED (see $log and $build/crashes/)"
    status=1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" 2>/dev/null | tail -n 1 || true)
  echo "$target: ${runs:-?} executions in $seconds s, $(find "$work/$name" -type f | wc -l) corpus inputs: $result"
done
exit $status
