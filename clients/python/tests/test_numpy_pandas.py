"""Python as a numpy/pandas user expects it (issue 24): broadcasting, NaN for failed cases,
DataFrames in one call, real types in help(), angles in the unit they went in, per-sample
predictions and residuals, and what `pip install .` does."""

import math
import pydoc
import re
import shutil
import subprocess

import numpy as np
import pandas as pd
import pytest

import gearcoupling as gc
from gearcoupling import _gearcoupling
from conftest import DATA, SOURCE_DIR, rad

SWEEP = str(DATA / "recordings" / "paper_torque_sweep.csv")
ECCENTRIC = str(DATA / "recordings" / "hidden_eccentricity_torque_ramp.csv")


# ---- broadcasting ---------------------------------------------------------------------------

def test_a_column_against_a_row_is_a_grid_of_the_broadcast_shape():
    torque = np.linspace(3e5, 2.4e6, 5)[:, None]          # (5, 1)
    zeta = np.array([[rad(0.05), rad(0.1), rad(0.2), rad(0.4)]])  # (1, 4)
    grid = gc.induced_moments_many("nrel_upwind", torque, zeta, 0.0, mu=0.1)
    assert grid.shape == (5, 4)
    for column in grid.values():
        assert column.shape == (5, 4)
    for i in range(5):
        for j in range(4):
            one = gc.induced_moments("nrel_upwind", torque[i, 0], zeta[0, j], mu=0.1)
            assert grid["sensor_moment_y_nm"][i, j] == one.sensor_moment_y_nm, (i, j)
            assert grid["teeth_in_contact"][i, j] == one.teeth_in_contact, (i, j)


def test_two_d_arrays_of_one_shape_and_a_scalar():
    rng = np.random.default_rng(3)
    torque = rng.uniform(3e5, 2e6, (3, 4))
    beta = rng.uniform(-np.pi, np.pi, (3, 4))
    out = gc.tooth_contact_many("nrel_downwind", torque, rad(0.25), beta)
    assert out["q"].shape == (3, 4)
    assert out.inputs["misalignment_rad"].shape == (3, 4)
    one = gc.tooth_contact("nrel_downwind", torque[2, 1], rad(0.25), beta[2, 1])
    assert out["max_tooth_load_n"][2, 1] == one.max_tooth_load_n
    friction = gc.estimate_friction_many("nrel_upwind", 1.5e6, rad(0.45), np.zeros((2, 3)),
                                         -62000.0, 136000.0)
    assert friction["friction_coefficient"].shape == (2, 3)


def test_scalars_alone_give_a_zero_dimensional_result_as_numpy_does():
    out = gc.induced_moments_many("nrel_upwind", 1.5e6, rad(0.3), 0.0, mu=0.1)
    assert out["magnitude_nm"].shape == np.add(1.0, 2.0).shape == ()
    assert float(out["magnitude_nm"]) == gc.induced_moments("nrel_upwind", 1.5e6, rad(0.3), mu=0.1).magnitude_nm


def test_shapes_that_do_not_broadcast_name_the_argument():
    with pytest.raises(gc.InvalidInput) as error:
        gc.induced_moments_many("nrel_upwind", np.full(3, 1e6), np.full(4, 0.001), mu=0.1)
    assert error.value.field == "misalignment_rad"
    assert "(4,)" in str(error.value) and "(3,)" in str(error.value)
    with pytest.raises(gc.InvalidInput) as error:
        gc.tooth_contact_many("nrel_upwind", np.ones((2, 3)) * 1e6, np.ones((3, 2)) * 0.001)
    assert error.value.field == "misalignment_rad"


# ---- failed cases ---------------------------------------------------------------------------

