#!/usr/bin/env bash
# README's test command: installs the packages, builds everything and runs every test, then
# the core suite again under AddressSanitizer + UndefinedBehaviorSanitizer and under
# ThreadSanitizer, and the libFuzzer targets for a few seconds each. ctest's summary of the
# full suite is printed last, then each stage's duration.
#
# Time (CI: a fresh clone on 2 cores): four trees are compiled, so compile time is most of the
# run beside the full suite's ctest. Ninja builds them (a tree configured before keeps its
# generator); precompiled headers (GC_PCH) and the sanitizer trees' -Og -g1
# (GC_SANITIZE_CODEGEN) cut the cost of a unit by a third to a half.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
times_file=$(mktemp)
trap 'rm -f "$times_file"' EXIT
children_cpu() {  # CPU seconds (user + system) of the finished child processes so far, in $cpu
  times >"$times_file"   # in this shell: a $(times) subshell has no children of its own
  cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%.0f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$times_file")
}
stage() {  # stage NAME: prints the previous stage's duration (its CPU time, the load), then NAME
  children_cpu
  if [ -n "${stage_name:-}" ]; then
    echo "-- ${stage_name}: $((SECONDS - stage_start)) s (CPU $((cpu - stage_cpu)) s;" \
         "load $(cut -d' ' -f1-3 /proc/loadavg))"
  fi
  stage_name=$1 stage_start=$SECONDS stage_cpu=$cpu
  [ -z "$1" ] || echo "== $1"
}
stage "packages (deploy/install-deps.sh)"
bash deploy/install-deps.sh
jobs=$(nproc)

# Ninja for a new build tree; one configured before keeps the generator it has.
generator() {  # $1 = build directory
  [ -f "$1/CMakeCache.txt" ] || echo "-G Ninja"
}

sanitized_core_tests() {  # $1 = address | thread
  local dir="build-$1"
  # shellcheck disable=SC2046
  cmake -S . -B "$dir" $(generator "$dir") -DCMAKE_BUILD_TYPE=Debug -DGC_SANITIZE="$1" \
    -DGC_CORE_ONLY=ON >/dev/null
  cmake --build "$dir" -j "$jobs" >/dev/null
  # setarch -R: GCC 12's ThreadSanitizer rejects some kernels' high mmap randomisation.
  (cd "$dir" && setarch "$(uname -m)" -R ctest --output-on-failure -j "$jobs" | tail -n 3)
}
stage "core tests under AddressSanitizer + UndefinedBehaviorSanitizer"
sanitized_core_tests address
stage "core tests under ThreadSanitizer"
sanitized_core_tests thread

stage "fuzz targets, 5 s each (libFuzzer + ASan + UBSan, clang; docs/fuzzing.md)"
bash tests/run_fuzz.sh 5

stage "full build"
# shellcheck disable=SC2046
cmake -S . -B build $(generator build) -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs"
stage "full test suite"
cd build
status=0
ctest --output-on-failure -j "$jobs" --timeout 600 || status=$?
stage ""
echo "-- total: $((SECONDS - start)) s"
exit "$status"
