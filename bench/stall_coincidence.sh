#!/bin/sh
# The control loop and ddsperf at the same time, to tell the service's own stalls from the
# host's (docs/benchmarks.md, "A control loop at 1 kHz"; issue 26).
#
#   bench/stall_coincidence.sh [BUILD_DIR]      (default: build)
#
# Run one after the other (bench/control_loop.sh with CONTROL_LOOP_CONCURRENT=0), the service and
# ddsperf each meet the stalls of a few ms that the host causes once in a while (the hypervisor
# pausing a virtual CPU for less than the 10 ms /proc/stat counts steal in, a woken thread held by
# another's kernel work) only when they run then. Here both run at once for SECONDS, on two
# domains, as in a cell of bench/control_loop.sh (the same function: bench/lib/control_loop.sh),
# for longer and with every stall listed: the service (gc_bench_control_loop, MODE) and `ddsperf
# ping RATE` against `ddsperf pong`, in the mode with the same wake-ups (listener for call_then,
# waitset for call), every process started under the same PRIORITY. bench/stall_coincidence.py
# then sets each stall of the service (a round trip over 1 ms, or ticks skipped) beside
# ddsperf's: one that ddsperf had too, within 2 ms, is the host's; the others are the service's
# own and are listed with their times (CLOCK_MONOTONIC, as perf's timestamps with -k
# CLOCK_MONOTONIC). Each pair costs a few percent of a core; on two
# cores the four round-trip threads can meet on one, which both sides pay alike.
#
# STALL_SECONDS (default 60), STALL_RATE (default 1000), STALL_MODE (default call_then; or call),
# STALL_PRIORITY (default fifo: `chrt -f 10`; or none), STALL_KEEP (unset: a directory to keep
# both round-trip files in), STALL_PHASE (default 0.5: the loop's ticks half a period after
# ping's, as in bench/control_loop.sh; "free": where the loop's start puts them). Every process is bounded in time (timeout).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="${CONTROL_LOOP_CONFIG:-file://$here/deploy/cyclonedds-loopback.xml}"
seconds=${STALL_SECONDS:-60}
rate=${STALL_RATE:-1000}
mode=${STALL_MODE:-call_then}
phase=${STALL_PHASE:-0.5}  # bench/lib/control_loop.sh's service_loop reads it
. "$here/bench/lib/ddsperf.sh"
. "$here/bench/lib/control_loop.sh"
ping_mode=$(ping_mode_of "$mode")
case ${STALL_PRIORITY:-fifo} in
  fifo) prefix="chrt -f 10" ;;
  none) prefix="" ;;
  *) echo "STALL_PRIORITY: unknown \"$STALL_PRIORITY\" (allowed: fifo, none)" >&2; exit 2 ;;
esac
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
claim_domain sdomain 8 100
work=$(mktemp -d)
service=""
cleanup() {
  ddsperf_ping_wait TERM
  ddsperf_pong_stop
  if [ -n "$service" ]; then kill "$service" 2>/dev/null || true; fi
  if [ -n "${STALL_KEEP:-}" ]; then
    mkdir -p "$STALL_KEEP"
    cp "$work"/*.rt "$STALL_KEEP"/ 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT INT TERM

echo "# $mode against ddsperf $ping_mode, at once, $seconds s at $rate Hz," \
  "priority ${STALL_PRIORITY:-fifo}, load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# shellcheck disable=SC2086 # the prefix is words
$prefix timeout $((seconds + 60)) "$build/service/gearcoupling-service" --domain "$sdomain" \
  --log-level warn &
service=$!
# shellcheck disable=SC2086
control_loop_pair "$rate" "$mode" "$seconds" "$work/service.rt" "$work/ddsperf.rt" $prefix
python3 "$here/bench/latency_stats.py" --rate-hz "$rate" "$work/service.rt" | sed 's/^/service: /'
python3 "$here/bench/latency_stats.py" --rate-hz "$rate" "$work/ddsperf.rt" | sed 's/^/ddsperf: /'
python3 "$here/bench/stall_coincidence.py" --rate-hz "$rate" "$work/service.rt" "$work/ddsperf.rt"
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
