#!/bin/sh
# Service round trip beside Cyclone's own ddsperf ping/pong, in one run, on the loopback-only
# configuration, under three loads: idle, one CPU hog, one hog per core (docs/benchmarks.md,
# "Service" and "Latency on a busy host"). A hog is `sh -c 'while :; do :; done'`, started and
# killed by this script. Throughput (1, 8, 32 clients) is measured in the idle run only.
#
#   bench/service_bench.sh [BUILD_DIR]      (default: build)
#
# With hogs, one run of a few seconds says little: where the scheduler puts the hogs and the
# two processes decides, for seconds at a time, whether a wake-up waits (ddsperf alone gives
# 18 us in one run and 70 us in the next). So each load is measured in ROUNDS rounds; a round
# is one WINDOW-second run of each of the four: ddsperf ping listener, the service with
# call_then, ddsperf ping waitset, the service with call(), in that order in odd rounds and
# pairwise swapped in even ones. Each round gives a ratio (the service's p50 over the ddsperf p50
# of the same round); the table gives the median round's p50s and the median ratio, with the
# lowest and highest ratio beside it.
#
# SERVICE_BENCH_ROUNDS (default 9): rounds per load. With one hog per core, whether a round
# trip's threads share a core or are split over both decides its time (25-30 us or 60 us and
# up, for ddsperf and the service alike) and changes within a second, so 5 rounds were too few.
# SERVICE_BENCH_WINDOW (default 1): seconds measured per run.
# SERVICE_BENCH_SECONDS (default 3): the throughput runs' length.
# SERVICE_BENCH_LOADS (default "0 1 all"): hogs per run; "all" = one per core.
# SERVICE_BENCH_SERVICE (default BUILD_DIR/service/gearcoupling-service): the service binary, to
# compare another build's service with the same client.
# SERVICE_BENCH_CONFIG (default deploy/cyclonedds-loopback.xml as a file:// URI): the Cyclone
# configuration of every process, ddsperf's too, to compare another.
# Every process is bounded in time (timeout) and uses a domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="${SERVICE_BENCH_CONFIG:-file://$here/deploy/cyclonedds-loopback.xml}"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
claim_domain sdomain 8 100
seconds=${SERVICE_BENCH_SECONDS:-3}
loads=${SERVICE_BENCH_LOADS:-0 1 all}
rounds=${SERVICE_BENCH_ROUNDS:-9}
window=${SERVICE_BENCH_WINDOW:-1}
cores=$(nproc)
. "$here/bench/lib/hogs.sh"
. "$here/bench/lib/ddsperf.sh"
service=""
work=$(mktemp -d)
cleanup() {
  rm -rf "$work"
  stop_hogs
  ddsperf_pong_stop
  if [ -n "$service" ]; then kill -TERM "$service" 2>/dev/null || true; fi
}
trap cleanup EXIT INT TERM

echo "# loopback config: $CYCLONEDDS_URI, domains $domain (ddsperf) and $sdomain (service), $cores cores, load before: $(cut -d' ' -f1-3 /proc/loadavg)"

# The floor: ddsperf ping/pong round trip (reliable, 12-byte samples); the median of its
# per-second p50s over WINDOW seconds, the first second (discovery) dropped, doubled (ddsperf
# prints half the round trip, bench/lib/ddsperf.sh) to compare round trip with round trip. $1 is
# ping's mode: listener (ddsperf's default: the pong's listener sends the next ping, no thread
# woken in between, like call_then) or waitset (a thread of ping's own waits for the pong, like
# a blocking call()).
ddsperf_run() {  # $1 ping mode; prints "p50 p99" of the round trip (us)
  ddsperf_pong_start "$domain" $((window + 4))
  ping_out=$(timeout $((window + 10)) ddsperf -i "$domain" -D $((window + 2)) ping "$1" 2>&1 || true)
  ddsperf_pong_stop
  echo "$(ddsperf_percentile "$ping_out" 50%) $(ddsperf_percentile "$ping_out" 99%)"
}

ddsperf_percentile() {  # $1 ping's output, $2 "50%" or "99%": twice the median per-second figure
  echo "$1" | awk -v p="$2" '/ 50% / { for (i = 1; i <= NF; i++) if ($i == p) { v = $(i+1); sub("us", "", v); print v } }' \
    | tail -n +2 | sort -g | awk '{ a[NR] = $1 } END { if (NR == 0) print "nan"; else print 2 * a[int((NR + 1) / 2)] }'
}

field() {  # $1 output, $2 calculation, $3 field (p50, p99)
  echo "$1" | awk -v c="$2" -v f="$3" '$2 == c { for (i = 1; i <= NF; i++) if (index($i, f "=") == 1) { v = substr($i, length(f) + 2); sub("us", "", v); print v } }'
}

