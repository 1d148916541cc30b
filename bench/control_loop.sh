#!/bin/sh
# A control loop against gearcoupling-service beside ddsperf ping at the same rate, in one run,
# on the loopback configuration, at three loads: idle, one CPU hog, one hog per core
# (docs/benchmarks.md, "A control loop at 1 kHz"; issue 26).
#
#   bench/control_loop.sh [BUILD_DIR]      (default: build)
#
# The service's loop (gc_bench_control_loop, its requests awaited before the next tick; a tick
# missed meanwhile is skipped) runs in two modes, each beside the ddsperf mode with the same
# wake-ups:
# - call_then (the loop's thread sends, the reply's callback takes the time) beside `ddsperf ping
#   RATE listener` against `ddsperf pong` (ping's main thread sends, the pong is taken in a
#   listener);
# - blocking call()s (the loop's thread is woken by each reply) beside `ddsperf ping RATE
#   waitset` (a thread of ping's own is woken for each pong).
# For each priority, load and rate, ROUNDS rounds. With CONTROL_LOOP_CONCURRENT=1 (the default) a
# round runs each mode and its ddsperf AT THE SAME TIME, on their two domains, for SECONDS (the
# two modes one after the other, their order swapped in even rounds; bench/lib/control_loop.sh,
# as bench/stall_coincidence.sh): a stall that the host makes (the hypervisor waking a halted
# vCPU late, steal) falls on both alike, where in turn it falls on whichever runs then. With
# CONTROL_LOOP_CONCURRENT=0 a round runs the four one after the other, SECONDS each (listener,
# call_then, waitset, call, pairwise swapped in even rounds).
# Every round trip is recorded, ddsperf's too (bench/ddsperf_roundtrips.c, preloaded: ddsperf
# itself prints per-second summaries of half the round trip only), and bench/latency_stats.py
# sums up the rounds of each of the four alike: p50, p99, p99.9, the maximum, the share over
# 1 ms, the ticks skipped and the share of deadlines missed (late or skipped; the script says
# why both count). Beside each: the time the hypervisor took the CPUs away during its runs
# (steal, /proc/stat; a whole vCPU is sometimes taken for 100 ms, and a round trip waits), the
# share of deadlines missed outside those times (bench/steal_log.py logs them through the whole
# run; bench/latency_stats.py --steal sets apart what overlapped them, ddsperf's and the
# service's alike) and the load average when its last run ended. Then the service over the
# ddsperf mode with the same wake-ups: the p50 and p99.9 ratios, the deadlines missed, whether
# the cell met issue 26's goals (deadlines taken outside stolen time) and, at the same time
# only, the share the service missed in stalls of its own: not ddsperf's within 2 ms
# (bench/stall_coincidence.py, round by round; the first five of each round listed with their
# CLOCK_MONOTONIC times, to look up in a `perf record -k CLOCK_MONOTONIC` trace).
#
# CONTROL_LOOP_CONCURRENT (default 1): 1, the service and its ddsperf at the same time; 0, in turn.
# CONTROL_LOOP_PHASE (default 0.5; at the same time only): the loop's ticks fall this many periods
#   (0 to 1) after ddsperf ping's, and follow them when ping starts its schedule again
#   (gc_bench_control_loop --phase-of); "free": wherever the loop's start puts them. Two loops
#   left free keep, through a round, the offset their starts gave, and the one whose round trip
#   follows the other's closely finds the host's network path and caches warm: at 100 Hz with a
#   hog per core, `call_then` was 0.59-0.62 x ddsperf's listener in rounds where it followed by
#   0.1-1.2 ms and 1.40-1.41 x where it led by 2.9-3.0 ms (docs/benchmarks.md). Half a period
#   apart, neither follows the other closer.
# CONTROL_LOOP_TICKS (default 9000): the ticks of a cell (a rate, a load, a mode) over its rounds
#   at every rate: a run lasts TICKS / (ROUNDS x RATE) seconds, 3 s at 1 kHz and 10 s at 100 Hz.
#   The goal's p99.9 and its 0.1 % are then 9 round trips at both rates. With 3,000 ticks they
#   were 3: a cell whose service misses 0.06 % of its deadlines (mean 1.8) then misses more than
#   3 with probability 0.11 on chance alone (Poisson); with 9,000 ticks, more than 9 with 0.05.
# CONTROL_LOOP_SECONDS (unset): seconds per run at every rate instead (at the same time: the
#   seconds both ran).
# CONTROL_LOOP_ROUNDS (default: runs of at most 10 s, at least 3 rounds; 3 at 1 kHz, 9 at 100 Hz):
#   rounds per load and rate: a host slow for a while weighs less spread over more rounds, and
#   with CONTROL_LOOP_PHASE=free so does the offset each round deals out between the two loops.
# CONTROL_LOOP_RATES (default "1000 100"): request rates (Hz).
# CONTROL_LOOP_LOADS (default "0 1 all"): hogs per load; "all" = one per core.
# CONTROL_LOOP_PRIORITIES (default "none"): each a whole pass over the loads, with the service,
#   the loop and ddsperf (ping and pong alike) started under
#   - none: as they are;
#   - fifo: `chrt -f 10` (SCHED_FIFO 10: docs/deploy.md, "Real-time priority");
#   - slice: still SCHED_OTHER, with a scheduler slice of CONTROL_LOOP_SLICE_US (default 100 us:
#     bench/gc_sched_slice; docs/architecture.md, "Where a control loop's tail comes from"),
#     which needs no privilege.
# CONTROL_LOOP_SPIN_US (default 0): call() spins up to this long on each reply before it sleeps
#   (ClientOptions::spin_before_sleep, 0 to 10000); its rows then say so. ddsperf's waitset
#   still sleeps: the option removes a wake-up that ddsperf keeps (docs/architecture.md).
# CONTROL_LOOP_LATE_US (unset): also list every round trip over this many us, with the time since
#   the one before (a periodic cause shows as a steady gap).
# CONTROL_LOOP_CONFIG (default deploy/cyclonedds-loopback.xml as a file:// URI): the Cyclone
#   configuration of every process, ddsperf's too, to compare another.
# After the tables, each cell's medians round by round (service/ddsperf) and, at the same time,
# how far the loop's sends fell after ping's, in periods (bench/send_phase.py), round by round.
# CONTROL_LOOP_PLAN (default 0): 1 prints the run's first line (rounds, seconds, modes) and stops.
# Every process is bounded in time (timeout) and uses a domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="${CONTROL_LOOP_CONFIG:-file://$here/deploy/cyclonedds-loopback.xml}"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
claim_domain sdomain 8 100
ticks=${CONTROL_LOOP_TICKS:-9000}
rounds_at() {  # RATE: CONTROL_LOOP_ROUNDS, or as many rounds as keep a run within 10 s, at least 3
  if [ -n "${CONTROL_LOOP_ROUNDS:-}" ]; then
    echo "$CONTROL_LOOP_ROUNDS"
  else
    awk -v t="$ticks" -v h="$1" 'BEGIN { r = t / (10 * h); r = (r == int(r)) ? r : int(r) + 1; print (r < 3) ? 3 : r }'
  fi
}
rates=${CONTROL_LOOP_RATES:-1000 100}
loads=${CONTROL_LOOP_LOADS:-0 1 all}
priorities=${CONTROL_LOOP_PRIORITIES:-none}
late_us=${CONTROL_LOOP_LATE_US:-}
slice_us=${CONTROL_LOOP_SLICE_US:-100}
spin_us=${CONTROL_LOOP_SPIN_US:-0}
case $spin_us in
  '' | *[!0-9]*) spin_ok=0 ;;
  *) spin_ok=$((spin_us <= 10000)) ;;
