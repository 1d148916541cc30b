"""In process equals the CLI's --json, byte for byte, for every calculation."""

import pytest

import gearcoupling as gc
from conftest import DATA, rad, read_textproto

POINTS = [  # (coupling, torque [N·m], misalignment [deg], direction [deg], mu)
    ("nrel_upwind", 1.5e6, 0.45, 0.0, 0.12),
    ("nrel_upwind", 3.2e5, 0.1, 37.5, 0.0),
    ("nrel_downwind", 9.0e5, 0.3, -120.0, 0.3),
]


@pytest.mark.parametrize("coupling,torque,zeta,beta,mu", POINTS)
def test_tooth_contact_equals_cli_json(cli, coupling, torque, zeta, beta, mu):
    result = gc.tooth_contact(coupling, torque, rad(zeta), rad(beta))
    expected = cli("contact", "--coupling", coupling, "--torque", repr(torque),
                   "--misalignment-deg", repr(zeta), "--direction-deg", repr(beta), "--json")
    assert result.to_json().encode() == expected
    assert isinstance(result, gc.ToothContactResult)
    assert result.teeth_in_contact == result.to_dict()["teeth_in_contact"]


@pytest.mark.parametrize("coupling,torque,zeta,beta,mu", POINTS)
def test_induced_moments_equals_cli_json(cli, coupling, torque, zeta, beta, mu):
    result = gc.induced_moments(coupling, torque, rad(zeta), rad(beta), mu=mu)
    expected = cli("moments", "--coupling", coupling, "--torque", repr(torque),
                   "--misalignment-deg", repr(zeta), "--direction-deg", repr(beta),
                   "--mu", repr(mu), "--json")
    assert result.to_json().encode() == expected


def test_contact_options_equal_cli_flags(cli):
    result = gc.induced_moments("nrel_upwind", 1.0e6, rad(0.2), mu=0.1, slices=8,
                                tolerance=1e-6, max_iterations=50)
    expected = cli("moments", "--torque", "1e6", "--misalignment-deg", "0.2", "--mu", "0.1",
                   "--slices", "8", "--tolerance", "1e-6", "--max-iterations", "50", "--json")
    assert result.to_json().encode() == expected


@pytest.mark.parametrize("coupling", ["nrel_upwind", "nrel_downwind"])
def test_jam_angle_and_restoring_torque_equal_cli_json(cli, coupling):
    assert gc.jam_angle(coupling).to_json().encode() == cli("jam-angle", "--coupling", coupling, "--json")
    assert (gc.restoring_torque(coupling).to_json().encode()
            == cli("restoring-torque", "--coupling", coupling, "--json"))


def test_estimate_friction_equals_cli_json(cli):
    result = gc.estimate_friction("nrel_upwind", 1.5e6, rad(0.45), rad(10.0), -62000.0, 136000.0)
    expected = cli("friction", "--torque", "1.5e6", "--misalignment-deg", "0.45",
                   "--direction-deg", "10", "--msy", "-62000", "--msz", "136000", "--json")
    assert result.to_json().encode() == expected


def test_coupling_from_file_dict_and_object_equal_catalogue(cli):
    path = DATA / "couplings" / "nrel_downwind.textproto"
    by_name = gc.jam_angle("nrel_downwind")
    assert gc.jam_angle(str(path)).to_json() == by_name.to_json()
    assert gc.jam_angle(path).to_json() == by_name.to_json()
    assert gc.jam_angle(gc.Coupling("nrel_downwind")).to_json() == by_name.to_json()
    assert cli("jam-angle", "--coupling", str(path), "--json") == by_name.to_json().encode()


def test_coupling_from_dict_equals_file():
    fields = read_textproto(DATA / "couplings" / "nrel_upwind.textproto")
    coupling = gc.Coupling(fields)
    assert coupling.catalogue_name is None
    assert coupling.name == "nrel_upwind"
    point = dict(torque_nm=1.2e6, misalignment_rad=rad(0.3), direction_rad=0.2, mu=0.1)
    assert (gc.induced_moments(fields, **point).to_json()
            == gc.induced_moments("nrel_upwind", **point).to_json())


def test_result_attributes_carry_units():
    result = gc.tooth_contact("nrel_upwind", 1.5e6, rad(0.45))
    assert result.teeth[0].load_n == result.to_dict()["teeth"][0]["load_n"]
    assert "max_tooth_load_n" in result.fields()
    with pytest.raises(AttributeError):
        result.max_tooth_load  # no unit, no field
