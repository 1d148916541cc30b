"""The core's errors as gearcoupling.InvalidInput (with .field), NotConverged and ModelError."""

import numpy as np
import pytest

import gearcoupling as gc
from conftest import rad


def test_invalid_input_names_the_field_and_is_a_value_error():
    with pytest.raises(gc.InvalidInput) as error:
        gc.induced_moments("nrel_upwind", 1e6, rad(5.0), mu=0.1)
    assert error.value.field == "operating_point.misalignment_rad"
    assert "jam angle" in str(error.value)
    assert isinstance(error.value, gc.ModelError)
    assert isinstance(error.value, ValueError)


@pytest.mark.parametrize("kwargs,field", [
    (dict(torque_nm=0.0, misalignment_rad=0.001), "operating_point.torque_nm"),
    (dict(torque_nm=1e6, misalignment_rad=-0.001), "operating_point.misalignment_rad"),
    (dict(torque_nm=1e6, misalignment_rad=0.001, mu=1.5), "operating_point.friction_coefficient"),
    (dict(torque_nm=1e6, misalignment_rad=0.001, slices=7), "options.slices"),
])
def test_fields(kwargs, field):
    kwargs.setdefault("mu", 0.1)
    with pytest.raises(gc.InvalidInput) as error:
        gc.induced_moments("nrel_upwind", **kwargs)
    assert error.value.field == field


def test_not_converged():
    with pytest.raises(gc.NotConverged) as error:
        # 42 kN·m at 0.4 deg lies on eq 22's root branch: one step cannot reach the fixed point.
        gc.tooth_contact("nrel_upwind", 4.2e4, rad(0.4), tolerance=1e-15, max_iterations=1)
    assert isinstance(error.value, gc.ModelError)
    assert not isinstance(error.value, gc.InvalidInput)
    assert error.value.field is None


def test_unknown_coupling_and_bad_dict():
    with pytest.raises(gc.InvalidInput) as error:
        gc.jam_angle("no_such_coupling")
    assert error.value.field == "coupling"
    assert "nrel_upwind" in str(error.value)
    with pytest.raises(gc.InvalidInput) as error:
        gc.Coupling({"name": "x", "teeth": 10})
    assert error.value.field.startswith("coupling.")
    with pytest.raises(gc.InvalidInput) as error:
        gc.Coupling({"name": "x", "no_such_field": 1})
    assert error.value.field == "coupling"
    with pytest.raises(TypeError):
        gc.jam_angle(42)


def test_vectorised_error_has_the_case_index():
    torque = np.array([1e6, 1e6, 1e6])
    zeta = np.array([0.001, 0.002, rad(9.0)])
    with pytest.raises(gc.InvalidInput) as error:
        gc.induced_moments_many("nrel_upwind", torque, zeta, mu=0.1)
    assert error.value.index == 2
    assert error.value.field == "operating_point.misalignment_rad"
    assert str(error.value).startswith("case 2: ")


def test_vectorised_argument_errors():
    with pytest.raises(gc.InvalidInput) as error:
        gc.induced_moments_many("nrel_upwind", np.ones(3) * 1e6, np.zeros(4), mu=0.1)
    assert error.value.field == "misalignment_rad"
    with pytest.raises(gc.InvalidInput) as error:  # 2-D arrays broadcast (test_numpy_pandas.py)
        gc.induced_moments_many("nrel_upwind", np.array(["a", "b"]), 0.0, mu=0.1)
    assert error.value.field == "torque_nm"
    with pytest.raises(gc.InvalidInput) as error:
        gc.induced_moments_many("nrel_upwind", 1e6, 0.0, mu=0.1, errors="ignore")
    assert error.value.field == "errors"
    with pytest.raises(gc.InvalidInput):
        gc.induced_moments_many("nrel_upwind", np.array([]), 0.0, mu=0.1)
