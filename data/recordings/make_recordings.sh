#!/usr/bin/env bash
# Regenerates the bundled recordings (docs/recordings.md) with `gearcoupling synth`: the same
# commands give the same bytes. Usage: data/recordings/make_recordings.sh [path/to/gearcoupling]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
gearcoupling="${1:-$here/../../build/clients/cli/gearcoupling}"
common=(--samples 1000 --noise-nm 2000 --seed 1)
for sequence in moment-sweep torque-sweep torque-ramp; do
  "$gearcoupling" synth --model paper --sequence "$sequence" "${common[@]}" \
    --out "$here/paper_${sequence//-/_}.csv"
done
"$gearcoupling" synth --model paper_downwind --sequence moment-sweep "${common[@]}" \
  --out "$here/paper_downwind_moment_sweep.csv"
"$gearcoupling" synth --model "$here/hidden_eccentricity.truth.textproto" --sequence torque-ramp \
  "${common[@]}" --out "$here/hidden_eccentricity_torque_ramp.csv"
"$gearcoupling" synth --model "$here/hidden_loading_friction.truth.textproto" --sequence moment-sweep \
  "${common[@]}" --out "$here/hidden_loading_friction_moment_sweep.csv"
"$gearcoupling" synth --model "$here/hidden_daq_skew.truth.textproto" --sequence torque-ramp \
  "${common[@]}" --out "$here/hidden_daq_skew_torque_ramp.csv"
# A bridge amplifier at its rail: the moment sweep with M_sy' clipped at -200 kN·m, as a DAQ whose
# range was set too tight records it (docs/tutorial.md, "Data quality before physics").
awk -F, -v OFS=, 'NR > 1 && $5 < -200000 { $5 = -200000 } { print }' "$here/paper_moment_sweep.csv" \
  > "$here/paper_moment_sweep_clipped.csv"
