#!/bin/sh
# The learning loop's latency and cost (docs/benchmarks.md, "Learning loop"): starts
# gearcoupling-monitor on loopback, replays the hidden-eccentricity recording into it RUNS times
# (a new test cell each time), and prints per run the time from the first health showing the
# error beyond the noise to the proposal (onset_to_proposal_s, which includes
# --diagnose-after-s), the wall time from the end of the replay to the proposal seen by
# `gearcoupling proposals`, and the diagnosis' CPU time (its thread's).
#
#   bench/learning_bench.sh [BUILD_DIR]        (default: build)
#
# LEARNING_BENCH_RUNS (3), LEARNING_BENCH_AFTER_S (1: --diagnose-after-s). Bounded in time;
# domain derived from this shell's pid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
export CYCLONEDDS_URI="file://$here/deploy/cyclonedds-loopback.xml"
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
runs=${LEARNING_BENCH_RUNS:-3}
after=${LEARNING_BENCH_AFTER_S:-1}
cli="$build/clients/cli/gearcoupling"
"$build/monitor/gearcoupling-monitor" --domain "$domain" --log-level warn --window-s 20 \
  --health-period-s 0.2 --stale-s 120 --dispose-s 300 --diagnose-after-s "$after" &
monitor=$!
trap 'kill -TERM "$monitor" 2>/dev/null || true' EXIT INT TERM
sleep 1
echo "run  onset_to_proposal_s  replay_end_to_seen_s  diagnosis_cpu_s  effects"
for run in $(seq 1 "$runs"); do
  cell="learning-bench-$run"
  "$cli" replay --in "$here/data/recordings/hidden_eccentricity_torque_ramp.csv" --test-cell "$cell" \
    --speed 20 --domain "$domain" >/dev/null
  start=$(date +%s.%N)
  for _ in $(seq 1 120); do
    json=$("$cli" proposals --test-cell "$cell" --json --discovery-s 0.5 --domain "$domain")
    if printf "%s\n" "$json" | grep -q '"state":"standing"'; then break; fi
  done
  seen=$(date +%s.%N)
  printf "%s\n" "$json" | python3 -c "
import json, sys
p = json.load(sys.stdin)['proposals']
p = p[0] if p else {}
print('$run', round(p.get('onset_to_proposal_s', float('nan')), 2), round($seen - $start, 2),
      round(p.get('diagnosis_cpu_s', float('nan')), 2), p.get('effects', 'none'), sep='  ')"
done
