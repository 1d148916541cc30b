#!/usr/bin/env python3
"""Which of the service's stalls ddsperf had at the same moment (bench/stall_coincidence.sh).

    bench/stall_coincidence.py --rate-hz 1000 SERVICE_FILE DDSPERF_FILE [--margin-ms 2]

Both files are one run each, taken at the same time (gc_bench_control_loop's --out and
bench/ddsperf_roundtrips.c's file: one "T_S ROUND_TRIP_US" line per request, T_S when it was
sent, CLOCK_MONOTONIC seconds). A stall of a program is a time in which it missed deadlines: a
round trip over 1 ms (from its send to its reply), or a gap between two sends with ticks of the
sender's rate in it at which it sent nothing (skipped); overlapping ones are merged. A stall of
the service is shared when one of ddsperf's overlaps it, each widened by the margin on either
side: the host held both programs up at once (the hypervisor, the kernel), which no design of
the service removes. The others are the service's own, and listed with ddsperf's longest round
trip in the same time (a host's slowdown that ddsperf, too, felt but kept under 1 ms shows
there): those are the ones to trace.

The deadlines the service missed (late round trips and skipped ticks, counted as
bench/latency_stats.py counts them) are split the same way.
"""
import argparse
import sys

from latency_stats import DEADLINE_US, read  # the same round-trip files, the same deadline


def grid_origin(samples, period_s):
    """A time a little before a tick of the sender's fixed rate. Each send is made at a tick plus
    the time its thread took to wake, much the same for most sends: the median of the sends'
    offsets from the first, modulo the period, less a tenth of a period. A send then belongs to
    the tick before it, unless it woke over nine tenths of a period later than most."""
    first = samples[0][0]
    offsets = sorted((t - first + period_s / 2) % period_s - period_s / 2 for t, _ in samples)
    return first + offsets[len(offsets) // 2] - 0.1 * period_s


def stalls(samples, period_s, fixed_grid):
    """[(start, end, missed deadlines)], merged where they overlap. fixed_grid: the sender's
    ticks are a fixed grid, and a send may be late by up to a period (gc_bench_control_loop);
    otherwise a send over half a period late is skipped and the next ticks count from it (ddsperf
    ping), so the ticks skipped in a gap are its length in periods, rounded, less one."""
    raw = []
    for t, us in samples:
        if us > DEADLINE_US:
            raw.append([t, t + us / 1e6, 1])
    origin = grid_origin(samples, period_s)
    for (a, _), (b, _) in zip(samples, samples[1:]):
        if fixed_grid:
            skipped = int((b - origin) // period_s) - int((a - origin) // period_s) - 1
        else:
            skipped = round((b - a) / period_s) - 1
        if skipped > 0:
            raw.append([a, b, skipped])
    raw.sort()
    merged = []
    for start, end, missed in raw:
        if merged and start <= merged[-1][1]:
            merged[-1][1] = max(merged[-1][1], end)
            merged[-1][2] += missed
        else:
            merged.append([start, end, missed])
    return merged


def shared(stall, others, margin_s):
    start, end = stall[0] - margin_s, stall[1] + margin_s
    return any(o[0] - margin_s < end and start < o[1] + margin_s for o in others)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("service")
    parser.add_argument("ddsperf")
    parser.add_argument("--rate-hz", type=float, required=True)
    parser.add_argument("--margin-ms", type=float, default=2.0)
    args = parser.parse_args(argv[1:])
    period_s = 1.0 / args.rate_hz
    service, ddsperf = sorted(read(args.service)), sorted(read(args.ddsperf))
    if not service or not ddsperf:
        print("no round trips in one of the files", file=sys.stderr)
        return 1
    # Only the time both ran: ddsperf's first second (discovery) is dropped by its caller.
    begin, end = max(service[0][0], ddsperf[0][0]), min(service[-1][0], ddsperf[-1][0])
    service = [s for s in service if begin <= s[0] <= end]
    ddsperf = [s for s in ddsperf if begin <= s[0] <= end]
    ours, theirs = stalls(service, period_s, True), stalls(ddsperf, period_s, False)
    margin_s = args.margin_ms / 1e3
    own = [s for s in ours if not shared(s, theirs, margin_s)]
    ticks = round((end - begin) / period_s) + 1
    missed = sum(s[2] for s in ours)
    own_missed = sum(s[2] for s in own)
    print(f"seconds={end - begin:.1f} ticks={ticks} service_stalls={len(ours)} "
          f"ddsperf_stalls={len(theirs)} shared={len(ours) - len(own)} service_only={len(own)} "
          f"service_missed={missed} ({100.0 * missed / ticks:.3f}%) "
          f"of_which_service_only={own_missed} ({100.0 * own_missed / ticks:.3f}%) "
          f"ddsperf_missed={sum(s[2] for s in theirs)} "
          f"({100.0 * sum(s[2] for s in theirs) / ticks:.3f}%) "
          f"(margin {args.margin_ms:g} ms)")
    for start, stop, n in own:
        near = [us for t, us in ddsperf
                if t < stop + margin_s and start - margin_s < t + us / 1e6]
        print(f"  service only: t={start:.4f} {1e3 * (stop - start):.2f} ms, {n} deadline(s); "
              f"ddsperf's longest round trip meanwhile {max(near, default=0.0):.0f} us")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
