#!/bin/sh
# A control loop against gearcoupling-service beside ddsperf ping at the same rate, in one run,
# on the loopback configuration, at three loads: idle, one CPU hog, one hog per core
# (docs/benchmarks.md, "A control loop at 1 kHz"; issue 26).
#
#   bench/control_loop.sh [BUILD_DIR]      (default: build)
#
# For each load and rate, ROUNDS rounds; a round is one run of SECONDS of each of these four, in
# this order in odd rounds and pairwise swapped in even ones, so that both see the host alike:
# - `ddsperf ping RATE listener` against `ddsperf pong` (ping's main thread sends at the rate,
#   the pong is taken in a listener);
# - the service with call_then at RATE (gc_bench_control_loop: the loop's thread sends, the
#   reply's callback takes the time);
# - `ddsperf ping RATE waitset` (a thread of ping's own is woken for each pong);
# - the service with blocking call()s at RATE (the loop's thread is woken by each reply).
# The service's requests are awaited before the next tick; a tick missed meanwhile is skipped.
# Every round trip is recorded, ddsperf's too (bench/ddsperf_roundtrips.c, preloaded: ddsperf
# itself prints per-second summaries of half the round trip only), and bench/latency_stats.py
# sums up the rounds of each of the four alike: p50, p99, p99.9, the maximum, the share over
# 1 ms, the ticks skipped and the share of deadlines missed (late or skipped; the script says
# why both count). Beside each: the time the hypervisor took the CPUs away during its runs
# (steal, /proc/stat; a whole vCPU is sometimes taken for 100 ms, and a round trip waits), the
# share of deadlines missed outside those times (bench/steal_log.py logs them through the whole
# run; bench/latency_stats.py --steal sets apart what overlapped them, ddsperf's and the
# service's alike) and the load average when its last run ended. Then the service over the ddsperf mode with the same
# wake-ups: call_then over listener, call() over waitset.
#
# CONTROL_LOOP_SECONDS (default 3): seconds per run.
# CONTROL_LOOP_ROUNDS (default 3): rounds per load and rate.
# CONTROL_LOOP_RATES (default "1000 100"): request rates (Hz).
# CONTROL_LOOP_LOADS (default "0 1 all"): hogs per load; "all" = one per core.
# CONTROL_LOOP_PRIORITIES (default "none"): each a whole pass over the loads, with the service,
#   the loop and ddsperf (ping and pong alike) started under
#   - none: as they are;
#   - fifo: `chrt -f 10` (SCHED_FIFO 10: docs/deploy.md, "Real-time priority").
# CONTROL_LOOP_LATE_US (unset): also list every round trip over this many us, with the time since
#   the one before (a periodic cause shows as a steady gap).
# CONTROL_LOOP_CONFIG (default deploy/cyclonedds-loopback.xml as a file:// URI): the Cyclone
#   configuration of every process, ddsperf's too, to compare another.
# Every process is bounded in time (timeout) and uses a domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="${CONTROL_LOOP_CONFIG:-file://$here/deploy/cyclonedds-loopback.xml}"
domain=$((1 + $$ % 200))
sdomain=$(( (domain + 100) % 200 + 1 ))
seconds=${CONTROL_LOOP_SECONDS:-3}
rounds=${CONTROL_LOOP_ROUNDS:-3}
rates=${CONTROL_LOOP_RATES:-1000 100}
loads=${CONTROL_LOOP_LOADS:-0 1 all}
priorities=${CONTROL_LOOP_PRIORITIES:-none}
late_us=${CONTROL_LOOP_LATE_US:-}
. "$here/bench/lib/hogs.sh"
. "$here/bench/lib/ddsperf.sh"
service=""
steal_logger=""
work=$(mktemp -d)
cleanup() {
  if [ -n "$steal_logger" ]; then kill "$steal_logger" 2>/dev/null || true; fi
  stop_hogs
  ddsperf_pong_stop
  if [ -n "$service" ]; then kill -TERM "$service" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT INT TERM

prefix_of() {  # $1 priority: the command prefix that starts a process with it
  case $1 in
    none) echo "" ;;
    fifo) echo "chrt -f 10" ;;
    *) echo "CONTROL_LOOP_PRIORITIES: unknown \"$1\" (allowed: none, fifo)" >&2; exit 2 ;;
  esac
}