esac
[ "$spin_ok" = 1 ] || { echo "CONTROL_LOOP_SPIN_US: \"$spin_us\" (allowed: 0 to 10000 us)" >&2; exit 2; }
if [ "$spin_us" -gt 0 ]; then
  call_label="call(), spinning $spin_us us,"
  call_how="call() spinning up to $spin_us us before it sleeps"
else
  call_label="call()"
  call_how="call() sleeping at once"
fi
concurrent=${CONTROL_LOOP_CONCURRENT:-1}
case $concurrent in
  0 | 1) ;;
  *) echo "CONTROL_LOOP_CONCURRENT: \"$concurrent\" (allowed: 1, at the same time; 0, in turn)" >&2; exit 2 ;;
esac
phase=${CONTROL_LOOP_PHASE:-0.5}  # bench/lib/control_loop.sh's service_loop reads it
case $phase in
  free | 0 | 1 | 0.[0-9] | 0.[0-9][0-9] | 1.0) ;;
  *) echo "CONTROL_LOOP_PHASE: \"$phase\" (allowed: free, or 0 to 1 periods in at most two decimals)" >&2; exit 2 ;;
esac
if [ "$phase" = free ]; then phase_how="the loop's ticks where its start puts them"; else phase_how="the loop's ticks $phase of a period after ping's"; fi
. "$here/bench/lib/hogs.sh"
. "$here/bench/lib/ddsperf.sh"
. "$here/bench/lib/control_loop.sh"
service=""
steal_logger=""
work=$(mktemp -d)
cleanup() {
  if [ -n "$steal_logger" ]; then kill "$steal_logger" 2>/dev/null || true; fi
  stop_hogs
  ddsperf_ping_wait TERM
  ddsperf_pong_stop
  if [ -n "$service" ]; then kill -TERM "$service" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT INT TERM

prefix_of() {  # $1 priority: the command prefix that starts a process with it
  case $1 in
    none) echo "" ;;
    fifo) echo "chrt -f 10" ;;
    slice) echo "$build/bench/gc_sched_slice $slice_us" ;;
    *) echo "CONTROL_LOOP_PRIORITIES: unknown \"$1\" (allowed: none, fifo, slice)" >&2; exit 2 ;;
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
# service) into FILE, alone (CONTROL_LOOP_CONCURRENT=0); adds the steal time of the run to
# FILE.steal.
run() {
  run_what=$1
  run_rate=$2
  run_file=$3
  shift 3
  before=$(steal_ms)
  case $run_what in
    listener | waitset)
      ddsperf_pair_start "$run_rate" "$run_what" "$run_file" $((seconds + 1)) "$@"
      ddsperf_pair_stop "$run_file" ;;
    *) service_loop "$run_rate" "$run_what" "$run_file" "$seconds" - "$@" ;;
  esac
  echo $(( $(steal_ms) - before )) >>"${run_file%-r*}.steal"
}

