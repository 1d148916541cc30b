#!/usr/bin/env bash
# Times `gearcoupling validate` over a synthetic recording (default 1e6 samples: the paper's
# model on a torque sweep with 2 kN·m of noise, made by `gearcoupling synth`): three runs,
# wall time and peak memory of each, then the median. Also times synth itself once. With an
# ANCHOR (another build's gearcoupling, e.g. main's), each run times the anchor too, right
# before, on the same recording with the same -j, and checks that both print the same.
#
#   bench/validate_throughput.sh [GEARCOUPLING] [SAMPLES] [THREADS] [ANCHOR]
#   (defaults: build/clients/cli/gearcoupling, 1000000, every hardware thread, none)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
gearcoupling="${1:-$here/../build/clients/cli/gearcoupling}"
samples="${2:-1000000}"
threads="${3:-$(nproc)}"
anchor="${4:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

/usr/bin/time -f "%e %M" -o "$work/time" "$gearcoupling" synth --model paper \
  --sequence torque-sweep --samples "$samples" --noise-nm 2000 --seed 1 --out "$work/rec.csv"
read -r seconds max_rss_kb < "$work/time"
echo "synth: $samples samples in $seconds s, peak RSS $((max_rss_kb / 1024)) MiB," \
     "$(du -h "$work/rec.csv" | cut -f1) of CSV; validate threads: $threads; $(nproc) hardware threads"

# One timed validate: "<seconds> <peak RSS in MiB>"; its summary in $2.
timed_validate() {
  /usr/bin/time -f "%e %M" -o "$work/time" "$1" validate --data "$work/rec.csv" \
    --model paper -j "$threads" --html "$work/report.html" > "$2"
  read -r seconds max_rss_kb < "$work/time"
  echo "$seconds $((max_rss_kb / 1024))"
}

times=()
anchor_times=()
for run in 1 2 3; do
  if [ -n "$anchor" ]; then
    read -r seconds rss < <(timed_validate "$anchor" "$work/anchor.txt")
    echo "run $run: anchor $seconds s, peak RSS $rss MiB"
    anchor_times+=("$seconds")
  fi
  read -r seconds rss < <(timed_validate "$gearcoupling" "$work/summary.txt")
  echo "run $run: $seconds s, peak RSS $rss MiB"
  times+=("$seconds")
  if [ -n "$anchor" ] && ! cmp -s "$work/anchor.txt" "$work/summary.txt"; then
    echo "the anchor prints another summary:"; diff "$work/anchor.txt" "$work/summary.txt" || true
  fi
done
median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n 2p)
echo "median: $median s for $samples samples (target <= 0.5 s)"
if [ -n "$anchor" ]; then
  anchor_median=$(printf '%s\n' "${anchor_times[@]}" | sort -n | sed -n 2p)
  echo "anchor median: $anchor_median s; ratio $(echo "scale=2; $median / $anchor_median" | bc)"
fi
sed -n 3,6p "$work/summary.txt"
