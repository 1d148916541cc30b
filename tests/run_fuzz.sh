#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, GC_FUZZ=ON with clang, in build-fuzz/) and runs each for
# SECONDS on its committed seed corpus and dictionary (docs/fuzzing.md). Exits non-zero when a
# target crashes, hangs (over 10 s on one input), leaks, runs out of memory or breaks a check:
# the input is left in build-fuzz/fuzz-artifacts/ to reproduce with `<target> <file>`.
#
#   tests/run_fuzz.sh            5 s a target: the CI-sized run of tests/run_all.sh
#   tests/run_fuzz.sh 300        the longer run of docs/benchmarks.md
#
# New inputs go to build-fuzz/fuzz-work/<target>/, never into the committed corpus.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-5}
dir=build-fuzz
targets=(recording_csv batch_csv coupling_text model_text wire_request batch_request)

generator=()   # Ninja for a new tree; one configured before keeps its generator
[ -f "$dir/CMakeCache.txt" ] || generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DGC_FUZZ=ON \
  -DGC_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$dir" -j "$(nproc)" --target fuzzers >/dev/null

failed=0
mkdir -p "$dir/fuzz-artifacts" "$dir/fuzz-logs"
for name in "${targets[@]}"; do
  work="$dir/fuzz-work/$name"
  log="$dir/fuzz-logs/$name.log"
  mkdir -p "$work"
  dict=()
  [ -f "fuzz/dict/$name.dict" ] && dict=(-dict="fuzz/dict/$name.dict")
  if "$dir/fuzz/${name}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       "${dict[@]}" -artifact_prefix="$dir/fuzz-artifacts/$name-" \
       -print_final_stats=1 "$work" "fuzz/corpus/$name" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    echo "fuzz $name: ${runs:-?} executions in ${seconds} s, no crash"
  else
    echo "fuzz $name: FAILED (log: $log)"
    grep -E "ERROR|fuzz check failed|Test unit written|SUMMARY" "$log" | head -n 20 || true
    failed=1
  fi
done
exit "$failed"
