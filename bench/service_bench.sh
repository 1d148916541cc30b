#!/bin/sh
# Service round trip and throughput beside Cyclone's own ddsperf ping/pong, in one run, on the
# loopback-only configuration (docs/benchmarks.md, "Service").
#
#   bench/service_bench.sh [BUILD_DIR]      (default: build)
#
# Every process is bounded in time (timeout) and uses a domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
domain=$((1 + $$ % 200))
seconds=${SERVICE_BENCH_SECONDS:-3}

echo "# loopback config: $CYCLONEDDS_URI, domain $domain, $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"

# 1. The floor: ddsperf ping/pong round trip (listener mode, reliable, 12-byte samples).
timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 4)) pong >/dev/null 2>&1 &
pong=$!
sleep 0.5
ping_out=$(timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 1)) ping 2>&1 || true)
wait $pong 2>/dev/null || true
# Median over the per-second reports of their p50 (the first second includes discovery).
ddsperf_p50=$(echo "$ping_out" | awk '/ 50% / { for (i = 1; i <= NF; i++) if ($i == "50%") { v = $(i+1); sub("us", "", v); print v } }' \
  | tail -n +2 | sort -g | awk '{ a[NR] = $1 } END { if (NR == 0) print "nan"; else print a[int((NR + 1) / 2)] }')
echo "ddsperf ping/pong p50 round trip: ${ddsperf_p50} us (median of per-second p50s)"

# 2. The service on the same configuration, a fresh domain so ddsperf leftovers cannot interfere.
sdomain=$(( (domain + 100) % 200 + 1 ))
"$build/service/gearcoupling-service" --domain "$sdomain" --log-level warn &
service=$!
trap 'kill -TERM $service 2>/dev/null || true' EXIT
bench_out=$(timeout 300 "$build/bench/gc_bench_service" --domain "$sdomain" --seconds "$seconds")
echo "$bench_out"
kill -TERM $service
wait $service || true
trap - EXIT

for calculation in jam_angle induced_moments; do
  p50=$(echo "$bench_out" | awk -v c="$calculation" '$2 == c { for (i = 1; i <= NF; i++) if ($i ~ /^p50=/) { v = $i; sub("p50=", "", v); sub("us", "", v); print v } }')
  awk -v a="$p50" -v b="$ddsperf_p50" -v c="$calculation" \
    'BEGIN { printf "ratio %s p50 / ddsperf p50 = %.2f (target <= 1.5)\n", c, a / b }'
done
