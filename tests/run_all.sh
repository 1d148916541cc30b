#!/usr/bin/env bash
# README's test command: installs the packages, builds everything and runs every test, then
# the core suite again under AddressSanitizer + UndefinedBehaviorSanitizer and under
# ThreadSanitizer, and the libFuzzer targets for a few seconds each. ctest's summary of the
# full suite is printed last.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
jobs=$(nproc)

sanitized_core_tests() {  # $1 = address | thread
  local dir="build-$1"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DGC_SANITIZE="$1" -DGC_CORE_ONLY=ON >/dev/null
  cmake --build "$dir" -j "$jobs" >/dev/null
  # setarch -R: GCC 12's ThreadSanitizer rejects some kernels' high mmap randomisation.
  (cd "$dir" && setarch "$(uname -m)" -R ctest --output-on-failure -j "$jobs" | tail -n 3)
}
echo "== core tests under AddressSanitizer + UndefinedBehaviorSanitizer"
sanitized_core_tests address
echo "== core tests under ThreadSanitizer"
sanitized_core_tests thread

echo "== fuzz targets, 5 s each (libFuzzer + ASan + UBSan, clang; docs/fuzzing.md)"
bash tests/run_fuzz.sh 5

echo "== full build and test suite"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs"
cd build
ctest --output-on-failure -j "$jobs" --timeout 600
