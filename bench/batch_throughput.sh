#!/usr/bin/env bash
# Times `gearcoupling batch` over a generated CSV of load cases (default 1e6 rows) on the
# bundled upwind coupling: three runs, wall time, CPU time and peak memory of each, then the
# median wall time. CPU time shows what the runs cost when other work shares the cores.
#
#   bench/batch_throughput.sh [GEARCOUPLING] [ROWS] [JOBS]
#   (defaults: build/clients/cli/gearcoupling, 1000000, every hardware thread)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
gearcoupling="${1:-$here/../build/clients/cli/gearcoupling}"
rows="${2:-1000000}"
jobs="${3:-$(nproc)}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Load cases spread over the upwind coupling's range: torque 0.2-2 MN·m, misalignment below
# its 0.75 deg jam angle, any direction, mu 0-0.2. Deterministic (fixed seed).
awk -v rows="$rows" 'BEGIN {
  srand(12345);
  print "torque_nm,misalignment_deg,direction_deg,mu";
  for (i = 0; i < rows; ++i)
    printf "%.6g,%.4g,%.4g,%.3g\n", 2e5 + 1.8e6 * rand(), 0.74 * rand(), 360 * rand(), 0.2 * rand();
}' > "$work/cases.csv"
echo "input: $rows rows, $(du -h "$work/cases.csv" | cut -f1); jobs: $jobs; $(nproc) hardware threads"

times=()
for run in 1 2 3; do
  /usr/bin/time -f "%e %M %U %S" -o "$work/time" \
    "$gearcoupling" batch --in "$work/cases.csv" --out "$work/results.csv" -j "$jobs"
  read -r seconds max_rss_kb user_s system_s < "$work/time"
  echo "run $run: ${seconds} s wall, ${user_s} s user + ${system_s} s system CPU," \
    "peak RSS ${max_rss_kb} KiB, $(($(wc -l < "$work/results.csv") - 1)) result rows"
  times+=("$seconds")
done
median="$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p)"
echo "median of 3: ${median} s wall for $rows rows"
