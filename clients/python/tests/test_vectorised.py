"""Vectorised calls equal one case at a time, exactly, on any number of threads."""

import numpy as np
import pandas as pd
import pytest

import gearcoupling as gc
from conftest import rad, random_cases

N = 400
TORQUE, ZETA, BETA, MU = random_cases(N, seed=13)

MOMENT_FIELDS = {  # column of induced_moments_many -> field of the one-case result
    "q": "q", "teeth_in_contact": "teeth_in_contact", "max_tooth_load_n": "max_tooth_load_n",
    "moment_y_dd_nm": "moment_y_dd_nm", "moment_z_dd_nm": "moment_z_dd_nm",
    "moment_y_nm": "moment_y_nm", "moment_z_nm": "moment_z_nm",
    "sensor_moment_y_nm": "sensor_moment_y_nm", "sensor_moment_z_nm": "sensor_moment_z_nm",
    "magnitude_nm": "magnitude_nm",
}


def test_induced_moments_many_equals_one_at_a_time():
    many = gc.induced_moments_many("nrel_upwind", TORQUE, ZETA, BETA, mu=MU)
    for i in range(0, N, 7):
        one = gc.induced_moments("nrel_upwind", TORQUE[i], ZETA[i], BETA[i], mu=MU[i]).to_dict()
        for column, field in MOMENT_FIELDS.items():
            assert many[column][i] == one[field], (i, column)
        assert many["moment_direction_rad"][i] == pytest.approx(rad(one["direction_deg"]), rel=1e-14)
        contact = gc.tooth_contact("nrel_upwind", TORQUE[i], ZETA[i], BETA[i])
        assert many["contact_stress_pa"][i] == contact.max_stress.contact_stress_pa
        assert many["bending_safety_factor"][i] == contact.max_stress.bending_safety_factor


def test_tooth_contact_many_equals_one_at_a_time():
    many = gc.tooth_contact_many("nrel_downwind", TORQUE, ZETA, BETA, slices=10)
    for i in range(0, N, 11):
        one = gc.tooth_contact("nrel_downwind", TORQUE[i], ZETA[i], BETA[i], slices=10)
        assert many["q"][i] == one.load_sharing.q
        assert many["iterations"][i] == one.load_sharing.iterations
        assert many["teeth_in_contact"][i] == one.teeth_in_contact
        assert many["max_tooth_load_n"][i] == one.max_tooth_load_n
        assert many["total_normal_load_n"][i] == one.total_normal_load_n
        assert bool(many["edge_loaded"][i]) == one.edge_loaded


def test_estimate_friction_many_equals_one_at_a_time():
    moments = gc.induced_moments_many("nrel_upwind", TORQUE, ZETA, BETA, mu=MU)
    many = gc.estimate_friction_many("nrel_upwind", TORQUE, ZETA, BETA,
                                     moments["sensor_moment_y_nm"], moments["sensor_moment_z_nm"],
                                     errors="mask")
    assert many["ok"].sum() > N // 2
    for i in np.flatnonzero(many["ok"])[::9]:
        one = gc.estimate_friction("nrel_upwind", TORQUE[i], ZETA[i], BETA[i],
                                   moments["sensor_moment_y_nm"][i], moments["sensor_moment_z_nm"][i])
        assert many["friction_coefficient"][i] == one.friction_coefficient
        assert many["moment_z_dd_nm"][i] == one.moment_z_dd_nm


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_threads_give_the_same_arrays(threads):
    reference = gc.induced_moments_many("nrel_upwind", TORQUE, ZETA, BETA, mu=MU, threads=1)
    other = gc.induced_moments_many("nrel_upwind", TORQUE, ZETA, BETA, mu=MU, threads=threads)
    for column in reference:
        np.testing.assert_array_equal(reference[column], other[column])


def test_scalars_broadcast_and_dtypes():
    many = gc.induced_moments_many("nrel_upwind", TORQUE[:5], rad(0.2), 0.0, mu=0.1)
    assert many["q"].shape == (5,)
    assert many["teeth_in_contact"].dtype == np.int32
    one = gc.induced_moments("nrel_upwind", TORQUE[3], rad(0.2), mu=0.1)
    assert many["sensor_moment_z_nm"][3] == one.sensor_moment_z_nm
    lists = gc.induced_moments_many("nrel_upwind", list(TORQUE[:5]), [rad(0.2)] * 5, mu=[0.1] * 5)
    np.testing.assert_array_equal(lists["magnitude_nm"], many["magnitude_nm"])


def test_mask_keeps_good_cases_and_names_the_bad():
    torque = TORQUE[:6].copy()
    torque[2] = -5.0
    many = gc.induced_moments_many("nrel_upwind", torque, ZETA[:6], mu=0.1, errors="mask")
    assert list(many["ok"]) == [True, True, False, True, True, True]
    assert many["error"][2].startswith("operating_point.torque_nm = -5 is out of range")
    assert many["error"][0] == ""
    assert np.isnan(many["magnitude_nm"][2])  # NaN, never a number that looks computed
    good = gc.induced_moments_many("nrel_upwind", torque[3:], ZETA[3:6], mu=0.1)
    np.testing.assert_array_equal(many["magnitude_nm"][3:], good["magnitude_nm"])


def test_the_gil_is_released_while_the_cases_run():
    # Python code runs in this thread while the other is still inside the call: with the GIL
    # held for the call, nothing could run here before it returned.
    import threading
    import time

    torque, zeta, beta, mu = random_cases(300_000, seed=5)
    started, results = threading.Event(), []

    def work():
        started.set()
        results.append(gc.induced_moments_many("nrel_upwind", torque, zeta, beta, mu=mu, threads=1))

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    time.sleep(0.05)  # gives the GIL away; it comes back only if the call does not hold it
    ran_during_call = not results
    worker.join()
    assert ran_during_call
    assert len(results[0]["q"]) == 300_000


def test_induced_moments_many_equals_gearcoupling_batch(cli, tmp_path):
    torque, zeta, beta, mu = random_cases(200, seed=21)
    zeta_deg, beta_deg = np.round(np.degrees(zeta), 6), np.round(np.degrees(beta), 6)
    cases = pd.DataFrame({"torque_nm": torque, "misalignment_deg": zeta_deg,
                          "direction_deg": beta_deg, "mu": mu})
    cases.to_csv(tmp_path / "cases.csv", index=False)
    cli("batch", "--in", str(tmp_path / "cases.csv"), "--out", str(tmp_path / "out.csv"))
    batch = pd.read_csv(tmp_path / "out.csv", float_precision="round_trip")
    # batch reads its _deg columns as recordings do: deg * (pi / 180), one constant.
    ours = gc.induced_moments_many("nrel_upwind", torque, zeta_deg * (np.pi / 180.0),
                                   beta_deg * (np.pi / 180.0), mu=mu)
    for column in batch.columns:
        if column in ours:
            np.testing.assert_array_equal(ours[column], batch[column].to_numpy(), err_msg=column)
