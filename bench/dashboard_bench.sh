#!/bin/sh
# The dashboard under load (docs/benchmarks.md, "Dashboard"): a live test cell replayed at
# 40,000 samples/s into gearcoupling-monitor (one residual per sample), the service answering a
# latency probe, first without the dashboard, then with it and 20 event-stream clients. Reports
# the dashboard's CPU share, the update latency to the clients (p50/p99), and for both phases
# the replay's achieved rate, the monitor's counts (taken, evaluated, lost) and the service's
# round trip, to show whether the dashboard slows either down.
#
#   bench/dashboard_bench.sh [BUILD_DIR]      (default: build)
#
# DASHBOARD_BENCH_SECONDS (default 15): length of each phase. DASHBOARD_BENCH_CLIENTS (default
# 20). DASHBOARD_BENCH_RATE (default 40000) samples/s. DASHBOARD_BENCH_CLIENT=browser: headless
# Chromium pages (bench/dashboard_browsers.py) instead of event-stream clients. Every process is bounded by timeout; the
# domain comes from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
seconds=${DASHBOARD_BENCH_SECONDS:-15}
clients=${DASHBOARD_BENCH_CLIENTS:-20}
rate=${DASHBOARD_BENCH_RATE:-40000}
work=$(mktemp -d)
pids=""
cleanup() {
  for pid in $pids; do kill -TERM "$pid" 2>/dev/null || true; done
  sleep 1
  for pid in $pids; do kill -KILL "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT INT TERM
cli="$build/clients/cli/gearcoupling"

# A recording long enough for a phase at the rate: data/recordings/paper_torque_ramp.csv
# (1000 rows, 10 s) again and again, its time shifted by 10 s each time.
rows=$(( rate * (seconds + 5) ))
awk -v rows="$rows" 'NR == 1 { print; next } { line[n++] = $0 }
  END { for (i = 0; i < rows; ++i) { split(line[i % n], f, ","); f[1] += 10 * int(i / n);
        out = f[1]; for (k = 2; k <= length(f); ++k) out = out "," f[k]; print out } }' \
  "$here/data/recordings/paper_torque_ramp.csv" > "$work/long.csv"

# utime + stime [ticks] of the program `timeout` $1 runs (its only child)
ticks() { awk '{ print $14 + $15 }' "/proc/$(cat "/proc/$1/task/$1/children" | cut -d' ' -f1)/stat"; }
hz=$(getconf CLK_TCK)
now() { date +%s.%N; }
share() {  # ticks $1 -> $2 over wall time $3 -> $4, as a percentage of one core
  awk -v a="$1" -v b="$2" -v t0="$3" -v t1="$4" -v hz="$hz" 'BEGIN { printf "%.1f%%", 100 * (b - a) / hz / (t1 - t0) }'
}

echo "# $(nproc) cores, load before: $(cut -d' ' -f1-3 /proc/loadavg), domain $domain, $rate samples/s, $seconds s a phase"
timeout 900 "$build/service/gearcoupling-service" --domain "$domain" 2> "$work/service.log" &
pids="$pids $!"
timeout 900 "$build/monitor/gearcoupling-monitor" --domain "$domain" --model paper 2> "$work/monitor.log" &
monitor=$!
pids="$pids $monitor"
sleep 2

phase() {  # $1 name, $2 test cell; the caller starts/stops what differs
  m0=$(ticks "$monitor"); t0=$(now)
  timeout $((seconds + 60)) "$cli" replay --in "$work/long.csv" --test-cell "$2" --rate "$rate" \
    --domain "$domain" > "$work/replay-$2.txt" &
  replay=$!
  sleep 1
  probe=$(timeout 120 "$build/bench/gc_bench_service" --domain "$domain" --latency-requests 2000 \
          --clients "" 2>&1 | grep -E "^latency (jam_angle|induced_moments) " || true)
  wait "$replay" || true
  m1=$(ticks "$monitor"); t1=$(now)
  sleep 2  # the monitor's next health
  counts=$(timeout 30 "$cli" status --domain "$domain" --json | python3 -c "
import json, sys
for c in json.load(sys.stdin)['test_cells']:
    if c['test_cell'] == '$2':
        k = c.get('counts', {}); print(f\"taken={k.get('taken', 0)} evaluated={k.get('evaluated', 0)} lost={k.get('lost', 0)}\")")
  echo "## $1"
  echo "replay: $(cat "$work/replay-$2.txt")"
  echo "monitor: $counts, CPU $(share "$m0" "$m1" "$t0" "$t1") of one core during the replay"
  echo "service probe (p50/p99 of one blocking call at a time, during the replay):"
  echo "$probe"
}

phase "without the dashboard" bench-a

timeout 900 "$build/clients/dashboard/gearcoupling-dashboard" --domain "$domain" --listen 127.0.0.1:0 \
  > "$work/dashboard.txt" 2> "$work/dashboard.log" &
dashboard=$!
pids="$pids $dashboard"
sleep 1
url=$(sed -n 's/^listening on //p' "$work/dashboard.txt")
if [ "${DASHBOARD_BENCH_CLIENT:-sse}" = browser ]; then
  # Real headless Chromium pages; the phase starts once they are all open (at most 300 s).
  /usr/bin/python3 "$here/bench/dashboard_browsers.py" "$url" "$clients" "$seconds" > "$work/sse.txt" &
  i=0
  while [ "$i" -lt 300 ] && ! grep -q ready "$work/sse.txt"; do sleep 1; i=$((i + 1)); done
else
  python3 "$here/bench/dashboard_sse_clients.py" "$url" "$clients" "$seconds" > "$work/sse.txt" &
fi
sse=$!
d0=$(ticks "$dashboard"); dt0=$(now)
phase "with the dashboard and $clients event-stream clients" bench-b
d1=$(ticks "$dashboard"); dt1=$(now)
wait "$sse" || true
echo "dashboard: CPU $(share "$d0" "$d1" "$dt0" "$dt1") of one core over the phase"
echo "clients: $(grep -v ready "$work/sse.txt")"
echo "dropped updates: $(curl -s "${url}metrics" | awk '/^gearcoupling_dashboard_updates_dropped_total/ { print $2 }')"
