#!/bin/sh
# Service round trip beside Cyclone's own ddsperf ping/pong, in one run, on the loopback-only
# configuration, under three loads: idle, one CPU hog, one hog per core (docs/benchmarks.md,
# "Service" and "Latency on a busy host"). A hog is `sh -c 'while :; do :; done'`, started and
# killed by this script. Throughput (1, 8, 32 clients) is measured in the idle run only.
#
#   bench/service_bench.sh [BUILD_DIR]      (default: build)
#
# SERVICE_BENCH_SECONDS (default 3): ddsperf's and the throughput runs' length.
# SERVICE_BENCH_LOADS (default "0 1 all"): hogs per run; "all" = one per core.
# SERVICE_BENCH_REQUESTS (default 5000): latency requests per calculation.
# SERVICE_BENCH_SERVICE (default BUILD_DIR/service/gearcoupling-service): the service binary, to
# compare another build's service with the same client.
# Every process is bounded in time (timeout) and uses a domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
domain=$((1 + $$ % 200))
sdomain=$(( (domain + 100) % 200 + 1 ))
seconds=${SERVICE_BENCH_SECONDS:-3}
loads=${SERVICE_BENCH_LOADS:-0 1 all}
requests=${SERVICE_BENCH_REQUESTS:-5000}
cores=$(nproc)
hogs=""
service=""
cleanup() {
  for pid in $hogs; do kill "$pid" 2>/dev/null || true; done
  if [ -n "$service" ]; then kill -TERM "$service" 2>/dev/null || true; fi
}
trap cleanup EXIT INT TERM

echo "# loopback config: $CYCLONEDDS_URI, domains $domain (ddsperf) and $sdomain (service), $cores cores, load before: $(cut -d' ' -f1-3 /proc/loadavg)"

start_hogs() {  # $1 hogs; each bounded by timeout in case this script is killed
  hogs=""
  i=0
  while [ "$i" -lt "$1" ]; do
    timeout 600 sh -c 'while :; do :; done' &
    hogs="$hogs $!"
    i=$((i + 1))
  done
}

stop_hogs() {
  for pid in $hogs; do kill "$pid" 2>/dev/null || true; done
  for pid in $hogs; do wait "$pid" 2>/dev/null || true; done
  hogs=""
}

# The floor: ddsperf ping/pong round trip (reliable, 12-byte samples); the median of its
# per-second p50s, the first second (discovery) dropped. ddsperf prints half the round trip (the
# one-way latency: (now - source timestamp) / 2 in process_pong, src/tools/ddsperf/ddsperf.c), so
# its figure is doubled here to compare round trip with round trip. $1 is ping's mode: listener
# (ddsperf's default: the pong's listener sends the next ping, no thread woken in between, like
# call_then) or waitset (a thread of ping's own waits for the pong, like a blocking call()).
ddsperf_p50() {
  timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 4)) pong >/dev/null 2>&1 &
  pong=$!
  sleep 0.5
  ping_out=$(timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 1)) ping "$1" 2>&1 || true)
  wait $pong 2>/dev/null || true
  echo "$ping_out" | awk '/ 50% / { for (i = 1; i <= NF; i++) if ($i == "50%") { v = $(i+1); sub("us", "", v); print v } }' \
    | tail -n +2 | sort -g | awk '{ a[NR] = $1 } END { if (NR == 0) print "nan"; else print 2 * a[int((NR + 1) / 2)] }'
}

field() {  # $1 output, $2 calculation, $3 field (p50, p99)
  echo "$1" | awk -v c="$2" -v f="$3" '$2 == c { for (i = 1; i <= NF; i++) if (index($i, f "=") == 1) { v = substr($i, length(f) + 2); sub("us", "", v); print v } }'
}

"${SERVICE_BENCH_SERVICE:-$build/service/gearcoupling-service}" --domain "$sdomain" --log-level warn &
service=$!
summary=""
for load in $loads; do
  [ "$load" = all ] && load=$cores
  start_hogs "$load"
  sleep 0.5
  floor=$(ddsperf_p50 listener)
  floor_ws=$(ddsperf_p50 waitset)
  clients=""
  [ "$load" -eq 0 ] && clients="1,8,32"
  out=$(timeout 300 "$build/bench/gc_bench_service" --domain "$sdomain" --seconds "$seconds" \
        --latency-requests "$requests" --clients "$clients")
  stop_hogs
  echo "## $load hog(s): ddsperf ping/pong round trip p50 ${floor} us (ping listener), ${floor_ws} us (ping waitset); twice its printed one-way figure, median of per-second p50s"
  echo "$out"
  line=$(awk -v l="$load" -v d="$floor" -v dw="$floor_ws" \
    -v j="$(field "$out" jam_angle p50)" -v jp="$(field "$out" jam_angle p99)" \
    -v m="$(field "$out" induced_moments p50)" -v mp="$(field "$out" induced_moments p99)" \
    -v jc="$(field "$out" jam_angle_cb p50)" -v jcp="$(field "$out" jam_angle_cb p99)" \
    -v mc="$(field "$out" moments_cb p50)" -v mcp="$(field "$out" moments_cb p99)" \
    'BEGIN { printf "| %s | %s / %s us | %s / %s us | %s / %s us | %.2f, %.2f | %.2f, %.2f | %s / %s us | %s / %s us | %.2f, %.2f |", l, d, dw, jc, jcp, mc, mcp, jc / d, mc / d, j / dw, m / dw, j, jp, m, mp, j / d, m / d }')
  summary="$summary
$line"
done
kill -TERM "$service"
wait "$service" || true
service=""

echo
echo "| hogs | ddsperf round trip p50, ping listener / waitset | call_then jam angle p50 / p99 | call_then moments p50 / p99 | ratio call_then / ddsperf listener (jam, moments) | ratio call() / ddsperf waitset (jam, moments) | call() jam angle p50 / p99 | call() moments p50 / p99 | ratio call() / ddsperf listener (jam, moments) |"
echo "|---|---|---|---|---|---|---|---|---|$summary"
echo "(target: p50 ratio <= 1.5; load after: $(cut -d' ' -f1-3 /proc/loadavg))"
