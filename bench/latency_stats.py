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

With --steal FILE (bench/steal_log.py's log of the same run), the round trips that overlapped a
time when the hypervisor had taken a CPU away, and the ticks skipped in a gap between two sends
that overlapped one, are set apart: stolen, how many; missed_unstolen, the share of the other
ticks' deadlines missed. The guest cannot prevent a 100 ms stall of its virtual CPU, and one
such stall in a 9 s run is 1.1 % of its ticks: this tells the program's misses from the host's.
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


def read_steal(path):
    """Windows (start, end) in which a CPU was taken away: STOLEN_MS before each log line's time,
    10 ms (the log's interval and the kernel's tick) on either side."""
    windows = []
    with open(path) as text:
        for line in text:
            fields = line.split()
            if len(fields) == 2:
                t, stolen_ms = float(fields[0]), float(fields[1])
                windows.append((t - stolen_ms / 1e3 - 0.01, t + 0.01))
    return windows


def overlaps(windows, start, end):
    return any(a < end and start < b for a, b in windows)


def set_apart(run, period_s, windows):
    """(round trips, skipped ticks) of a run that overlapped a window."""
    trips = sum(1 for t, u in run if overlaps(windows, t, t + u / 1e6))
    skipped = sum(max(0, round((b[0] - a[0]) / period_s) - 1)
                  for a, b in zip(run, run[1:]) if overlaps(windows, a[0], b[0]))
    return trips, skipped


def unstolen(runs, period_s, windows, over, skipped):
    """The stolen and missed_unstolen fields."""
    kept = [[s for s in run if not overlaps(windows, s[0], s[0] + s[1] / 1e6)] for run in runs]
    n = sum(len(run) for run in kept)
    late = sum(1 for run in kept for _, u in run if u > DEADLINE_US)
    apart = [set_apart(run, period_s, windows) for run in runs]
    stolen_trips = sum(a for a, _ in apart)
    kept_skipped = max(0, skipped - sum(b for _, b in apart))
    share = 100.0 * (late + kept_skipped) / (n + kept_skipped) if n + kept_skipped else float("nan")
    return f" stolen={stolen_trips + skipped - kept_skipped} missed_unstolen={share:.3f}%"


def skipped_ticks(samples, period_s):
    """Ticks of the rate, from the first send of a run to its last, at which nothing was sent."""
    if not samples:
        return 0
    return max(0, round((samples[-1][0] - samples[0][0]) / period_s) + 1 - len(samples))


def summary(runs, rate_hz, windows=None):
    samples = [s for run in runs for s in run]
    if not samples:
        return ("n=0 p50=nan p99=nan p999=nan max=nan over_1ms=nan skipped=nan missed=nan"
                " stolen=nan missed_unstolen=nan")
    us = sorted(u for _, u in samples)
    over = sum(1 for u in us if u > DEADLINE_US)
    skipped = sum(skipped_ticks(run, 1.0 / rate_hz) for run in runs)
    return (f"n={len(us)} p50={percentile(us, 0.50):.1f}us p99={percentile(us, 0.99):.1f}us "
            f"p999={percentile(us, 0.999):.1f}us max={us[-1]:.1f}us "
            f"over_1ms={100.0 * over / len(us):.3f}% skipped={skipped} "
            f"missed={100.0 * (over + skipped) / (len(us) + skipped):.3f}%"
            + ("" if windows is None else unstolen(runs, 1.0 / rate_hz, windows, over, skipped)))


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
    parser.add_argument("--steal", metavar="FILE",
                        help="bench/steal_log.py's log: set apart what overlapped stolen time")
    parser.add_argument("--late", type=float, metavar="US",
                        help="also list every round trip over US microseconds")
    args = parser.parse_args(argv[1:])
    runs = [read(path) for path in args.files]
    windows = read_steal(args.steal) if args.steal else None
    print(summary(runs, args.rate_hz, windows))
    if args.late is not None:
        for path, run in zip(args.files, runs):
            print("\n".join([f"{path}:"] + late(run, args.late)))
    return 0 if any(runs) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
