#!/usr/bin/env bash
# ctest packaging.find_package: `cmake --install` into a temporary prefix; the consumer project
# (tests/packaging/consumer/, copied out of the tree) configured with find_package(gearcoupling)
# and built against it; the installed gearcoupling-service started on loopback (the installed
# etc/gearcoupling/cyclonedds.xml) on a domain of its own, finding the catalogue installed beside
# it; the consumer's jam angle through gearcoupling::client must equal the core's in process.
#   find_package_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
tmp=$(mktemp -d /tmp/gc_find_package.XXXXXX)
service=""
cleanup() {
  if [ -n "$service" ]; then kill -KILL "$service" 2>/dev/null || true; fi
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; [ -f "$tmp/service.log" ] && cat "$tmp/service.log" >&2; exit 1; }

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
cp -r "$source/tests/packaging/consumer" "$tmp/consumer"
cmake -S "$tmp/consumer" -B "$tmp/consumer/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$tmp/consumer/build" -j 2 >/dev/null

# Domains 201-215 (packaging.deb: 216-230): apart from the 1-200 of tests/service's
# test_domain(), so no concurrently running DDS test shares it.
domain=$((201 + $$ % 15))
export CYCLONEDDS_URI=file://$prefix/etc/gearcoupling/cyclonedds.xml
unset GEARCOUPLING_CATALOG
"$prefix/bin/gearcoupling-service" --domain "$domain" 2>"$tmp/service.log" &
service=$!

"$tmp/consumer/build/consumer" "$domain" | tee "$tmp/consumer.out" || fail "consumer"
grep -q "^catalogue $prefix/share/gearcoupling/couplings\$" "$tmp/consumer.out" ||
  fail "the consumer did not find the installed catalogue"
grep -q "catalogue_dir=$prefix/share/gearcoupling/couplings " "$tmp/service.log" ||
  fail "the service did not find the installed catalogue"

kill -TERM "$service"
status=0
wait "$service" || status=$?
service=""
[ "$status" -eq 0 ] || fail "gearcoupling-service exited $status on SIGTERM"
echo "PASS: find_package(gearcoupling) consumer answered through the installed service"
