#!/usr/bin/env python3
"""The figures of one control-loop run (bench/control_loop.sh) from its round trips.

    bench/latency_stats.py --rate-hz 1000 FILE...             # one line of figures
    bench/latency_stats.py --rate-hz 1000 --late 1000 FILE... # and every round trip over 1000 us,
                                                              # with the time since the one before

Each FILE is one run (a round of bench/control_loop.sh); the figures pool the runs. A FILE has
one "T_S ROUND_TRIP_US" line per request: T_S when it was sent (CLOCK_MONOTONIC
seconds), as gc_bench_control_loop and bench/ddsperf_roundtrips.c write them, so the service
and ddsperf are summed up by the same code. A percentile is the value at rank floor(p * n) of
the sorted round trips, as in bench/service_bench.cc.

The figures: n, p50, p99, p99.9 and the maximum of the round trips; over_1ms, the share of
round trips over 1 ms; skipped, the ticks of the rate from the first send to the last at which
nothing was sent (a request still out, in gc_bench_control_loop; in ddsperf, a ping more than half
a period late, which it skips); missed, the share of ticks whose deadline
was missed, (round trips over 1 ms + ticks skipped) / (round trips + ticks skipped). ddsperf's
ping does not wait for a pong before the next ping, so a stall of 5 ms makes five late round
trips; the control loop awaits each request, so the same stall makes one late round trip and
four skipped ticks: `missed` counts both alike.
"""
import argparse
import sys

DEADLINE_US = 1000.0


def read(path):
    samples = []
    with open(path) as text:
        for line in text:
            fields = line.split()
            if len(fields) == 2:
                samples.append((float(fields[0]), float(fields[1])))
    return samples


def percentile(sorted_us, p):
    return sorted_us[min(int(p * len(sorted_us)), len(sorted_us) - 1)]


def skipped_ticks(samples, period_s):
    """Ticks of the rate, from the first send of a run to its last, at which nothing was sent."""
    if not samples:
        return 0
    return max(0, round((samples[-1][0] - samples[0][0]) / period_s) + 1 - len(samples))


def summary(runs, rate_hz):
    samples = [s for run in runs for s in run]
    if not samples:
        return "n=0 p50=nan p99=nan p999=nan max=nan over_1ms=nan skipped=nan missed=nan"
    us = sorted(u for _, u in samples)
    over = sum(1 for u in us if u > DEADLINE_US)
    skipped = sum(skipped_ticks(run, 1.0 / rate_hz) for run in runs)
    return (f"n={len(us)} p50={percentile(us, 0.50):.1f}us p99={percentile(us, 0.99):.1f}us "
            f"p999={percentile(us, 0.999):.1f}us max={us[-1]:.1f}us "
            f"over_1ms={100.0 * over / len(us):.3f}% skipped={skipped} "
            f"missed={100.0 * (over + skipped) / (len(us) + skipped):.3f}%")


def late(samples, threshold_us):
    """Round trips over the threshold: when, how long, and how long after the one before."""
    lines = []
    previous = None
    start = samples[0][0] if samples else 0.0
    for t, u in samples:
        if u <= threshold_us:
            continue
        gap = "" if previous is None else f" +{1e3 * (t - previous):.1f} ms"
        lines.append(f"  t={t - start:8.4f} s {u:8.1f} us{gap}")
        previous = t
    return lines


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+", metavar="FILE")
    parser.add_argument("--rate-hz", type=float, required=True, help="the rate of the sends")
    parser.add_argument("--late", type=float, metavar="US",
                        help="also list every round trip over US microseconds")
    args = parser.parse_args(argv[1:])
    runs = [read(path) for path in args.files]
    print(summary(runs, args.rate_hz))
    if args.late is not None:
        for path, run in zip(args.files, runs):
            print("\n".join([f"{path}:"] + late(run, args.late)))
    return 0 if any(runs) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
