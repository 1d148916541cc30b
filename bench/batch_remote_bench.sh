#!/usr/bin/env bash
# Batches over DDS against the in-process batch, side by side in one run (issue 40): the same
# generated CSV of load cases (default 10^6 rows: contact and induced moments on the bundled
# upwind coupling, as bench/batch_throughput.sh makes them) through
#   gearcoupling batch -j JOBS                       (in process, every core)
#   gearcoupling batch --remote -j REMOTE_JOBS       (gearcoupling-service on this host, loopback,
#                                                     512 cases per request)
# alternately, ROUNDS rounds; wall time of each, cases/s, the ratio remote/in-process per round and
# of the medians, and whether the two outputs are byte for byte the same.
#
#   bench/batch_remote_bench.sh [ROWS] [ROUNDS] [JOBS] [REMOTE_JOBS]
#   (defaults: 1000000, 3, every hardware thread, 4; GC_BUILD_DIR: build/)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${GC_BUILD_DIR:-$here/../build}"
gearcoupling="$build/clients/cli/gearcoupling"
service_bin="$build/service/gearcoupling-service"
rows="${1:-1000000}"
rounds="${2:-3}"
jobs="${3:-$(nproc)}"
remote_jobs="${4:-4}"
work="$(mktemp -d)"
domain="${GC_DOMAIN:-$((120 + RANDOM % 100))}"
export CYCLONEDDS_URI="file://$here/../deploy/cyclonedds-loopback.xml"
service_pid=""
cleanup() {
  if [[ -n "$service_pid" ]]; then kill "$service_pid" 2>/dev/null || true; wait "$service_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

awk -v rows="$rows" 'BEGIN {
  srand(12345);
  print "torque_nm,misalignment_deg,direction_deg,mu";
  for (i = 0; i < rows; ++i)
    printf "%.6g,%.4g,%.4g,%.3g\n", 2e5 + 1.8e6 * rand(), 0.74 * rand(), 360 * rand(), 0.2 * rand();
}' > "$work/cases.csv"

"$service_bin" --domain "$domain" --log-level warn > "$work/service.log" 2>&1 &
service_pid=$!
echo "input: $rows rows; in process -j $jobs; remote -j $remote_jobs, service: 2 workers" \
  "(default: one per hardware thread), domain $domain; $(nproc) hardware threads"

wall() {  # wall seconds of "$@", output to $work/out.csv
  local start end
  start=$(date +%s.%N)
  "$@" > /dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}

local_times=(); remote_times=()
for round in $(seq 1 "$rounds"); do
  t_local=$(wall "$gearcoupling" batch --in "$work/cases.csv" --out "$work/local.csv" --coupling nrel_upwind -j "$jobs")
  t_remote=$(wall "$gearcoupling" batch --in "$work/cases.csv" --out "$work/remote.csv" --coupling nrel_upwind \
    -j "$remote_jobs" --remote --domain "$domain" --timeout-s 60)
  same="identical"
  cmp -s "$work/local.csv" "$work/remote.csv" || same="DIFFERENT"
  printf 'round %d: in process %.3f s (%.0f cases/s), remote %.3f s (%.0f cases/s), ratio %.2f, outputs %s\n' \
    "$round" "$t_local" "$(echo "$rows / $t_local" | bc -l)" "$t_remote" "$(echo "$rows / $t_remote" | bc -l)" \
    "$(echo "$t_local / $t_remote" | bc -l)" "$same"
  local_times+=("$t_local"); remote_times+=("$t_remote")
done
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
m_local=$(median "${local_times[@]}"); m_remote=$(median "${remote_times[@]}")
printf 'median of %d: in process %.3f s (%.0f cases/s), remote %.3f s (%.0f cases/s): remote at %.2fx in-process throughput\n' \
  "$rounds" "$m_local" "$(echo "$rows / $m_local" | bc -l)" "$m_remote" "$(echo "$rows / $m_remote" | bc -l)" \
  "$(echo "$m_local / $m_remote" | bc -l)"
