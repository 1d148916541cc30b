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

# The floor: ddsperf ping/pong round trip (listener mode, reliable, 12-byte samples); the median
# of its per-second p50s, the first second (discovery) dropped.
ddsperf_p50() {
  timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 4)) pong >/dev/null 2>&1 &
  pong=$!
  sleep 0.5
  ping_out=$(timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 1)) ping 2>&1 || true)
  wait $pong 2>/dev/null || true
  echo "$ping_out" | awk '/ 50% / { for (i = 1; i <= NF; i++) if ($i == "50%") { v = $(i+1); sub("us", "", v); print v } }' \
    | tail -n +2 | sort -g | awk '{ a[NR] = $1 } END { if (NR == 0) print "nan"; else print a[int((NR + 1) / 2)] }'
}

field() {  # $1 output, $2 calculation, $3 field (p50, p99)
  echo "$1" | awk -v c="$2" -v f="$3" '$2 == c { for (i = 1; i <= NF; i++) if (index($i, f "=") == 1) { v = substr($i, length(f) + 2); sub("us", "", v); print v } }'
}

"$build/service/gearcoupling-service" --domain "$sdomain" --log-level warn &
service=$!
summary=""
for load in $loads; do
  [ "$load" = all ] && load=$cores
  start_hogs "$load"
  sleep 0.5
  floor=$(ddsperf_p50)
  clients=""
  [ "$load" -eq 0 ] && clients="1,8,32"
  out=$(timeout 300 "$build/bench/gc_bench_service" --domain "$sdomain" --seconds "$seconds" \
        --latency-requests "$requests" --clients "$clients")
  stop_hogs
  echo "## $load hog(s): ddsperf ping/pong p50 ${floor} us (median of per-second p50s)"
  echo "$out"
  jam=$(field "$out" jam_angle p50)
  moments=$(field "$out" induced_moments p50)
  line=$(awk -v l="$load" -v d="$floor" -v j="$jam" -v m="$moments" -v jp="$(field "$out" jam_angle p99)" -v mp="$(field "$out" induced_moments p99)" \
    'BEGIN { printf "| %s | %s us | %s / %s us | %s / %s us | %.2f | %.2f |", l, d, j, jp, m, mp, j / d, m / d }')
  summary="$summary
$line"
done
kill -TERM "$service"
wait "$service" || true
service=""

echo
echo "| hogs | ddsperf p50 | jam angle p50 / p99 | induced moments p50 / p99 | ratio jam | ratio moments |"
echo "|---|---|---|---|---|---|$summary"
echo "(ratio = service p50 / ddsperf p50, target <= 1.5; load after: $(cut -d' ' -f1-3 /proc/loadavg))"
