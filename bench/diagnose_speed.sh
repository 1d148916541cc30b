#!/bin/sh
# `gearcoupling diagnose` end to end on 20,000 and 150,000 rows, with a hidden effect and on noise
# alone (docs/benchmarks.md, "Diagnose"; issue 37 item 6: under 2 s and 5 s on the 2-core machine).
#
#   bench/diagnose_speed.sh [BUILD_DIR] [RUNS]        (defaults: build, 5)
#
# The recordings are made with `gearcoupling synth` (2 kN·m of noise, seed 3): the paper's model
# plus a hub-sleeve eccentricity (data/recordings/hidden_eccentricity.truth.textproto) on the
# torque ramp, found in round 1, then noise; and the paper's model alone on the moment sweep,
# noise at once. Each diagnose is timed RUNS times (wall, and user + system CPU: on a shared
# machine the CPU time says what the wall time would be on a quiet one, over the 2 cores).
# DIAGNOSE_SPEED_ANCHOR=path/to/another/gearcoupling times that binary on the same files in the
# same run, alternating with this one (the anchor of docs/benchmarks.md: e.g. the build before a
# change). Prints one line per recording and binary: the medians, then every run.
set -eu
build="${1:-build}"
runs="${2:-5}"
here="$(cd "$(dirname "$0")/.." && pwd)"
gearcoupling="$build/clients/cli/gearcoupling"
anchor="${DIAGNOSE_SPEED_ANCHOR:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

synth() {  # NAME MODEL SEQUENCE SAMPLES
  "$gearcoupling" synth --model "$2" --sequence "$3" --samples "$4" --noise-nm 2000 --seed 3 \
    --out "$work/$1.csv" 2>/dev/null
}
effect="$here/data/recordings/hidden_eccentricity.truth.textproto"
synth effect_20k "$effect" torque-ramp 20000
synth noise_20k paper moment-sweep 20000
synth effect_150k "$effect" torque-ramp 150000
synth noise_150k paper moment-sweep 150000

# One run: "wall cpu" in seconds.
timed() {  # BINARY CSV
  /usr/bin/time -f "%e %U %S" -o "$work/time" "$1" diagnose --data "$2" --model paper >/dev/null
  awk '{ printf "%.2f %.2f\n", $1, $2 + $3 }' "$work/time"
}

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for name in effect_20k noise_20k effect_150k noise_150k; do
  : >"$work/this"
  : >"$work/anchor"
  for run in $(seq "$runs"); do
    timed "$gearcoupling" "$work/$name.csv" >>"$work/this"
    [ -n "$anchor" ] && timed "$anchor" "$work/$name.csv" >>"$work/anchor"
  done
  for who in this anchor; do
    [ -s "$work/$who" ] || continue
    wall="$(cut -d' ' -f1 "$work/$who" | median)"
    cpu="$(cut -d' ' -f2 "$work/$who" | median)"
    printf '%s %s: median wall %s s, cpu %s s; runs (wall cpu): %s\n' "$name" "$who" "$wall" "$cpu" \
      "$(paste -sd, "$work/$who")"
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
