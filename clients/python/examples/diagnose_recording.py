#!/usr/bin/env python3
"""Diagnosis of a bundled recording: which effect the paper's model lacks on a torque ramp with
a hidden eccentricity, the error before and after adding it, and the model written out.

    PYTHONPATH=build/clients/python python3 clients/python/examples/diagnose_recording.py found.textproto
"""

import sys
from pathlib import Path

import pandas as pd

import gearcoupling as gc


def main(model_path: str) -> None:
    csv = Path(gc.bundled_data_dir("recordings")) / "hidden_eccentricity_torque_ramp.csv"
    recording = pd.read_csv(csv, float_precision="round_trip")  # any DataFrame with these columns
    result = gc.diagnose(recording, "paper", write_model=model_path)
    for number, round_ in enumerate(result.rounds, 1):
        best = round_.ranking[0] if round_.ranking else None
        print(f"round {number}: {round_.outcome}; best candidate: {best.effect if best else '-'}")
    print(result.summary)
    print("effects found:", ", ".join(result.model.effects))

    before = gc.validate(csv, "paper")
    after = gc.validate(csv, result.model)
    for channel in ("msy", "msz"):
        print(f"RMSE of {channel}: {getattr(before.models[0].overall, channel).rmse_nm:.0f} N·m before, "
              f"{getattr(after.models[0].overall, channel).rmse_nm:.0f} N·m with the effects found")
    print(f"model -> {model_path}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "diagnosed.textproto")
