#!/usr/bin/env python3
"""The Python module against `gearcoupling batch` on the same load cases (docs/benchmarks.md,
"Python").

In process: ROWS cases of contact + moments (eqs 5-48) from numpy arrays through
gearcoupling.induced_moments_many, against `gearcoupling batch` reading them from CSV and writing
results to CSV. Remote: REMOTE_ROWS cases through one gearcoupling-service (loopback, a domain
of this run's own) with Client.induced_moments_many, against `batch --remote -j 32`. Three runs
each, medians of the wall times.

    PYTHONPATH=build/clients/python /usr/bin/python3 bench/python_throughput.py
        [--rows 1000000] [--remote-rows 100000] [--jobs N] [--in-flight 256] [--build build]
        [--skip-in-process] [--skip-remote]
"""

import argparse
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import gearcoupling as gc

SOURCE = Path(__file__).resolve().parents[1]


def cases(rows: int) -> dict:
    """Load cases over the upwind coupling's range (as bench/batch_throughput.sh): torque
    0.2-2 MN·m, misalignment below its 0.75 deg jam angle, any direction, mu 0-0.2."""
    rng = np.random.default_rng(12345)
    return {"torque_nm": 2e5 + 1.8e6 * rng.random(rows), "misalignment_deg": 0.74 * rng.random(rows),
            "direction_deg": 360.0 * rng.random(rows), "mu": 0.2 * rng.random(rows)}


def write_csv(path: Path, load_cases: dict) -> None:
    columns = list(load_cases)
    with open(path, "w") as out:
        out.write(",".join(columns) + "\n")
        for row in zip(*(load_cases[c].tolist() for c in columns)):
            out.write(",".join(repr(value) for value in row) + "\n")


def arrays(load_cases: dict) -> tuple:
    """The cases as the module takes them: degrees to radians exactly as the CLI converts."""
    return (load_cases["torque_nm"], load_cases["misalignment_deg"] * np.pi / 180.0,
            load_cases["direction_deg"] * np.pi / 180.0, load_cases["mu"])


def median_of_3(label: str, run) -> float:
    times = []
    for number in (1, 2, 3):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
        print(f"  {label} run {number}: {times[-1]:.3f} s", flush=True)
    return statistics.median(times)


def batch(cli: str, csv: Path, out: Path, *flags: str) -> None:
    subprocess.run([cli, "batch", "--in", str(csv), "--out", str(out), *flags], check=True)


def in_process(cli: str, rows: int, jobs: int, work: Path) -> None:
    load_cases = cases(rows)
    csv = work / "cases.csv"
    write_csv(csv, load_cases)
    inputs = arrays(load_cases)
    print(f"in process: {rows} cases, {jobs} threads")
    cli_s = median_of_3("gearcoupling batch -j %d" % jobs,
                        lambda: batch(cli, csv, work / "results.csv", "-j", str(jobs)))
    python_s = median_of_3("induced_moments_many",
                           lambda: gc.induced_moments_many("nrel_upwind", *inputs[:3], mu=inputs[3],
                                                           threads=jobs))
    print(f"medians: batch {cli_s:.3f} s, Python {python_s:.3f} s; Python/batch = {python_s / cli_s:.2f} "
          f"(target <= 1.3)")


def remote(cli: str, service: str, rows: int, in_flight: int, work: Path) -> None:
    load_cases = cases(rows)
    csv = work / "remote_cases.csv"
    write_csv(csv, load_cases)
    inputs = arrays(load_cases)
    domain = 1 + os.getpid() % 200
    os.environ["CYCLONEDDS_URI"] = f"file://{SOURCE}/deploy/cyclonedds-loopback.xml"
    process = subprocess.Popen([service, "--domain", str(domain), "--log-level", "warn"])
    try:
        client = gc.Client(domain=domain, timeout=60.0)
        assert client.wait_for_service(30.0), "no service"
        print(f"remote: {rows} cases (2 requests each), one service on domain {domain}")
        cli_s = median_of_3("batch --remote -j 32",
                            lambda: batch(cli, csv, work / "remote_results.csv", "--remote",
                                          "--domain", str(domain), "-j", "32", "--timeout", "60"))
        python_s = median_of_3(f"Client.induced_moments_many in_flight={in_flight}",
                               lambda: client.induced_moments_many("nrel_upwind", *inputs[:3], mu=inputs[3],
                                                                   in_flight=in_flight))
        print(f"medians: batch --remote {cli_s:.3f} s ({rows / cli_s:.0f} cases/s), Python {python_s:.3f} s "
              f"({rows / python_s:.0f} cases/s); Python/batch throughput = {cli_s / python_s:.2f} "
              f"(target >= 0.5)")
    finally:
        process.send_signal(signal.SIGTERM)
        process.wait(timeout=20)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--remote-rows", type=int, default=100_000)
    parser.add_argument("--jobs", type=int, default=os.cpu_count())
    parser.add_argument("--in-flight", type=int, default=256)
    parser.add_argument("--build", default=str(SOURCE / "build"))
    parser.add_argument("--skip-remote", action="store_true")
    parser.add_argument("--skip-in-process", action="store_true")
    args = parser.parse_args()
    cli = f"{args.build}/clients/cli/gearcoupling"
    print(f"{os.cpu_count()} hardware threads; load average {os.getloadavg()[0]:.2f}")
    with tempfile.TemporaryDirectory() as work:
        if not args.skip_in_process:
            in_process(cli, args.rows, args.jobs, Path(work))
        if not args.skip_remote:
            remote(cli, f"{args.build}/service/gearcoupling-service", args.remote_rows, args.in_flight, Path(work))


if __name__ == "__main__":
    sys.exit(main())
