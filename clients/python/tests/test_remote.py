"""Through gearcoupling-service equals in process: a real service on this test's own DDS
domain, loopback only (deploy/cyclonedds-loopback.xml), as tests/service/ runs it."""

import os
import signal
import subprocess

import numpy as np
import pytest

import gearcoupling as gc
from conftest import DATA, SOURCE_DIR, rad, random_cases

if not hasattr(gc, "Client"):
    pytest.skip("built without the service", allow_module_level=True)


@pytest.fixture(scope="module")
def client():
    binary = os.environ.get("GC_SERVICE")
    if not binary:
        pytest.skip("GC_SERVICE not set (run through ctest)")
    domain = 1 + os.getpid() % 200  # as tests/service/service_process.h: one domain per process
    os.environ["CYCLONEDDS_URI"] = f"file://{SOURCE_DIR}/deploy/cyclonedds-loopback.xml"
    service = subprocess.Popen([binary, "--domain", str(domain), "--log-level", "warn"])
    try:
        client = gc.Client(domain=domain, timeout=20.0)
        assert client.wait_for_service(20.0), "no service instance within 20 s"
        yield client
    finally:
        service.send_signal(signal.SIGTERM)
        try:
            service.wait(timeout=10)
        except subprocess.TimeoutExpired:
            service.kill()
            service.wait()


def test_one_case_equals_in_process(client):
    point = dict(torque_nm=1.5e6, misalignment_rad=rad(0.45), direction_rad=rad(20.0))
    assert client.tooth_contact("nrel_upwind", **point).to_json() == gc.tooth_contact("nrel_upwind", **point).to_json()
    assert (client.induced_moments("nrel_downwind", **point, mu=0.12).to_json()
            == gc.induced_moments("nrel_downwind", **point, mu=0.12).to_json())
    for coupling in ("nrel_upwind", "nrel_downwind"):
        assert client.jam_angle(coupling).to_json() == gc.jam_angle(coupling).to_json()
        assert client.restoring_torque(coupling).to_json() == gc.restoring_torque(coupling).to_json()
    measured = (1.5e6, rad(0.45), 0.1, -62000.0, 136000.0)
    assert (client.estimate_friction("nrel_upwind", *measured).to_json()
            == gc.estimate_friction("nrel_upwind", *measured).to_json())


def test_inline_couplings_equal_in_process(client):
    path = DATA / "couplings" / "nrel_downwind.textproto"
    assert client.jam_angle(path).to_json() == gc.jam_angle(path).to_json()
    coupling = gc.Coupling(str(path))
    point = dict(torque_nm=8e5, misalignment_rad=rad(0.2), mu=0.05)
    assert client.induced_moments(coupling, **point).to_json() == gc.induced_moments(coupling, **point).to_json()


def test_many_equal_in_process(client):
    n = 300
    torque, zeta, beta, mu = random_cases(n, seed=7)
    rng = np.random.default_rng(8)
    remote = client.induced_moments_many("nrel_upwind", torque, zeta, beta, mu=mu, in_flight=32)
    local = gc.induced_moments_many("nrel_upwind", torque, zeta, beta, mu=mu)
    for column in local:
        np.testing.assert_array_equal(remote[column], local[column], err_msg=column)
    remote = client.tooth_contact_many("nrel_downwind", torque, zeta, beta)
    local = gc.tooth_contact_many("nrel_downwind", torque, zeta, beta)
    for column in local:
        np.testing.assert_array_equal(remote[column], local[column], err_msg=column)
    msy, msz = rng.uniform(-2e5, 0, n), rng.uniform(0, 2e5, n)
    remote = client.estimate_friction_many("nrel_upwind", torque, zeta, beta, msy, msz, errors="mask")
    local = gc.estimate_friction_many("nrel_upwind", torque, zeta, beta, msy, msz, errors="mask")
    for column in local:
        np.testing.assert_array_equal(remote[column], local[column], err_msg=column)


def test_many_load_cases_go_in_batches_with_bad_cases_in_place(client):
    # Issue 40: 5000 cases are two requests (4096 cases at most per batch), not 10,000; a bad
    # case fails in its place, naming its field, and its neighbours are answered.
    torque, zeta, beta, mu = random_cases(5000, seed=11)
    torque[17] = -5.0
    zeta[4000] = rad(5.0)
    sent = client.counters()["sent"]
    remote = client.induced_moments_many("nrel_upwind", torque, zeta, beta, mu=mu, errors="mask")
    assert client.counters()["sent"] - sent == 2
    local = gc.induced_moments_many("nrel_upwind", torque, zeta, beta, mu=mu, errors="mask")
    for column in local:
        np.testing.assert_array_equal(remote[column], local[column], err_msg=column)
    assert not remote["ok"][17] and not remote["ok"][4000] and remote["ok"].sum() == 4998
    assert "operating_point.torque_nm" in remote["error"][17]
    assert "operating_point.misalignment_rad" in remote["error"][4000]


def test_many_broadcast_and_mask_as_in_process(client):
    torque = np.linspace(3e5, 2.4e6, 4)[:, None]
    zeta = np.array([rad(0.1), rad(0.3), rad(5.0)])  # the last beyond the jam angle
    remote = client.induced_moments_many("nrel_upwind", torque, zeta, 0.0, mu=0.1, errors="mask")
    local = gc.induced_moments_many("nrel_upwind", torque, zeta, 0.0, mu=0.1, errors="mask")
    assert remote["q"].shape == (4, 3)
    assert np.isnan(remote["magnitude_nm"][:, 2]).all()
    for column in local:
        np.testing.assert_array_equal(remote[column], local[column], err_msg=column)
    assert remote.to_frame().equals(local.to_frame())


def test_remote_errors_are_the_core_errors(client):
    with pytest.raises(gc.InvalidInput) as error:
        client.induced_moments("nrel_upwind", 1e6, rad(5.0), mu=0.1)
    assert error.value.field == "operating_point.misalignment_rad"
    with pytest.raises(gc.InvalidInput) as error:
        client.induced_moments_many("nrel_upwind", np.array([1e6, -1.0, 1e6]), 0.001, mu=0.1)
    assert error.value.index == 1
    assert error.value.field == "operating_point.torque_nm"
    with pytest.raises(gc.ModelError) as error:  # the service's refusal, naming its field
        client.jam_angle("no_such_coupling")
    assert error.value.field == "coupling.catalogue_name"
    assert "nrel_upwind" in str(error.value)


def test_no_service_is_a_timeout():
    lonely = gc.Client(domain=1 + (os.getpid() + 100) % 200, timeout=0.5)
    with pytest.raises(gc.Timeout):
        lonely.jam_angle("nrel_upwind")
    # A vectorised call stops sending after the first timeout: every case fails with it, in
    # about one timeout, not one per case.
    many = lonely.induced_moments_many("nrel_upwind", np.full(1000, 1e6), 0.001, mu=0.1, errors="mask")
    assert not many["ok"].any()
    assert all("no gearcoupling-service instance ready" in message for message in many["error"])
