#!/usr/bin/env python3
"""bench/stall_coincidence.py on made-up runs whose stalls are known (ctest
bench.stall_coincidence_synthetic): no timing, no DDS."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PERIOD = 0.001


def run_file(path, start, ticks, late=(), skip=(), wake_us=60.0):
    """A 1 kHz run: a send at each tick (plus a wake-up time), 100 us round trips; `late` maps
    tick -> round trip (us), `skip` lists ticks at which nothing was sent."""
    late = dict(late)
    with open(path, "w") as out:
        for i in range(ticks):
            if i in skip:
                continue
            out.write(f"{start + i * PERIOD + wake_us / 1e6:.6f} {late.get(i, 100.0):.1f}\n")


def report(service, ddsperf):
    return subprocess.run(
        [sys.executable, os.path.join(HERE, "stall_coincidence.py"), "--rate-hz", "1000",
         service, ddsperf], check=True, capture_output=True, text=True).stdout


def main():
    with tempfile.TemporaryDirectory() as work:
        service, ddsperf = os.path.join(work, "service.rt"), os.path.join(work, "ddsperf.rt")
        # The service: a 9 ms stall at tick 2000 (one late round trip, eight ticks skipped), a
        # 1.5 ms one at tick 5000 (late, one skipped), and one skipped tick at 7000.
        run_file(service, 100.0, 10000, late={2000: 9000.0, 5000: 1500.0},
                 skip=set(range(2001, 2009)) | {5001, 7000})
        # ddsperf, sending on its own grid 0.3 ms off the service's: late pongs through the
        # first stall (it does not await them), nothing near the other two.
        run_file(ddsperf, 100.0003, 10000, late={2000 + k: 9000.0 - 1000.0 * k for k in range(8)})
        out = report(service, ddsperf)
        print(out, end="")
        first = out.splitlines()[0]
        expected = ["service_stalls=3", "shared=1", "service_only=2",
                    "service_missed=12 (0.120%)", "of_which_service_only=3 (0.030%)"]
        missing = [e for e in expected if e not in first]
        if missing or "t=105.0001" not in out or "t=106.9991" not in out:
            print(f"expected {expected} and the two service-only stalls listed", file=sys.stderr)
            return 1
        # Wake-up times that differ from send to send by less than a period skip nothing.
        run_file(service, 100.0, 3000, wake_us=60.0)
        with open(service) as text:
            lines = text.readlines()
        with open(service, "w") as out_file:
            for n, line in enumerate(lines):
                t, us = line.split()
                out_file.write(f"{float(t) + (0.0006 if n % 7 == 0 else 0.0):.6f} {us}\n")
        run_file(ddsperf, 100.0, 3000)
        quiet = report(service, ddsperf)
        print(quiet, end="")
        if "service_stalls=0" not in quiet:
            print("late wake-ups within a period were counted as stalls", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