def test_mask_gives_nan_for_a_failed_case_not_zero():
    torque = np.array([[1e6, -5.0], [2e6, 1.5e6]])
    out = gc.induced_moments_many("nrel_upwind", torque, rad(0.2), mu=0.1, errors="mask")
    assert out["ok"].tolist() == [[True, False], [True, True]]
    assert out["error"][0, 1].startswith("operating_point.torque_nm = -5")
    for name, column in out.items():
        if name in ("ok", "error"):
            continue
        assert column.dtype == np.float64, name  # integer columns too: they hold NaN
        assert np.isnan(column[0, 1]), name
        assert not np.isnan(column[out["ok"]]).any(), name
    assert out["teeth_in_contact"][1, 0] == gc.induced_moments("nrel_upwind", 2e6, rad(0.2), mu=0.1).teeth_in_contact
    contact = gc.tooth_contact_many("nrel_upwind", np.array([1e6, -5.0]), rad(0.2), errors="mask")
    assert contact["edge_loaded"].dtype == np.bool_ and not contact["edge_loaded"][1]
    # errors="raise" keeps the integer columns integers.
    assert gc.induced_moments_many("nrel_upwind", 1e6, rad(0.2), mu=0.1)["teeth_in_contact"].dtype == np.int32


# ---- DataFrames -----------------------------------------------------------------------------

def test_a_vectorised_result_is_one_data_frame_with_its_inputs():
    torque = np.linspace(3e5, 2.4e6, 3)[:, None]
    grid = gc.induced_moments_many("nrel_upwind", torque, np.array([rad(0.1), rad(0.3)]), 0.0,
                                   mu=0.12)
    frame = grid.to_frame()
    assert isinstance(frame, pd.DataFrame)
    assert len(frame) == 6
    assert list(frame.columns[:4]) == ["torque_nm", "misalignment_rad", "direction_rad", "mu"]
    assert "sensor_moment_y_nm" in frame.columns
    # Row 3 is grid[1, 1] (C order), with its own inputs.
    assert frame["torque_nm"][3] == torque[1, 0]
    assert frame["misalignment_rad"][3] == rad(0.3)
    assert frame["sensor_moment_y_nm"][3] == grid["sensor_moment_y_nm"][1, 1]
    assert isinstance(grid, dict)  # still the dict it was: pandas.DataFrame(grid) for 1-D ones


def test_one_result_is_a_one_row_data_frame_and_its_lists_frames_of_their_own():
    moments = gc.induced_moments("nrel_upwind", 1.5e6, rad(0.45), rad(20.0), mu=0.12)
    frame = moments.to_frame()
    assert len(frame) == 1
    assert frame["sensor_moment_y_nm"][0] == moments.sensor_moment_y_nm
    assert frame["operating_point_torque_nm"][0] == 1.5e6
    assert frame["direction_deg"][0] == moments.direction_deg
    assert frame["direction_rad"][0] == moments.direction_rad
    contact = gc.tooth_contact("nrel_upwind", 1.5e6, rad(0.45))
    teeth = contact.to_frame("teeth")
    assert len(teeth) == len(contact.teeth) > 10
    assert {"load_n", "angle_deg", "angle_rad"} <= set(teeth.columns)


# ---- help() ---------------------------------------------------------------------------------

def signatures(function) -> list[str]:
    """pybind11's signature lines of a function (one per overload)."""
    doc = function.__doc__ or ""
    return [line for line in doc.splitlines() if re.match(r"^(\d+\. )?\w+\(.*\) -> ", line)]


def bound_callables():
    for name in dir(_gearcoupling):
        value = getattr(_gearcoupling, name)
        if type(value).__name__ == "builtin_function_or_method":
            yield name, value
        elif isinstance(value, type) and not issubclass(value, BaseException):
            for method_name, method in vars(value).items():
                if method_name.startswith("__") and method_name != "__init__":
                    continue
                if isinstance(method, property):
                    yield f"{name}.{method_name}", method.fget
                elif callable(method) and type(method).__name__ == "instancemethod":
                    yield f"{name}.{method_name}", method


def test_help_shows_real_types_never_handle_or_object():
    checked = 0
    for name, function in bound_callables():
        for signature in signatures(function):
            checked += 1
            assert not re.search(r"\bhandle\b|\bobject\b", signature), f"{name}: {signature}"
    assert checked > 30
    text = pydoc.render_doc(gc.induced_moments_many)
    assert "torque_nm: numpy.ndarray | float" in text
    assert "-> gearcoupling.CaseTable" in text
    assert "-> gearcoupling.InducedMomentsResult" in gc.induced_moments.__doc__
    assert "coupling: gearcoupling.Coupling | str | os.PathLike | dict" in gc.jam_angle.__doc__
    assert "recording: gearcoupling.Recording | str | os.PathLike | pandas.DataFrame" in gc.validate.__doc__


