#!/usr/bin/env python3
"""When the hypervisor took a CPU away, during a benchmark run (bench/control_loop.sh).

    bench/steal_log.py SECONDS FILE

Reads every CPU's steal time in /proc/stat every 10 ms for SECONDS and writes a line
"T_S STOLEN_MS" to FILE whenever it grew: T_S when it was seen (CLOCK_MONOTONIC seconds, as the
round trips' files), STOLEN_MS the most any one CPU lost since the look before. The kernel counts
steal in ticks of 10 ms and adds them when the virtual CPU runs again, so a CPU taken away for
100 ms shows as 100 ms at its end. bench/latency_stats.py --steal FILE then sets apart the round
trips that overlapped it.
"""
import sys
import time

INTERVAL_S = 0.01
TICK_MS = 10  # USER_HZ = 100: /proc/stat counts in hundredths of a second


def steal_per_cpu():
    with open("/proc/stat") as stat:
        return [int(line.split()[8]) for line in stat
                if line.startswith("cpu") and not line.startswith("cpu ")]


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    end = time.monotonic() + float(argv[1])
    before = steal_per_cpu()
    with open(argv[2], "w") as out:
        while time.monotonic() < end:
            time.sleep(INTERVAL_S)
            now = steal_per_cpu()
            grown = max(b - a for a, b in zip(before, now))
            if grown > 0:
                out.write(f"{time.monotonic():.4f} {grown * TICK_MS}\n")
                out.flush()
            before = now
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
