#!/bin/sh
# The live test cell at rate (docs/benchmarks.md, "Live test cell"): starts gearcoupling-monitor
# on loopback, then gc_bench_live with CELLS test cells at RATE Hz each for SECONDS, once per
# batching in BATCHES (us between DDS samples of a cell; 0 = one sample per DDS sample).
#
#   bench/live_bench.sh [BUILD_DIR]        (default: build)
#
# LIVE_BENCH_CELLS (4), LIVE_BENCH_RATE (10000), LIVE_BENCH_SECONDS (10),
# LIVE_BENCH_BATCHES ("1000 0"), LIVE_BENCH_SWAP_MS (0; 100: a model swap to every cell every
# 100 ms), LIVE_BENCH_RT (empty; "1": monitor and publishers under
# SCHED_FIFO priority 10 with chrt, as on a test cell's own host), LIVE_BENCH_MONITOR_ARGS (empty;
# more flags of gearcoupling-monitor, e.g. "--model paper_downwind --diagnose-after-s 1
# --rediagnose-s 0": every cell's error beyond the noise, so diagnoses run back to back the
# whole time). Bounded in time; domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
cells=${LIVE_BENCH_CELLS:-4}
rate=${LIVE_BENCH_RATE:-10000}
seconds=${LIVE_BENCH_SECONDS:-10}
batches=${LIVE_BENCH_BATCHES:-1000 0}
rt=""
if [ -n "${LIVE_BENCH_RT:-}" ]; then rt="chrt -f 10"; fi
monitor=""
cleanup() { if [ -n "$monitor" ]; then kill -TERM "$monitor" 2>/dev/null || true; fi; }
trap cleanup EXIT INT TERM
for batch in $batches; do
  # shellcheck disable=SC2086 # LIVE_BENCH_MONITOR_ARGS is a list of flags
  $rt "$build/monitor/gearcoupling-monitor" --domain "$domain" --log-level info ${LIVE_BENCH_MONITOR_ARGS:-} &
  monitor=$!
  sleep 1
  timeout $((seconds + 60)) $rt "$build/bench/gc_bench_live" --domain "$domain" --cells "$cells" \
    --rate "$rate" --seconds "$seconds" --batch-us "$batch" --monitor-pid "$monitor" \
    --swap-ms "${LIVE_BENCH_SWAP_MS:-0}" || true
  kill -TERM "$monitor"; wait "$monitor" || true
  monitor=""
done
