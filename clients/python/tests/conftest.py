"""Shared by the module's tests: the CLI and the service from the build (ctest passes their
paths), the source tree's data, and degrees as the CLI converts them."""

import math
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("GC_SOURCE_DIR", Path(__file__).resolve().parents[3]))
DATA = SOURCE_DIR / "data"


def rad(degrees: float) -> float:
    """Degrees to radians exactly as the CLI does (codec/angle_units.h: deg * pi / 180)."""
    return degrees * math.pi / 180.0


def random_cases(n: int, seed: int):
    """n load cases over the couplings' range: torque [N·m], misalignment and direction [rad], mu."""
    import numpy as np

    rng = np.random.default_rng(seed)
    return (rng.uniform(2e5, 2.5e6, n), rng.uniform(0.0, rad(0.6), n),
            rng.uniform(-np.pi, np.pi, n), rng.uniform(0.0, 0.3, n))


@pytest.fixture(scope="session")
def cli():
    """Runs the CLI; returns its standard output (bytes). Fails the test on a non-zero exit."""
    binary = os.environ.get("GC_CLI")
    if not binary:
        pytest.skip("GC_CLI not set (run through ctest)")

    def run(*args: str, cwd=None) -> bytes:
        done = subprocess.run([binary, *args], capture_output=True, timeout=120, cwd=cwd)
        assert done.returncode == 0, done.stderr.decode()
        return done.stdout

    return run


def read_textproto(path: Path) -> dict:
    """A flat coupling file (scalars and one level of nested messages, '#' comments) as the dict
    the module takes: what a script might build from its own records."""
    fields: dict = {}
    target = fields
    for line in path.read_text().splitlines():
        line = line.split("#")[0].strip()
        if not line:
            continue
        if line.endswith("{"):
            target = fields.setdefault(line[:-1].strip(), {})
        elif line == "}":
            target = fields
        else:
            key, value = (part.strip() for part in line.split(":", 1))
            target[key] = value.strip('"') if value.startswith('"') else float(value)
    return fields