# ---- angles ---------------------------------------------------------------------------------

def radians_that_do_not_survive_degrees() -> float:
    """An angle in rad whose trip through degrees changes its last bit, so a _rad attribute
    computed from the _deg field would not equal it."""
    for k in range(1, 10_000):
        value = 1e-3 * k / 7.0
        if math.radians(math.degrees(value)) != value:
            return value
    raise AssertionError("every angle survived")


def test_angles_come_back_in_the_unit_they_went_in():
    zeta = radians_that_do_not_survive_degrees()
    beta = -2.0 * zeta
    moments = gc.induced_moments("nrel_upwind", 1.5e6, zeta, beta, mu=0.12)
    assert moments.operating_point.misalignment_rad == zeta  # exactly
    assert moments.operating_point.direction_rad == beta
    assert moments.operating_point.misalignment_deg == pytest.approx(math.degrees(zeta), rel=1e-15)
    many = gc.induced_moments_many("nrel_upwind", 1.5e6, zeta, beta, mu=0.12)
    assert moments.direction_rad == float(many["moment_direction_rad"])
    assert "direction_rad" in dir(moments)
    assert moments.to_dict() == moments.to_dict() and "direction_rad" not in moments.to_dict()
    contact = gc.tooth_contact("nrel_upwind", 1.5e6, zeta, beta)
    assert contact.offset_alpha_rad == float(gc.tooth_contact_many("nrel_upwind", 1.5e6, zeta, beta)["offset_alpha_rad"])
    assert contact.teeth[0].angle_rad == pytest.approx(math.radians(contact.teeth[0].angle_deg), rel=1e-15)
    jam = gc.jam_angle("nrel_upwind")
    assert jam.angle_rad == gc.Coupling("nrel_upwind").jam_angle_rad
    assert jam.facewidth_rad == pytest.approx(math.radians(jam.facewidth_deg), rel=1e-15)
    friction = gc.estimate_friction("nrel_upwind", 1.5e6, zeta, beta, -62000.0, 136000.0)
    assert friction.measurement.misalignment_rad == zeta


# ---- per-sample predictions and residuals ---------------------------------------------------

def test_model_predict_gives_every_sample_with_validates_errors():
    predictions = gc.Model("paper").predict(SWEEP)
    frame = predictions.to_frame()
    assert len(frame) == 1000
    assert list(frame.columns) == [
        "time_s", "torque_nm", "misalignment_rad", "direction_rad", "msy_measured_nm",
        "msz_measured_nm", "msy_predicted_nm", "msz_predicted_nm", "msy_residual_nm",
        "msz_residual_nm", "ok", "error"]
    assert frame["ok"].all()
    np.testing.assert_array_equal(frame["msy_residual_nm"],
                                  frame["msy_predicted_nm"] - frame["msy_measured_nm"])
    overall = gc.validate(SWEEP, "paper").models[0].overall
    assert frame["msy_residual_nm"].mean() == pytest.approx(overall.msy.bias_nm, rel=1e-9, abs=1e-6)
    assert math.sqrt((frame["msz_residual_nm"] ** 2).mean()) == pytest.approx(overall.msz.rmse_nm, rel=1e-9)


def test_predict_takes_the_models_input_timing_into_account():
    # moment_delay predicts sample i from the inputs delay_s earlier (CouplingModel::predict_at):
    # the errors then are validate's for that model, not the paper model's.
    delayed = gc.Model("paper").with_effect("moment_delay=delay_s=0.5")
    predicted = delayed.predict(SWEEP)
    plain = gc.Model("paper").predict(SWEEP)
    assert not np.array_equal(predicted["msy_predicted_nm"], plain["msy_predicted_nm"])
    validated = gc.validate(SWEEP, delayed).models[0].overall
    rmse = math.sqrt(np.nanmean(predicted["msy_residual_nm"] ** 2))
    assert rmse == pytest.approx(validated.msy.rmse_nm, rel=1e-9)