# stats RATE FILE...: bench/latency_stats.py's line for the runs, plus the late round trips if asked.
stats() {
  stats_rate=$1
  shift
  if [ -n "$late_us" ]; then
    echo "## round trips over $late_us us" >&2
    python3 "$here/bench/latency_stats.py" --rate-hz "$stats_rate" --late "$late_us" "$@" | sed -n '2,$p' >&2
  fi
  python3 "$here/bench/latency_stats.py" --rate-hz "$stats_rate" --steal "$work/steal.log" "$@" | head -n 1 || true
}

steal_ms() {  # the time stolen from all CPUs by the hypervisor so far (ms)
  awk '/^cpu / { print $9 * 10 }' /proc/stat
}

# run WHAT RATE FILE PREFIX...: one run of WHAT (listener, waitset: ddsperf; call_then, call: the
# service) into FILE; adds the steal time of the run to FILE.steal.
run() {
  run_what=$1
  run_rate=$2
  run_file=$3
  shift 3
  before=$(steal_ms)
  case $run_what in
    listener | waitset) ddsperf_loop "$run_rate" "$run_what" "$run_file" "$@" ;;
    *) service_loop "$run_rate" "$run_what" "$run_file" "$@" ;;
  esac
  echo $(( $(steal_ms) - before )) >>"${run_file%-r*}.steal"
}

# ddsperf_loop RATE MODE FILE PREFIX...: ddsperf ping at RATE in MODE against a pong, both
# started through PREFIX, every round trip into FILE.
ddsperf_loop() {
  rate=$1
  mode=$2
  file=$3
  shift 3
  ddsperf_pong_start "$domain" $((seconds + 4)) "$@"
  GC_DDSPERF_ROUNDTRIPS="$file" LD_PRELOAD="$build/bench/libgc_ddsperf_roundtrips.so" \
    "$@" timeout $((seconds + 10)) ddsperf -i "$domain" -D $((seconds + 1)) ping "${rate}Hz" "$mode" \
    >"$file.out" 2>&1 || true
  ddsperf_pong_stop
  # The first second is discovery and the first pings' matching: dropped, as the service's
  # warm-up is.
  awk 'NR == 1 { start = $1 } $1 >= start + 1' "$file" >"$file.kept"
  mv "$file.kept" "$file"
}

# service_loop RATE MODE FILE PREFIX...: gc_bench_control_loop at RATE with MODE, every round
# trip into FILE.
service_loop() {
  rate=$1
  mode=$2
  file=$3
  shift 3
  "$@" timeout $((seconds + 40)) "$build/bench/gc_bench_control_loop" --domain "$sdomain" \
    --mode "$mode" --rate-hz "$rate" --seconds "$seconds" --out "$file" >"$file.out" 2>&1 || true
}

field() {  # LINE NAME: the value of NAME=VALUE in LINE, unit stripped
  echo "$1" | tr ' ' '\n' | awk -F= -v n="$2" '$1 == n { v = $2; sub("us|%", "", v); print v }'
}

ratio() {  # A B: A / B with two decimals
  awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "nan" }'
}

row() {  # PRIORITY HOGS RATE WHAT LINE STEAL_FILE
  echo "| $1 | $2 | $3 | $4 | $(field "$5" n) | $(field "$5" p50) | $(field "$5" p99) | $(field "$5" p999) | $(field "$5" max) | $(field "$5" over_1ms) % | $(field "$5" skipped) | $(field "$5" missed) % | $(field "$5" missed_unstolen) % | $(awk '{ s += $1 } END { print s + 0 }' "$6") ms | $(cut -d' ' -f1 /proc/loadavg) |"
}

ratios_row() {  # PRIORITY HOGS RATE WHAT SERVICE_LINE DDSPERF_LINE
  echo "| $1 | $2 | $3 | $4 | $(ratio "$(field "$5" p50)" "$(field "$6" p50)") | $(ratio "$(field "$5" p999)" "$(field "$6" p999)") | $(field "$5" missed) % / $(field "$6" missed) % | $(field "$5" missed_unstolen) % / $(field "$6" missed_unstolen) % |"
}

