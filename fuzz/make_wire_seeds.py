#!/usr/bin/env python3
"""Writes the seed corpora of wire_request_fuzzer (fuzz/corpus/wire_request/: every calculation
with a catalogue name and with each bundled coupling inline) and batch_request_fuzzer
(fuzz/corpus/batch_request/: every batch calculation over a catalogue and an inline coupling,
good cases beside bad ones), in the byte layouts the fuzzers read (docs/fuzzing.md, "wire_request_fuzzer's input"). Run from the repository root.

`make_wire_seeds.py decode FILE` prints the request a fuzzer input (e.g. a crash) stands for."""
import math
import pathlib
import re
import struct
import sys

DOUBLES_1 = ["module_m", "pressure_angle_rad", "pitch_diameter_m", "base_diameter_m",
             "outer_diameter_m", "root_diameter_m", "center_distance_m", "backlash_m",
             "tooth_thickness_m", "tool_tip_radius_m", "facewidth_m", "lead_modification_m",
             "profile_tip_relief_m", "profile_relief_start_roll_rad"]
DOUBLES_2 = ["form_factor_hub", "form_factor_sleeve", "youngs_modulus_pa", "poisson_ratio",
             "design_misalignment_rad", "coupling_weight_n", "shaft_weight_per_length_n_per_m",
             "shaft_length_m", "tilt_rad"]
CALCULATIONS = ["tooth_contact", "jam_angle", "induced_moments", "restoring_torque", "friction"]


def read_coupling(path):
    """key: value pairs of a coupling .textproto, angles converted from _deg to _rad."""
    fields = {}
    for key, value in re.findall(r"^\s*(\w+):\s*(\"[^\"]*\"|[-+.\w]+)", path.read_text(), re.M):
        if key.endswith("_deg"):
            fields[key[:-4] + "_rad"] = math.radians(float(value))
        else:
            fields[key] = value.strip('"')
    return fields


def string(text):
    data = text.encode()
    return struct.pack("<H", len(data)) + data


def optional(fields, name):
    return struct.pack("<Bd", name in fields, float(fields.get(name, 0.0)))


def definition(fields):
    out = string(fields["name"]) + struct.pack("<i", int(fields["teeth"]))
    out += b"".join(struct.pack("<d", float(fields[k])) for k in DOUBLES_1)
    out += optional(fields, "crown_radius_m")
    out += b"".join(struct.pack("<d", float(fields[k])) for k in DOUBLES_2)
    out += optional(fields, "sleeve_root_diameter_m")
    return out + struct.pack("<dd", float(fields["contact_stress_pa"]),
                             float(fields["bending_stress_pa"]))


OPTIONS = struct.pack("<diiddB", 1e-9, 100, 20, 0.0, 0.9, 0)
BATCH_CALCULATIONS = ["load_case", "induced_moments", "jam_angle", "restoring_torque"]


def tail():
    operating_point = struct.pack("<dddd", 1.0e6, 0.002, 0.3, 0.1)
    measurement = struct.pack("<ddddd", 1.0e5, 0.0039317, 0.0, -142228.4, 8808.9)
    return operating_point + OPTIONS + measurement


def batch(index, inline):
    """Couplings nrel_upwind by name and `inline`; a good case on each, a torque of zero, an index
    past the couplings and a misalignment beyond the jam angle."""
    cases = [(0, 1.0e6, 0.002, 0.3, 0.1), (1, 1.5e6, 0.004, 0.0, 0.12), (0, 0.0, 0.002, 0.0, 0.1),
             (7, 1.0e6, 0.002, 0.0, 0.1), (0, 1.0e6, 0.5, 0.0, 0.1)]
    out = struct.pack("<BBB", index, 2, 0) + string("nrel_upwind") + struct.pack("<B", 1)
    out += definition(inline) + OPTIONS + struct.pack("<H", len(cases))
    return out + b"".join(struct.pack("<Idddd", *case) for case in cases)


class Reader:
    """Reads as the fuzzer does: front to back, zeros past the end."""

    def __init__(self, data):
        self.data, self.at = data, 0

    def take(self, fmt):
        size = struct.calcsize(fmt)
        chunk = self.data[self.at:self.at + size].ljust(size, b"\0")
        self.at = min(len(self.data), self.at + size)
        return struct.unpack(fmt, chunk)[0]

    def string(self):
        length = min(self.take("<H"), len(self.data) - self.at)
        text = self.data[self.at:self.at + length].split(b"\0")[0]
        self.at += length
        return text


def decode(path):
    r = Reader(pathlib.Path(path).read_bytes())
    print("calculation:", CALCULATIONS[r.take("<B") % 5])
    if r.take("<B") & 1 == 0:
        print("catalogue_name:", r.string())
    else:
        print("name:", r.string(), "teeth:", r.take("<i"))
        for k in DOUBLES_1:
            print(f"{k}: {r.take('<d')!r}")
        present, value = r.take("<B") & 1, r.take("<d")
        print("crown_radius_m:", value if present else "absent")
        for k in DOUBLES_2:
            print(f"{k}: {r.take('<d')!r}")
        present, value = r.take("<B") & 1, r.take("<d")
        print("sleeve_root_diameter_m:", value if present else "absent")
        print("allowables:", r.take("<d"), r.take("<d"))
    names = ["torque_nm", "misalignment_rad", "direction_rad", "friction_coefficient"]
    print("operating_point:", {k: r.take("<d") for k in names})
    print("options:", {"tolerance": r.take("<d"), "max_iterations": r.take("<i"),
                       "slices": r.take("<i"), "spacing_error_m": r.take("<d"),
                       "min_load_fraction": r.take("<d"), "continuous": r.take("<B") & 1})
    names = ["torque_nm", "misalignment_rad", "direction_rad", "sensor_moment_y_nm",
             "sensor_moment_z_nm"]
    print("measurement:", {k: r.take("<d") for k in names})


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "decode":
        decode(sys.argv[2])
        return
    root = pathlib.Path(".")
    out_dir = root / "fuzz/corpus/wire_request"
    out_dir.mkdir(parents=True, exist_ok=True)
    couplings = sorted((root / "data/couplings").glob("*.textproto"))
    for index, calculation in enumerate(CALCULATIONS):
        (out_dir / f"{calculation}_catalogue").write_bytes(
            struct.pack("<BB", index, 0) + string("nrel_upwind") + tail())
        for path in couplings:
            (out_dir / f"{calculation}_inline_{path.stem}").write_bytes(
                struct.pack("<BB", index, 1) + definition(read_coupling(path)) + tail())
    batch_dir = root / "fuzz/corpus/batch_request"
    batch_dir.mkdir(parents=True, exist_ok=True)
    for index, calculation in enumerate(BATCH_CALCULATIONS):
        (batch_dir / calculation).write_bytes(batch(index, read_coupling(couplings[0])))


if __name__ == "__main__":
    main()
