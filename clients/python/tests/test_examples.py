"""The examples of clients/python/examples run as a user runs them (no display: Agg)."""

import os
import subprocess
import sys
from pathlib import Path

import pandas as pd

import gearcoupling as gc

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def run_example(name: str, *args: str, cwd: Path) -> str:
    # The module this test imported, whatever the working directory.
    environment = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(Path(gc.__file__).parents[1]))
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *args], capture_output=True,
                          text=True, timeout=300, cwd=cwd, env=environment)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_load_case_sweep_writes_every_case(tmp_path):
    out = run_example("load_case_sweep.py", "sweep.csv", cwd=tmp_path)
    table = pd.read_csv(tmp_path / "sweep.csv", float_precision="round_trip")
    assert len(table) == 360 and "360 load cases" in out
    row = table.iloc[123]
    one = gc.induced_moments("nrel_upwind", row.torque_nm, row.misalignment_rad, row.direction_rad, mu=row.mu)
    assert row.sensor_moment_y_nm == one.sensor_moment_y_nm
    assert row.teeth_in_contact == one.teeth_in_contact


def test_paper_table3_and_figure8(tmp_path):
    out = run_example("paper_table3_figure8.py", "figure8.png", cwd=tmp_path)
    assert (tmp_path / "figure8.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    lines = out.splitlines()
    # docs/model.md's Table 3 and Figure 8 tables.
    assert any(line.split()[:3] == ["nrel_upwind", "0.9", "0.7509"] for line in lines)
    assert any(line.split()[:3] == ["nrel_downwind", "1.8", "1.7217"] for line in lines)
    assert any(line.split() == ["0.50", "0.367", "58", "85.5", "235"] for line in lines)
    assert any(line.split() == ["0.75", "0.275", "42", "114.1", "271"] for line in lines)


def test_diagnose_recording_finds_the_hidden_eccentricity(tmp_path):
    out = run_example("diagnose_recording.py", "found.textproto", cwd=tmp_path)
    assert "best candidate: eccentricity" in out
    assert gc.Model(str(tmp_path / "found.textproto")).effects[-1] == "eccentricity"