def test_a_refused_sample_is_nan_with_its_reason(tmp_path):
    frame = pd.read_csv(SWEEP, float_precision="round_trip").head(20)
    frame.loc[5, "misalignment_rad"] = rad(5.0)  # beyond the jam angle
    predictions = gc.Model("paper").predict(frame)
    assert not predictions["ok"][5] and predictions["ok"].sum() == 19
    assert np.isnan(predictions["msy_predicted_nm"][5]) and np.isnan(predictions["msy_residual_nm"][5])
    assert "misalignment" in predictions["error"][5]


def test_validate_and_diagnose_give_their_samples_as_data_frames():
    validation = gc.validate(SWEEP, "paper", add="hysteresis=lag_rad=6e-4")
    before, after = validation.samples(), validation.samples(1)
    assert isinstance(before, pd.DataFrame) and len(before) == len(after) == 1000
    assert math.sqrt((after["msy_residual_nm"] ** 2).mean()) == pytest.approx(
        validation.models[1].overall.msy.rmse_nm, rel=1e-9)
    with pytest.raises(ValueError):
        validation.samples(2)
    diagnosis = gc.diagnose(ECCENTRIC, "paper", threads=2)
    given, found = diagnosis.samples(0), diagnosis.samples(1)
    rms = lambda frame: math.sqrt((frame["msy_residual_nm"] ** 2).mean())  # noqa: E731
    assert rms(found) < 0.7 * rms(given)  # the eccentricity found explains the residual
    assert diagnosis.samples(diagnosis.model.name)["msy_predicted_nm"].equals(found["msy_predicted_nm"])


# ---- pip install ----------------------------------------------------------------------------

def test_pip_install_is_documented_as_debian_12_allows_it():
    """docs/python.md says why `pip install .` does not build the module: Debian 12 packages no
    CMake-driving build backend. This fails the day Debian's archive has one, as a reminder."""
    docs = (SOURCE_DIR / "docs" / "python.md").read_text()
    assert "python3-scikit-build-core" in docs and "pip install" in docs
    assert not (SOURCE_DIR / "pyproject.toml").exists()
    if shutil.which("apt-cache") is None:
        pytest.skip("no apt-cache: not a Debian host")
    for package in ("python3-scikit-build-core", "python3-scikit-build", "python3-meson-python"):
        policy = subprocess.run(["apt-cache", "policy", package], capture_output=True, text=True,
                                timeout=60).stdout
        assert "Candidate:" not in policy or "Candidate: (none)" in policy, (
            f"Debian now packages {package}: make `pip install .` work (docs/python.md)")


# ---- a Series keeps its index (issue 39) ----------------------------------------------------

def test_a_series_input_gives_results_with_its_index():
    cases = pd.DataFrame({"torque_nm": [1e6, 1.5e6, 2e6], "misalignment_deg": [0.1, 0.2, 0.3]},
                         index=pd.Index(["run-a", "run-b", "run-c"], name="run"))
    out = gc.induced_moments_many("nrel_upwind", cases["torque_nm"],
                                  np.radians(cases["misalignment_deg"]), mu=0.1)
    assert out.index.equals(cases.index)
    frame = out.to_frame()
    assert frame.index.equals(cases.index)
    assert frame.loc["run-b", "magnitude_nm"] == gc.induced_moments(
        "nrel_upwind", 1.5e6, np.radians(0.2), mu=0.1).magnitude_nm
    joined = cases.join(out.series("magnitude_nm"))   # lines up by the index, not by position
    assert joined["magnitude_nm"].notna().all()
    # Arrays (no index), or a grid that is not the Series' rows: 0..n-1 as before.
    assert gc.induced_moments_many("nrel_upwind", np.array([1e6, 2e6]), 0.001, mu=0.1).index is None
    grid = gc.induced_moments_many("nrel_upwind", cases["torque_nm"].to_numpy()[:, None],
                                   np.array([0.001, 0.002]), mu=0.1)
    assert grid.index is None and list(grid.to_frame().index) == list(range(6))
