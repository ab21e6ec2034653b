#!/usr/bin/env bash
# Builds the libFuzzer targets with clang in BUILD_DIR (just them and the libraries they need) and runs each
# for SECONDS from its seed corpus, then prints per target: executions per second, total executions and the
# coverage edges reached (cov:). Inputs that crash, leak or hang are saved as BUILD_DIR/findings/<target>/;
# new corpus inputs collect in BUILD_DIR/corpus/<target>/. Fails when any target has a finding.
# usage: run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]   (targets: every one when none are named)
# FUZZ_RUNS=N in the environment stops each target after N executions too (SECONDS is then its cap);
# FUZZ_SEED=N fixes libFuzzer's random seed, so a run explores the same inputs each time (ctest's does).
set -uo pipefail
(( $# >= 2 )) || { echo "usage: $0 BUILD_DIR SECONDS [TARGET...]" >&2; exit 2; }
build=$(realpath -m "$1")
seconds=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
all_targets=(protocol http_request resume_token scene_json gltf obj texture)
targets=("$@")
(( ${#targets[@]} > 0 )) || targets=("${all_targets[@]}")
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "$0: SECONDS must be a positive whole number, got '$seconds'" >&2; exit 2; }
for target in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $target "* ]] || { echo "$0: no fuzz target '$target' (${all_targets[*]})" >&2; exit 2; }
done
command -v clang++ >/dev/null || { echo "$0: clang++ is missing: run docker/install-deps.sh" >&2; exit 2; }

# Optimised but with line tables, so a finding's stack names its lines; warnings are the GCC build's business.
cmake -S "$source_dir" -B "$build" -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSPECULA_FUZZ=ON \
  -DSPECULA_WERROR=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" >"$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; echo "$0: configuring the clang build failed" >&2; exit 1; }
cmake --build "$build" --target "${targets[@]/%/_fuzzer}" ||
  { echo "$0: building the fuzz targets failed" >&2; exit 1; }

failed=()
printf '%-14s %10s %14s %8s  %s\n' target exec/s executions edges findings >"$build/summary.txt"
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target" findings="$build/findings/$target" log="$build/logs/$target.log"
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  dictionary=() runs=()
  [[ -n ${FUZZ_RUNS:-} ]] && runs=(-runs="$FUZZ_RUNS")
  [[ -n ${FUZZ_SEED:-} ]] && runs+=(-seed="$FUZZ_SEED")
  [[ -f "$here/$target.dict" ]] && dictionary=(-dict="$here/$target.dict")
  echo "fuzzing $target for $seconds s"
  touch "$build/logs/$target.started"  # findings of earlier runs, still in the folder, are not this run's
  # -timeout: a single input running 25 s is a hang; -rss_limit_mb: the decoders' own bounds stay well under it.
  "$build/fuzz/${target}_fuzzer" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2560 -print_final_stats=1 \
    -artifact_prefix="$findings/" "${dictionary[@]}" "${runs[@]}" "$corpus" "$here/corpus/$target" >"$log" 2>&1
  status=$?
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  edges=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  found=$(find "$findings" -type f -newer "$build/logs/$target.started" | wc -l)
  printf '%-14s %10s %14s %8s  %s\n' "$target" "${rate:-?}" "${executions:-?}" "${edges:-?}" "$found" >>"$build/summary.txt"
  if (( status != 0 || found > 0 )); then
    failed+=("$target")
    grep -E -A40 '^==[0-9]+==ERROR|^SUMMARY|ALARM|out-of-memory|runtime error' "$log" | head -60
    echo "$target: exit status $status; findings in $findings; full log $log"
  fi
done
cat "$build/summary.txt"
if (( ${#failed[@]} > 0 )); then
  echo "findings in: ${failed[*]}" >&2
  exit 1
fi
