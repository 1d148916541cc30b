#!/usr/bin/env python3
"""A load-case sweep written to CSV: torque x misalignment x direction for the upwind coupling,
contact and induced moments (eqs 5-48) on all cores in one vectorised call.

    PYTHONPATH=build/clients/python python3 clients/python/examples/load_case_sweep.py sweep.csv
"""

import math
import sys

import numpy as np
import pandas as pd

import gearcoupling as gc


def main(out_path: str) -> None:
    coupling = gc.Coupling("nrel_upwind")
    torque_nm = np.linspace(2.5e5, 2.5e6, 10)
    # Up to 90 % of the jam angle: beyond it the coupling jams (InvalidInput).
    misalignment_rad = np.linspace(0.0, 0.9 * coupling.jam_angle_rad, 12)
    direction_rad = np.radians([0.0, 45.0, 90.0])
    # Broadcast as numpy does: torque down axis 0, misalignment along 1, direction along 2.
    results = gc.induced_moments_many(coupling, torque_nm[:, None, None],
                                      misalignment_rad[None, :, None], direction_rad, mu=0.1)
    table = results.to_frame()  # one row per case: the inputs, then the results
    table.to_csv(out_path, index=False)
    worst = table.loc[table.magnitude_nm.idxmax()]
    print(f"{len(table)} load cases -> {out_path}")
    print(f"largest |M'| {worst.magnitude_nm:.0f} N·m at T = {worst.torque_nm:.3g} N·m, "
          f"zeta = {math.degrees(worst.misalignment_rad):.3f} deg")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "load_case_sweep.csv")