# run_pair MODE RATE ROUND PREFIX...: the service's loop in MODE and ddsperf in the mode with the
# same wake-ups at the same time (CONTROL_LOOP_CONCURRENT=1), into the files of round ROUND of the
# cell $f; adds the steal time of the pair to both programs' .steal.
run_pair() {
  pair_what=$1
  pair_ping=$(ping_mode_of "$1")
  pair_at=$2
  pair_round=$3
  shift 3
  before=$(steal_ms)
  control_loop_pair "$pair_at" "$pair_what" "$seconds" "$f-$pair_what-r$pair_round" \
    "$f-$pair_ping-r$pair_round" "$@"
  pair_stolen=$(( $(steal_ms) - before ))
  echo "$pair_stolen" >>"$f-$pair_what.steal"
  echo "$pair_stolen" >>"$f-$pair_ping.steal"
}

# own_stalls MODE RATE LABEL: the share (%) of the ticks of cell $f's rounds at which the
# service in MODE missed its deadline in stalls of its own, not ddsperf's within 2 ms
# (bench/stall_coincidence.py, round by round, pooled); lists the first five of each round's
# stalls of its own, with their times, into $work/own.txt.
own_stalls() {
  own_ticks=0
  own_missed=0
  own_round=1
  while [ "$own_round" -le "$rounds" ]; do
    own_out=$(python3 "$here/bench/stall_coincidence.py" --rate-hz "$2" "$f-$1-r$own_round" \
      "$f-$(ping_mode_of "$1")-r$own_round" 2>&1 || true)
    own_line=$(echo "$own_out" | head -n 1)
    own_ticks=$((own_ticks + $(field "$own_line" ticks | grep -E '^[0-9]+$' || echo 0)))
    own_missed=$((own_missed + $(field "$own_line" of_which_service_only | grep -E '^[0-9]+$' || echo 0)))
    echo "$own_out" | sed -n '2,6s/^ *service only: /'"$3, round $own_round: "'/p' >>"$work/own.txt"
    own_more=$(( $(echo "$own_out" | grep -c 'service only:' || true) - 5 ))
    [ "$own_more" -le 0 ] || echo "$3, round $own_round: and $own_more more" >>"$work/own.txt"
    own_round=$((own_round + 1))
  done
  awk -v m="$own_missed" -v t="$own_ticks" 'BEGIN { if (t > 0) printf "%.3f", 100 * m / t; else print "nan" }'
}

