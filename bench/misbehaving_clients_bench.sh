#!/bin/sh
# A well-behaved client's round trip (p50, p99, max) while another client misbehaves: none,
# made-up client ids (fake-ids), a client that never reads its replies (deaf; both from
# tests/service/misbehaving_client, in a process of its own). A fresh
# gearcoupling-service (2 workers) per mode, loopback-only configuration, a domain of this run's
# own (docs/benchmarks.md, "Misbehaving clients").
#
#   bench/misbehaving_clients_bench.sh [BUILD_DIR]      (default: build)
#
# GEARCOUPLING_SERVICE overrides the service binary (to measure another build beside it);
# MISBEHAVING_SECONDS (default 5) is each mode's length. Every process runs under timeout.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
service_bin=${GEARCOUPLING_SERVICE:-$build/service/gearcoupling-service}
seconds=${MISBEHAVING_SECONDS:-5}
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
echo "# $service_bin, domain $domain, $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
service=""
trap 'if [ -n "$service" ]; then kill -TERM $service 2>/dev/null || true; fi' EXIT INT TERM
for mode in none fake-ids deaf; do
  timeout -k 5 $((seconds + 60)) "$service_bin" --domain "$domain" --jobs 2 --log-level error &
  service=$!
  bad=""
  if [ "$mode" != none ]; then
    # Its own process: a full reader blocks its whole process's DDS delivery. It finds the
    # instance and matches first (about a second), then misbehaves for seconds + 2.
    timeout $((seconds + 40)) "$build/tests/service/misbehaving_client" "$domain" "$mode" \
      $((seconds + 2)) &
    bad=$!
  fi
  timeout $((seconds + 50)) "$build/bench/gc_bench_misbehaving" --domain "$domain" --mode "$mode" \
    --seconds "$seconds" || echo "mode $mode: the benchmark failed or timed out"
  if [ -n "$bad" ]; then kill "$bad" 2>/dev/null || true; wait "$bad" 2>/dev/null || true; fi
  kill -TERM "$service"
  wait "$service" || true
  service=""
done
