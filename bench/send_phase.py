#!/usr/bin/env python3
"""How far the service's sends fall after ddsperf's, in periods (bench/control_loop.sh).

    bench/send_phase.py --rate-hz 100 SERVICE_FILE DDSPERF_FILE

Both files are one round, taken at the same time (the round-trip files of
bench/latency_stats.py: "T_S ROUND_TRIP_US", T_S when the request was sent, CLOCK_MONOTONIC
seconds). Prints the median, over the service's sends, of the time since ddsperf's latest send
before it, in periods (0 to 1): gc_bench_control_loop --phase-of keeps it at its --phase (0.5 in
bench/control_loop.sh), where two loops left to their start times keep whatever offset those gave.
"""
import argparse
import bisect
import sys

from latency_stats import read


def send_phase(service, ddsperf, period_s):
    """Median of (service send - ddsperf's latest send before it) / period, or None without any."""
    theirs = sorted(t for t, _ in ddsperf)
    phases = []
    for t, _ in service:
        i = bisect.bisect_right(theirs, t)
        if i > 0:
            phases.append(((t - theirs[i - 1]) / period_s) % 1.0)
    if not phases:
        return None
    phases.sort()
    return phases[len(phases) // 2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rate-hz", type=float, required=True)
    parser.add_argument("service")
    parser.add_argument("ddsperf")
    args = parser.parse_args()
    phase = send_phase(read(args.service), read(args.ddsperf), 1.0 / args.rate_hz)
    if phase is None:
        print("nan")
        return 1
    print(f"{phase:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