seconds_at() {  # RATE: seconds per run: CONTROL_LOOP_SECONDS, or `ticks` ticks over the rounds (rounded up)
  if [ -n "${CONTROL_LOOP_SECONDS:-}" ]; then
    echo "$CONTROL_LOOP_SECONDS"
  else
    awk -v t="$ticks" -v r="$(rounds_at "$1")" -v h="$1" 'BEGIN { s = t / (r * h); print (s == int(s)) ? s : int(s) + 1 }'
  fi
}

round_phases() {  # SERVICE_MODE: how far cell $f's loop's sends fell after ping's, round by round
  rp_round=1
  rp_out=""
  while [ "$rp_round" -le "$rounds" ]; do
    rp_out="$rp_out $(python3 "$here/bench/send_phase.py" --rate-hz "$rate" "$f-$1-r$rp_round" \
      "$f-$(ping_mode_of "$1")-r$rp_round" || true)"
    rp_round=$((rp_round + 1))
  done
  echo "${rp_out# }"
}

round_medians() {  # SERVICE_MODE DDSPERF_MODE: cell $f's p50s round by round, service/ddsperf (us)
  rm_round=1
  rm_out=""
  while [ "$rm_round" -le "$rounds" ]; do
    for rm_mode in "$1" "$2"; do
      rm_line=$(python3 "$here/bench/latency_stats.py" --rate-hz "$rate" "$f-$rm_mode-r$rm_round" | head -n 1 || true)
      if [ "$rm_mode" = "$1" ]; then rm_out="$rm_out $(field "$rm_line" p50)"; else rm_out="$rm_out/$(field "$rm_line" p50)"; fi
    done
    rm_round=$((rm_round + 1))
  done
  echo "${rm_out# }"
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

goals_met() {  # SERVICE_LINE DDSPERF_LINE: yes if the cell meets issue 26's three goals, else no
  awk -v s50="$(field "$1" p50)" -v d50="$(field "$2" p50)" -v s999="$(field "$1" p999)" \
    -v d999="$(field "$2" p999)" -v sm="$(field "$1" missed_unstolen)" \
    -v dm="$(field "$2" missed_unstolen)" 'BEGIN {
      ok = d50 > 0 && s50 <= 1.5 * d50 && d999 > 0 && s999 <= 2 * d999 && (sm <= 0.1 || sm <= 2 * dm)
      print ok ? "yes" : "no" }'
}

ratios_row() {  # PRIORITY HOGS RATE WHAT SERVICE_LINE DDSPERF_LINE [OWN]
  echo "| $1 | $2 | $3 | $4 | $(ratio "$(field "$5" p50)" "$(field "$6" p50)") | $(ratio "$(field "$5" p999)" "$(field "$6" p999)") | $(field "$5" missed) % / $(field "$6" missed) % | $(field "$5" missed_unstolen) % / $(field "$6" missed_unstolen) % | ${7:--} | $(goals_met "$5" "$6") |"
}

if [ "$concurrent" = 1 ]; then how="the service and ddsperf at the same time, $phase_how"; else how="the service and ddsperf in turn"; fi
echo "# loopback config: $CYCLONEDDS_URI, domains $domain (ddsperf) and $sdomain (service), $(nproc) cores, $(for rate in $rates; do printf '%s round(s) of %s s per run at %s Hz, ' "$(rounds_at "$rate")" "$(seconds_at "$rate")" "$rate"; done)$how, $call_how, at $(git -C "$here" describe --always --dirty 2>/dev/null || echo "?"), load before: $(cut -d' ' -f1-3 /proc/loadavg)"
[ "${CONTROL_LOOP_PLAN:-0}" = 0 ] || exit 0
table="| priority | hogs | rate (Hz) | what | n | p50 (us) | p99 (us) | p99.9 (us) | max (us) | over 1 ms | ticks skipped | deadlines missed | missed outside stolen time | steal | load average |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
ratios="| priority | hogs | rate (Hz) | service / ddsperf, same wake-ups | p50 ratio | p99.9 ratio | deadlines missed, service / ddsperf | outside stolen time | service's, in stalls of its own | goals met |
|---|---|---|---|---|---|---|---|---|---|"
medians=""
phases=""
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
      rounds=$(rounds_at "$rate")
      seconds=$(seconds_at "$rate")
      r=1
      while [ "$r" -le "$rounds" ]; do
        if [ "$concurrent" = 1 ]; then
          if [ $((r % 2)) -eq 1 ]; then order="call_then call"; else order="call call_then"; fi
          for what in $order; do
            # shellcheck disable=SC2086 # the prefix is words
            run_pair "$what" "$rate" "$r" $prefix
          done
        else
          if [ $((r % 2)) -eq 1 ]; then order="listener call_then waitset call"; else order="call_then listener call waitset"; fi
          for what in $order; do
            # shellcheck disable=SC2086 # the prefix is words
            run "$what" "$rate" "$f-$what-r$r" $prefix
          done
        fi
        r=$((r + 1))
      done
      medians="$medians
