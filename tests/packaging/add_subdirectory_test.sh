#!/usr/bin/env bash
# ctest packaging.add_subdirectory: tests/packaging/superproject/ (copied out of the tree) takes
# this source tree in with add_subdirectory and configures with GoogleTest and Google Benchmark
# unfindable; it checks the gearcoupling:: targets are there and no test or benchmark is.
# Configure only: a build would compile the whole project again.
#   add_subdirectory_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source=$2
tmp=$(mktemp -d /tmp/gc_add_subdirectory.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
cp -r "$source/tests/packaging/superproject" "$tmp/superproject"
cmake -S "$tmp/superproject" -B "$tmp/build" -DGC_SOURCE_DIR="$source" \
  -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON >"$tmp/log" 2>&1 ||
  { cat "$tmp/log"; echo "FAIL: configure"; exit 1; }
echo "PASS: add_subdirectory(gearcoupling) configured without GoogleTest and Google Benchmark"