# service_run MODE: one WINDOW-second latency run of each calculation with MODE (call or
# call_then); prints "jam_p50 jam_p99 moments_p50 moments_p99".
service_run() {
  out=$(timeout 120 "$build/bench/gc_bench_service" --domain "$sdomain" --modes "$1" \
        --latency-seconds "$window" --clients "")
  if [ "$1" = call ]; then j=jam_angle; m=induced_moments; else j=jam_angle_cb; m=moments_cb; fi
  echo "$(field "$out" $j p50) $(field "$out" $j p99) $(field "$out" $m p50) $(field "$out" $m p99)"
}

# median COLUMN FILE [DIVISOR_COLUMN]: the median of a column of FILE, or of column/divisor.
median() {
  awk -v c="$1" -v d="${3:-0}" '{ print d ? $c / $d : $c }' "$2" | sort -g \
    | awk '{ a[NR] = $1 } END { if (NR == 0) print "nan"; else if (NR % 2) print a[(NR + 1) / 2]; else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}
range() {  # COLUMN FILE DIVISOR_COLUMN: "lowest-highest" of column/divisor
  awk -v c="$1" -v d="$3" '{ r = $c / $d; if (NR == 1 || r < lo) lo = r; if (NR == 1 || r > hi) hi = r } END { printf "%.2f-%.2f", lo, hi }' "$2"
}

"${SERVICE_BENCH_SERVICE:-$build/service/gearcoupling-service}" --domain "$sdomain" --log-level warn &
service=$!
summary=""
for load in $loads; do
  [ "$load" = all ] && load=$cores
  start_hogs "$load"
  sleep 0.5
  rows="$work/load$load"
  : >"$rows"
  echo "## $load hog(s): $rounds rounds of $window s; per round, p50 and p99 (us): ddsperf listener round trip (twice ddsperf's one-way figures); service call_then jam, moments; ddsperf waitset round trip; service call() jam, moments"
  r=1
  while [ "$r" -le "$rounds" ]; do
    if [ $((r % 2)) -eq 1 ]; then
      dl=$(ddsperf_run listener); cb=$(service_run call_then)
      dw=$(ddsperf_run waitset); bl=$(service_run call)
    else
      cb=$(service_run call_then); dl=$(ddsperf_run listener)
      bl=$(service_run call); dw=$(ddsperf_run waitset)
    fi
    echo "$dl $cb $dw $bl" | tee -a "$rows"
    r=$((r + 1))
  done
  if [ "$load" -eq 0 ]; then
    timeout 300 "$build/bench/gc_bench_service" --domain "$sdomain" --seconds "$seconds" \
      --modes "" --clients 1,8,32
  fi
  stop_hogs
  # columns: 1-2 ddsperf listener p50 p99, 3-6 call_then jam p50 p99 moments p50 p99,
  # 7-8 ddsperf waitset p50 p99, 9-12 call() jam p50 p99 moments p50 p99
  line="| $load | $(median 1 "$rows") / $(median 2 "$rows") us"
  line="$line | $(median 3 "$rows") / $(median 4 "$rows") us | $(median 5 "$rows") / $(median 6 "$rows") us"
  line="$line | $(printf '%.2f' "$(median 3 "$rows" 1)") ($(range 3 "$rows" 1)), $(printf '%.2f' "$(median 5 "$rows" 1)") ($(range 5 "$rows" 1))"
  line="$line | $(median 7 "$rows") / $(median 8 "$rows") us"
  line="$line | $(median 9 "$rows") / $(median 10 "$rows") us | $(median 11 "$rows") / $(median 12 "$rows") us"
  line="$line | $(printf '%.2f' "$(median 9 "$rows" 7)") ($(range 9 "$rows" 7)), $(printf '%.2f' "$(median 11 "$rows" 7)") ($(range 11 "$rows" 7))"
  line="$line | $(printf '%.2f' "$(median 9 "$rows" 1)"), $(printf '%.2f' "$(median 11 "$rows" 1)") |"
  summary="$summary
$line"
done
kill -TERM "$service"
wait "$service" || true
service=""

echo
echo "Medians over the rounds (p50 / p99 are the median round's), and the median ratio with the lowest and highest round's:"
echo
echo "| hogs | ddsperf listener p50 / p99 | call_then jam angle p50 / p99 | call_then moments p50 / p99 | p50 ratio call_then / ddsperf listener: jam, moments | ddsperf waitset p50 / p99 | call() jam angle p50 / p99 | call() moments p50 / p99 | p50 ratio call() / ddsperf waitset: jam, moments | p50 ratio call() / ddsperf listener: jam, moments |"
echo "|---|---|---|---|---|---|---|---|---|---|$summary"
echo "(target: p50 ratio <= 1.5; load after: $(cut -d' ' -f1-3 /proc/loadavg))"
