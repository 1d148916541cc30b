#!/bin/sh
# Wake-ups per second of every thread of the service and of a client making blocking calls,
# beside ddsperf's pong and ping (waitset mode, the same three wake-ups per round trip), on the
# loopback configuration (docs/benchmarks.md, "Wake-ups and CPU per round trip"). On a busy host every wake-up
# besides the round trip's own is a chance for the scheduler to split the round trip's threads
# over the cores, so this counts them: from the third field of /proc/PID/task/TID/schedstat
# (the number of times the thread was scheduled in; the first, its time on a CPU, gives the CPU
# time per wake-up), over a 1-second window that starts 1.5 s into the run. ddsperf ping gets
# -D 5: its round-trip threads end a second before it does, and with -D 3 they had sometimes
# ended inside the window, leaving them out of the report. A thread preempted and run again
# counts twice, so for a thread that runs long (tev sending a burst) the count is more than
# its wake-ups.
#
#   bench/wakeups.sh [BUILD_DIR]      (default: build)
#
# WAKEUPS_CONFIG (default: deploy/cyclonedds-loopback.xml as a file:// URI): the Cyclone
# configuration of every process, to compare another.
# WAKEUPS_MODE (default call): call, blocking calls beside ddsperf ping waitset; call_then,
# listener mode (the reply callback sends the next request) beside ddsperf ping listener.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="${WAKEUPS_CONFIG:-file://$here/deploy/cyclonedds-loopback.xml}"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
work=$(mktemp -d)
pids=""
cleanup() {
  for pid in $pids; do kill "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT INT TERM
mode=${WAKEUPS_MODE:-call}
case $mode in
  call) ping_mode=waitset ;;
  call_then) ping_mode=listener ;;
  *) echo "WAKEUPS_MODE: unknown mode \"$mode\" (allowed: call, call_then)" >&2; exit 2 ;;
esac

# snapshot FILE PID...: "pid tid name cpu_ns count" for every thread of each PID
snapshot() {
  out=$1
  shift
  : >"$out"
  for pid in "$@"; do
    for task in /proc/"$pid"/task/*; do
      [ -r "$task/schedstat" ] || continue
      echo "$pid ${task##*/} $(cat "$task/comm" | tr ' ' '_') $(cut -d' ' -f1,3 "$task/schedstat")" >>"$out"
    done
  done
}

child() {  # the pid of the process `timeout` (pid $1) runs
  for _ in 1 2 3 4 5 6 7 8 9 10; do
    pid=$(pgrep -P "$1" | head -n 1)
    if [ -n "$pid" ]; then echo "$pid"; return; fi
    sleep 0.1
  done
  echo "$1"
}

# report LABEL SERVER_PID CLIENT_PID: a 1-second window of both processes' threads
report() {
  snapshot "$work/a" "$2" "$3"
  sleep 1
  snapshot "$work/b" "$2" "$3"
  echo "## $1 (wake-ups in 1 s, and CPU time per wake-up; threads that woke at least once)"
  awk -v s="$2" 'NR == FNR { t[$2] = $4; n[$2] = $5; next } ($2 in n) && $5 > n[$2] {
      printf "%-8s %-16s %6d %7.1f us\n", ($1 == s ? "server" : "client"), $3, $5 - n[$2],
             ($4 - t[$2]) / 1000 / ($5 - n[$2]) }' \
    "$work/a" "$work/b"
}

timeout 30 "$build/service/gearcoupling-service" --domain "$domain" --log-level warn &
service=$!
pids="$service"
sleep 1
timeout 30 "$build/bench/gc_bench_service" --domain "$domain" --modes "$mode" --latency-seconds 3 \
  --clients "" >"$work/client.out" &
client=$!
pids="$pids $client"
sleep 1.5
report "gearcoupling-service and gc_bench_service ($mode: jam angle, then moments)" \
  "$(child "$service")" "$(child "$client")"
wait "$client"
cat "$work/client.out"
kill -TERM "$service"
wait "$service" || true

claim_domain pdomain 8 100
timeout 30 ddsperf -i "$pdomain" -D 7 pong >/dev/null 2>&1 &
pong=$!
pids="$pids $pong"
sleep 0.5
timeout 30 ddsperf -i "$pdomain" -D 5 ping "$ping_mode" >"$work/ping.out" 2>&1 &
ping=$!
pids="$pids $ping"
sleep 1.5
report "ddsperf pong and ping $ping_mode" "$(child "$pong")" "$(child "$ping")"
wait "$ping" || true
grep " 50% " "$work/ping.out" | tail -1
