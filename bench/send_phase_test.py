#!/usr/bin/env python3
"""bench/send_phase.py on made-up runs whose offsets are known (ctest bench.send_phase_synthetic):
no timing, no DDS."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def run_file(path, start, period, ticks, wake_us=(20.0,)):
    """A run at one send a period from `start`, each woken wake_us late (cycled)."""
    with open(path, "w") as out:
        for i in range(ticks):
            out.write(f"{start + i * period + wake_us[i % len(wake_us)] / 1e6:.6f} 100.0\n")


def phase(service, ddsperf, rate_hz):
    result = subprocess.run(
        [sys.executable, os.path.join(HERE, "send_phase.py"), "--rate-hz", str(rate_hz), service,
         ddsperf], capture_output=True, text=True)
    return result.returncode, result.stdout.strip()


def main():
    failures = []

    def expect(what, got, want):
        if got != want:
            failures.append(f"{what}: {got}, {want} expected")

    with tempfile.TemporaryDirectory() as work:
        service, ddsperf = os.path.join(work, "service.rt"), os.path.join(work, "ddsperf.rt")
        # 100 Hz, the service's ticks 5 ms after ddsperf's, both woken 20 us late: half a period.
        run_file(ddsperf, 100.0, 0.01, 1000)
        run_file(service, 100.005, 0.01, 1000)
        expect("half a period at 100 Hz", phase(service, ddsperf, 100), (0, "0.50"))
        # 1 kHz, 0.9 ms after; ddsperf's wake-ups spread 20-420 us, so its latest send falls
        # 0.50-0.90 ms before the service's: the median counts, 0.70 periods.
        run_file(ddsperf, 100.0, 0.001, 3000, wake_us=(20.0, 120.0, 220.0, 320.0, 420.0))
        run_file(service, 100.0009, 0.001, 3000)
        expect("jittered ddsperf at 1 kHz", phase(service, ddsperf, 1000), (0, "0.70"))
        # The service's sends 0.1 ms before ddsperf's: 0.99 of a period after the one before.
        run_file(ddsperf, 100.0, 0.01, 1000)
        run_file(service, 99.9999, 0.01, 1000)
        expect("just before", phase(service, ddsperf, 100), (0, "0.99"))
        # No ddsperf send before any of the service's: no phase.
        run_file(ddsperf, 200.0, 0.01, 10)
        expect("nothing before", phase(service, ddsperf, 100), (1, "nan"))
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
