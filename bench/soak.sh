#!/bin/sh
# A soak of gearcoupling-service (docs/benchmarks.md, "Soak"): for DURATION seconds, 8 clients
# each sending requests at a fixed rate and awaiting each answer, and one client that joins the
# domain, is answered once and leaves again every second. A table row every INTERVAL seconds:
# requests, failures, round-trip p50/p99, reconnections, and the service's resident memory, file
# descriptors and threads. It then checks they stayed flat after the first row (bench/soak_load.cc
# says how, in numbers) and exits 1 if not, or if any request or reconnection failed.
#
#   bench/soak.sh [DURATION_S] [BUILD_DIR]      (defaults: 3600, build)
#
# SOAK_INTERVAL_S: seconds a row (default 60; 10 when DURATION_S is under 600).
# SOAK_CLIENTS (default 8) and SOAK_RATE_HZ (default 100, each client's rate).
# On the loopback-only configuration, on a domain derived from this shell's pid; every process
# is bounded in time. ctest runs the 60 s version (bench.soak_60s).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
duration=${1:-3600}
build=${2:-$here/build}
if [ "$duration" -lt 600 ]; then interval=${SOAK_INTERVAL_S:-10}; else interval=${SOAK_INTERVAL_S:-60}; fi
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
service=""
cleanup() {
  if [ -n "$service" ]; then kill -TERM "$service" 2>/dev/null || true; wait "$service" 2>/dev/null || true; fi
}
trap cleanup EXIT INT TERM

echo "# soak: $duration s on domain $domain, $(nproc) cores, load before: $(cut -d' ' -f1-3 /proc/loadavg)"
timeout $((duration + 120)) "$build/service/gearcoupling-service" --domain "$domain" --log-level warn &
service=$!
sleep 1
# The service is timeout's child: its own pid is the one to watch.
service_pid=$(cat "/proc/$service/task/$service/children" | tr -d ' ')
case "$service_pid" in '' | *[!0-9]*) echo "soak: no single gearcoupling-service under timeout ($service_pid)" >&2; exit 1 ;; esac
timeout $((duration + 60)) "$build/bench/gc_bench_soak" --domain "$domain" --service-pid "$service_pid" \
  --clients "${SOAK_CLIENTS:-8}" --rate-hz "${SOAK_RATE_HZ:-100}" --seconds "$duration" --interval-s "$interval"
