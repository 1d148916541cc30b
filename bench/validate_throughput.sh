#!/usr/bin/env bash
# Times `gearcoupling validate` over a synthetic recording (default 1e6 samples: the paper's
# model on a torque sweep with 2 kN·m of noise, made by `gearcoupling synth`): three runs,
# wall time and peak memory of each, then the median. Also times synth itself once.
#
#   bench/validate_throughput.sh [GEARCOUPLING] [SAMPLES] [THREADS]
#   (defaults: build/clients/cli/gearcoupling, 1000000, every hardware thread)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
gearcoupling="${1:-$here/../build/clients/cli/gearcoupling}"
samples="${2:-1000000}"
threads="${3:-$(nproc)}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

/usr/bin/time -f "%e %M" -o "$work/time" "$gearcoupling" synth --model paper \
  --sequence torque-sweep --samples "$samples" --noise-nm 2000 --seed 1 --out "$work/rec.csv"
read -r seconds max_rss_kb < "$work/time"
echo "synth: $samples samples in $seconds s, peak RSS $((max_rss_kb / 1024)) MiB," \
     "$(du -h "$work/rec.csv" | cut -f1) of CSV; validate threads: $threads; $(nproc) hardware threads"

times=()
for run in 1 2 3; do
  /usr/bin/time -f "%e %M" -o "$work/time" "$gearcoupling" validate --data "$work/rec.csv" \
    --model paper -j "$threads" --html "$work/report.html" > "$work/summary.txt"
  read -r seconds max_rss_kb < "$work/time"
  echo "run $run: $seconds s, peak RSS $((max_rss_kb / 1024)) MiB"
  times+=("$seconds")
done
median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n 2p)
echo "median: $median s for $samples samples (target < 5 s)"
sed -n 3,6p "$work/summary.txt"
