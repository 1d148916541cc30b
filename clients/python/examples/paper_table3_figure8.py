#!/usr/bin/env python3
"""The paper's Table 3 (jam angles) and Figure 8 (tooth loads of the upwind coupling at
1.5 MN·m as the misalignment grows), with a plot (docs/model.md compares them with the paper).

    PYTHONPATH=build/clients/python python3 clients/python/examples/paper_table3_figure8.py figure8.png
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402

import gearcoupling as gc  # noqa: E402

PAPER_TABLE3_DEG = {"nrel_upwind": 0.9, "nrel_downwind": 1.8}
FIGURE8_TORQUE_NM = 1.5e6
FIGURE8_MISALIGNMENT_DEG = [0.0, 0.1, 0.5, 0.7, 0.75]


def table3() -> None:
    print("Table 3: jam angle [deg] (eqs 23-35)")
    print(f"{'coupling':<15}{'paper':>8}{'ours':>9}{'eq 30':>9}{'eq 34':>9}  governing")
    for name, paper in PAPER_TABLE3_DEG.items():
        jam = gc.jam_angle(name)
        print(f"{name:<15}{paper:>8.1f}{jam.angle_deg:>9.4f}{jam.facewidth_deg:>9.4f}"
              f"{jam.radial_deg:>9.4f}  {jam.governing}")


def figure8(png_path: str) -> None:
    print(f"\nFigure 8: nrel_upwind at {FIGURE8_TORQUE_NM:.3g} N·m")
    print(f"{'zeta [deg]':>10}{'q':>8}{'teeth':>7}{'peak [kN]':>11}{'contact [MPa]':>15}")
    figure, axes = plt.subplots(figsize=(8, 4.5))
    for zeta_deg in FIGURE8_MISALIGNMENT_DEG:
        contact = gc.tooth_contact("nrel_upwind", FIGURE8_TORQUE_NM, zeta_deg * math.pi / 180.0)
        print(f"{zeta_deg:>10.2f}{contact.load_sharing.q:>8.3f}{contact.teeth_in_contact:>7}"
              f"{contact.max_tooth_load_n / 1e3:>11.1f}{contact.max_stress.contact_stress_pa / 1e6:>15.0f}")
        teeth = sorted(contact.teeth, key=lambda tooth: tooth.angle_deg % 360.0)
        axes.plot([tooth.angle_deg % 360.0 for tooth in teeth], [tooth.load_n / 1e3 for tooth in teeth],
                  label=f"{zeta_deg:g} deg")
    axes.set_xlabel("tooth angle from z'' [deg]")
    axes.set_ylabel("tooth load P_d [kN] (eq 9)")
    axes.set_title("Figure 8: upwind coupling, 1.5 MN·m")
    axes.legend(title="misalignment")
    figure.tight_layout()
    figure.savefig(png_path, dpi=100)
    print(f"plot -> {png_path}")


if __name__ == "__main__":
    table3()
    figure8(sys.argv[1] if len(sys.argv) > 1 else "figure8.png")