$priority, $load hog(s), $rate Hz: call_then/listener $(round_medians call_then listener); call/waitset $(round_medians call waitset)"
      if [ "$concurrent" = 1 ]; then
        phases="$phases
$priority, $load hog(s), $rate Hz: call_then $(round_phases call_then); call $(round_phases call)"
      fi
      own_call_then=""
      own_call=""
      if [ "$concurrent" = 1 ]; then
        own_call_then="$(own_stalls call_then "$rate" "$priority, $load hog(s), $rate Hz, call_then") %"
        own_call="$(own_stalls call "$rate" "$priority, $load hog(s), $rate Hz, call") %"
      fi
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
$(ratios_row "$priority" "$load" "$rate" "call_then / ddsperf listener" "$line_call_then" "$line_listener" "$own_call_then")
$(ratios_row "$priority" "$load" "$rate" "$call_label / ddsperf waitset" "$line_call" "$line_waitset" "$own_call")"
    done
    stop_hogs
  done
  kill -TERM "$service"
  wait "$service" || true
  service=""
done

# The prioritised service (fifo, slice) against the unprioritised ddsperf of the same run, when
# both passes ran.
cross=""
case " $priorities " in *" none "*)
  for prio in fifo slice; do
    case " $priorities " in *" $prio "*)
      for load in $loads; do
        for rate in $rates; do
          for pair in call_then:listener call:waitset; do
            eval "service_line=\"\$kept_${prio}_${load}_${rate}_${pair%%:*}\""
            eval "ddsperf_line=\"\$kept_none_${load}_${rate}_${pair##*:}\""
            # shellcheck disable=SC2154 # set by the evals above
            cross="$cross
$(ratios_row "$prio / none" "$load" "$rate" "${pair%%:*} ($prio) / ddsperf ${pair##*:} (none)" "$service_line" "$ddsperf_line")"
          done
        done
      done ;;
    esac
  done ;;
esac

echo
echo "Every run's round trips (us; listener and waitset are ddsperf's, the whole round trip):"
echo
echo "$table"
echo
echo "The service against ddsperf in the mode with the same wake-ups:"
echo
echo "$ratios$cross"
echo "(goal: p99.9 within 2 x; deadlines missed outside stolen time at most 0.1 %, or twice ddsperf's; p50 within 1.5 x; load after: $(cut -d' ' -f1-3 /proc/loadavg))"
echo
echo "The medians round by round (us, service/ddsperf; the rounds above pool them):"
echo "$medians"
if [ "$concurrent" = 1 ]; then
  echo "(in stalls of its own: the deadlines the service missed in stalls that ddsperf, running at the same time, did not have within 2 ms; bench/stall_coincidence.py)"
  echo
  echo "How far the loop's sends fell after ddsperf ping's, round by round (periods, median; bench/send_phase.py):"
  echo "$phases"
  if [ -s "$work/own.txt" ]; then
    echo
    echo "The service's stalls of its own (CLOCK_MONOTONIC start, length, deadlines; the first five a round):"
    echo
    cat "$work/own.txt"
  fi
fi
echo "(steal: the hypervisor took CPUs away for $(awk '{ s += $2 } END { print s + 0 }' "$work/steal.log") ms in all, $(wc -l <"$work/steal.log") times; bench/steal_log.py)"
exit "$failed"
