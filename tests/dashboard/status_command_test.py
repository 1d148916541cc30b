"""`gearcoupling status` against real gearcoupling-service processes on a private loopback DDS
domain (issue 12): the table, --json, and --watch seeing a killed instance turn stale."""
import json
import os
import signal
import subprocess
import time

import domain_claim

SOURCE_DIR = os.environ["GC_SOURCE_DIR"]
SERVICE = os.environ["GC_SERVICE_BINARY"]
CLI = os.environ["GC_GEARCOUPLING_BINARY"]
DOMAIN = domain_claim.claim()  # one per test process, held while it runs (domain_claim.py)
ENVIRONMENT = dict(os.environ,
                   CYCLONEDDS_URI="file://" + os.path.join(SOURCE_DIR, "deploy/cyclonedds-loopback.xml"))


def service():
    return subprocess.Popen([SERVICE, "--domain", str(DOMAIN)], env=ENVIRONMENT, stderr=subprocess.DEVNULL)


def status(*args):
    return subprocess.run([CLI, "status", "--domain", str(DOMAIN), *args], env=ENVIRONMENT,
                          capture_output=True, text=True, timeout=60, check=True).stdout


def stop(process):
    if process.poll() is None:
        process.send_signal(signal.SIGTERM)
        process.wait(timeout=10)


def test_the_table_and_json_show_a_running_instance_with_its_catalogue():
    running = service()
    try:
        time.sleep(1.0)
        table = status()
        assert "alive" in table and "jam_angle" in table
        assert "nrel_upwind (100 teeth" in table
        report = json.loads(status("--json"))
        (instance,) = report["instances"]
        assert instance["pid"] == running.pid
        assert instance["state"] == "alive" and instance["accepting"] is True
        assert {c["name"] for c in instance["catalogue"]} == {"nrel_upwind", "nrel_downwind"}
        assert {c["calculation"] for c in instance["calculations"]} >= {"jam_angle", "tooth_contact"}
    finally:
        stop(running)


def test_watch_sees_a_killed_instance_turn_stale_and_a_stopped_one_stopped():
    killed, stopped = service(), service()
    watch = subprocess.Popen([CLI, "status", "--domain", str(DOMAIN), "--json", "--watch",
                              "--interval-s", "0.5", "--count", "24"],
                             env=ENVIRONMENT, stdout=subprocess.PIPE, text=True)
    try:
        states = {}
        killed_at = None
        for line in watch.stdout:  # at most 24 reports, 12 s
            report = json.loads(line)
            states = {i["pid"]: i["state"] for i in report["instances"]}
            if killed_at is None and states.get(killed.pid) == "alive" and states.get(stopped.pid) == "alive":
                killed.send_signal(signal.SIGKILL)
                stopped.send_signal(signal.SIGTERM)
                killed_at = time.monotonic()
            if killed_at and states.get(killed.pid) == "stale" and states.get(stopped.pid) == "stopped":
                break
        assert killed_at is not None, "both instances never showed alive"
        assert states.get(killed.pid) == "stale", states
        assert states.get(stopped.pid) == "stopped", states
    finally:
        watch.kill()
        watch.wait()
        killed.kill()
        stop(stopped)


def test_a_refused_request_is_refused_not_failed_and_a_never_called_calculation_shows_a_dash():
    running = service()
    try:
        time.sleep(1.0)
        # An unknown coupling: the client's input, refused by the service.
        asked = subprocess.run([CLI, "jam-angle", "--coupling", "no_such_coupling", "--remote",
                                "--domain", str(DOMAIN)], env=ENVIRONMENT, capture_output=True, text=True,
                               timeout=60)
        assert asked.returncode != 0
        time.sleep(1.5)   # the service publishes its status every second
        report = json.loads(status("--json"))
        (instance,) = report["instances"]
        figures = {c["calculation"]: c for c in instance["calculations"]}
        assert figures["jam_angle"]["refused"] == "1" and figures["jam_angle"]["failed"] == "0", figures
        assert "p50_service_time_s" in figures["jam_angle"]
        # Never called: no service time in the JSON, "-" in the table.
        assert "p50_service_time_s" not in figures["restoring_torque"], figures
        row = next(line.split() for line in status().splitlines() if " restoring_torque " in f" {line} ")
        assert row[-2:] == ["-", "-"], row
    finally:
        stop(running)