echo "# loopback config: $CYCLONEDDS_URI, domains $domain (ddsperf) and $sdomain (service), $(nproc) cores, $rounds rounds of $seconds s per run, load before: $(cut -d' ' -f1-3 /proc/loadavg)"
table="| priority | hogs | rate (Hz) | what | n | p50 (us) | p99 (us) | p99.9 (us) | max (us) | over 1 ms | ticks skipped | deadlines missed | missed outside stolen time | steal | load average |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
ratios="| priority | hogs | rate (Hz) | service / ddsperf, same wake-ups | p50 ratio | p99.9 ratio | deadlines missed, service / ddsperf | outside stolen time |
|---|---|---|---|---|---|---|---|"
failed=0
timeout 3600 python3 "$here/bench/steal_log.py" 3600 "$work/steal.log" &
steal_logger=$!
for priority in $priorities; do
  prefix=$(prefix_of "$priority")
  # shellcheck disable=SC2086 # the prefix is words
  $prefix timeout 3600 "$build/service/gearcoupling-service" --domain "$sdomain" --log-level warn &
  service=$!
  for load in $loads; do
    start_hogs "$load"
    sleep 0.5
    for rate in $rates; do
      f="$work/$priority-$load-$rate"
      r=1
      while [ "$r" -le "$rounds" ]; do
        if [ $((r % 2)) -eq 1 ]; then order="listener call_then waitset call"; else order="call_then listener call waitset"; fi
        for what in $order; do
          # shellcheck disable=SC2086 # the prefix is words
          run "$what" "$rate" "$f-$what-r$r" $prefix
        done
        r=$((r + 1))
      done
      for what in listener call_then waitset call; do
        line=$(stats "$rate" "$f-$what"-r*[0-9])
        [ "$(field "$line" n)" != 0 ] || { failed=1; echo "$what at $rate Hz, $load hog(s): no round trip; its output:" >&2; cat "$f-$what"-r*.out >&2; }
        table="$table
$(row "$priority" "$load" "$rate" "$what" "$line" "$f-$what.steal")"
        eval "line_$what=\"\$line\""
        eval "kept_${priority}_${load}_${rate}_$what=\"\$line\""
      done
      # shellcheck disable=SC2154 # set by the eval above
      ratios="$ratios
$(ratios_row "$priority" "$load" "$rate" "call_then / ddsperf listener" "$line_call_then" "$line_listener")
$(ratios_row "$priority" "$load" "$rate" "call() / ddsperf waitset" "$line_call" "$line_waitset")"
    done
    stop_hogs
  done
  kill -TERM "$service"
  wait "$service" || true
  service=""
done

# The prioritised service against the unprioritised ddsperf of the same run, when both passes ran.
cross=""
case " $priorities " in *" none "*) case " $priorities " in *" fifo "*)
  for load in $loads; do
    for rate in $rates; do
      for pair in call_then:listener call:waitset; do
        eval "service_line=\"\$kept_fifo_${load}_${rate}_${pair%%:*}\""
        eval "ddsperf_line=\"\$kept_none_${load}_${rate}_${pair##*:}\""
        # shellcheck disable=SC2154 # set by the evals above
        cross="$cross
$(ratios_row "fifo / none" "$load" "$rate" "${pair%%:*} (fifo) / ddsperf ${pair##*:} (none)" "$service_line" "$ddsperf_line")"
      done
    done
  done ;; esac ;; esac

echo
echo "Every run's round trips (us; listener and waitset are ddsperf's, the whole round trip):"
echo
echo "$table"
echo
echo "The service against ddsperf in the mode with the same wake-ups:"
echo
echo "$ratios$cross"
echo "(goal: p99.9 within 2 x; deadlines missed at most 0.1 %, or twice ddsperf's; p50 within 1.5 x; load after: $(cut -d' ' -f1-3 /proc/loadavg))"
echo "(steal: the hypervisor took CPUs away for $(awk '{ s += $2 } END { print s + 0 }' "$work/steal.log") ms in all, $(wc -l <"$work/steal.log") times; bench/steal_log.py)"
exit "$failed"
