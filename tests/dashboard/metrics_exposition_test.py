"""The dashboard's /metrics as Prometheus and Grafana read it (issue 25), against a real
gearcoupling-service, gearcoupling-monitor and `gearcoupling replay` on a private loopback DDS
domain, the dashboard on a free port (no browser):

- the exposition parses with a real parser (python3-prometheus-client's text parser);
- no label is named `instance` (Prometheus's target label: ours would become exported_instance);
- every summary has `_sum` and `_count`, and a calculation never called has NaN quantiles;
- a refused query counts as refused, not as a failure of the service;
- the test cell has `gearcoupling_cell_model_info{model=...} 1`, bias gauges per channel and its
  model health;
- every metric name the Grafana dashboard (deploy/grafana/gearcoupling.json) queries is in the
  scrape.

Run by ctest (tests/dashboard/CMakeLists.txt), which passes the programs' paths.
"""
import json
import math
import os
import re
import signal
import subprocess
import time
import urllib.error
import urllib.parse
import urllib.request

import pytest

import domain_claim

# Debian's python3-prometheus-client (deploy/install-deps.sh).
parser = pytest.importorskip("prometheus_client.parser",
                             reason="python3-prometheus-client is absent (deploy/install-deps.sh)")
text_string_to_metric_families = parser.text_string_to_metric_families

SOURCE_DIR = os.environ["GC_SOURCE_DIR"]
SERVICE = os.environ["GC_SERVICE_BINARY"]
DASHBOARD = os.environ["GC_DASHBOARD_BINARY"]
MONITOR = os.environ["GC_MONITOR_BINARY"]
CLI = os.environ["GC_GEARCOUPLING_BINARY"]
GRAFANA_DASHBOARD = os.path.join(SOURCE_DIR, "deploy/grafana/gearcoupling.json")
# One domain per test process, as the C++ tests pick theirs (tests/service/service_process.h).
DOMAIN = domain_claim.claim()  # one per test process, held while it runs (domain_claim.py)
ENVIRONMENT = dict(os.environ,
                   CYCLONEDDS_URI="file://" + os.path.join(SOURCE_DIR, "deploy/cyclonedds-loopback.xml"))
TEST_CELL = "dyno-metrics"


def get(url, timeout=10):
    """(status, body) of a GET, error statuses included."""
    try:
        with urllib.request.urlopen(url, timeout=timeout) as response:
            return response.status, response.read().decode()
    except urllib.error.HTTPError as error:
        return error.code, error.read().decode()


def samples(text):
    """Every sample of the exposition as parsed by prometheus_client: (name, labels, value)."""
    return [(s.name, s.labels, s.value) for family in text_string_to_metric_families(text)
            for s in family.samples]


@pytest.fixture(scope="module")
def scrape():
    children = []

    def start(args, **kwargs):
        child = subprocess.Popen(args, env=ENVIRONMENT, **kwargs)
        children.append(child)
        return child

    try:
        start([SERVICE, "--domain", str(DOMAIN), "--status-interval-s", "0.2"],
              stderr=subprocess.DEVNULL)
        start([MONITOR, "--domain", str(DOMAIN), "--model", "paper"], stderr=subprocess.DEVNULL)
        dashboard = start([DASHBOARD, "--domain", str(DOMAIN), "--listen", "127.0.0.1:0"],
                          stdout=subprocess.PIPE, text=True)
        line = dashboard.stdout.readline()
        assert line.startswith("listening on http://"), f"dashboard printed {line!r}"
        url = line.split("listening on ", 1)[1].strip()
        replay = start([CLI, "replay", "--in",
                        os.path.join(SOURCE_DIR, "data/recordings/hidden_eccentricity_torque_ramp.csv"),
                        "--test-cell", TEST_CELL, "--rate", "1000", "--domain", str(DOMAIN)],
                       stdout=subprocess.DEVNULL)
        # One query answered and one refused (an unknown coupling), through the dashboard.
        deadline = time.monotonic() + 15
        answered = refused = None
        while time.monotonic() < deadline and answered != 200:
            answered, _ = get(url + "api/query?coupling=nrel_upwind&torque_nm=1.5e6&misalignment_deg=0.5")
            time.sleep(0.2)
        assert answered == 200
        refused, body = get(url + "api/query?coupling=no_such_coupling&torque_nm=1.5e6&misalignment_deg=0.5")
        assert refused == 422, body
        replay.wait(timeout=30)
        # The monitor's health (once a second) and the service's status (every 0.2 s) arrive.
        text = ""
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            _, text = get(url + "metrics")
            parsed = samples(text)
            if any(n == "gearcoupling_cell_model_info" for n, _, _ in parsed) and \
                    any(n == "gearcoupling_requests_refused_total" and v >= 1 for n, _, v in parsed):
                break
            time.sleep(0.3)
        yield text
    finally:
        for child in children:
            if child.poll() is None:
                child.send_signal(signal.SIGTERM)
        for child in children:
            try:
                child.wait(timeout=5)
            except subprocess.TimeoutExpired:
                child.kill()
                child.wait()


def test_the_exposition_parses_and_no_label_is_named_instance(scrape):
    parsed = samples(scrape)
    assert len(parsed) > 50
    assert all("instance" not in labels for _, labels, _ in parsed)
    assert any("service_instance" in labels for _, labels, _ in parsed)


def test_summaries_have_sum_and_count_and_nan_quantiles_when_never_called(scrape):
    parsed = samples(scrape)
    base = "gearcoupling_service_time_seconds"
    series = {}
    for name, labels, value in parsed:
        if name.startswith(base):
            key = (labels["service_instance"], labels["calculation"])
            series.setdefault(key, {})[(name, labels.get("quantile"))] = value
    assert series
    for key, values in series.items():
        assert (base + "_sum", None) in values and (base + "_count", None) in values, key
        assert (base, "0.5") in values and (base, "0.99") in values, key
        if values[(base + "_count", None)] == 0:
            assert math.isnan(values[(base, "0.5")]) and math.isnan(values[(base, "0.99")]), key
            assert values[(base + "_sum", None)] == 0, key
        else:
            assert values[(base, "0.99")] >= values[(base, "0.5")] > 0, key
    # The panel asked jam_angle, tooth_contact and induced_moments; never friction_estimate.
    assert any(v[(base + "_count", None)] == 0 for (_, c), v in series.items() if c == "friction_estimate")


def test_a_refused_query_is_not_a_failure_of_the_service(scrape):
    counts = {}
    for name, labels, value in samples(scrape):
        if name in ("gearcoupling_requests_refused_total", "gearcoupling_requests_failed_total"):
            counts[name] = counts.get(name, 0) + value
        if name == "gearcoupling_dashboard_queries_total":
            counts[labels["outcome"]] = value
    assert counts["gearcoupling_requests_refused_total"] >= 1, counts
    assert counts["gearcoupling_requests_failed_total"] == 0, counts
    assert counts["answered"] >= 1 and counts["refused"] == 1 and counts["failed"] == 0, counts


def test_the_test_cell_has_its_model_its_bias_and_its_health(scrape):
    parsed = samples(scrape)
    info = [(labels, value) for name, labels, value in parsed if name == "gearcoupling_cell_model_info"]
    assert info == [({"test_cell": TEST_CELL, "model": "paper"}, 1.0)]
    bias = {labels["channel"]: value for name, labels, value in parsed
            if name == "gearcoupling_cell_bias_newton_metres" and labels["test_cell"] == TEST_CELL}
    assert set(bias) == {"msy", "msz"} and all(math.isfinite(v) for v in bias.values())
    health = {labels["health"]: value for name, labels, value in parsed
              if name == "gearcoupling_cell_model_health" and labels["test_cell"] == TEST_CELL}
    assert set(health) == {"unknown", "at_noise_level", "systematic", "far_off", "unit_error", "stale"}
    assert sum(health.values()) == 1
    # The hidden eccentricity is far beyond the noise for the paper's model.
    assert health["at_noise_level"] == 0, health


def grafana_metric_names():
    """Every gearcoupling_* name in the Grafana dashboard's queries (panel targets and template
    variables)."""
    with open(GRAFANA_DASHBOARD) as f:
        board = json.load(f)
    queries = []

    def walk(panels):
        for panel in panels:
            queries.extend(t["expr"] for t in panel.get("targets", []))
            walk(panel.get("panels", []))

    walk(board["panels"])
    for variable in board.get("templating", {}).get("list", []):
        query = variable.get("query")
        if isinstance(query, dict):
            query = query.get("query", "")
        if variable.get("type") == "query":
            queries.append(query)
    assert queries, "the Grafana dashboard has no query"
    return {name for q in queries for name in re.findall(r"\bgearcoupling_[a-z0-9_]+", q)}


def test_every_metric_the_grafana_dashboard_queries_is_in_the_scrape(scrape):
    scraped = {name for name, _, _ in samples(scrape)}
    used = grafana_metric_names()
    assert len(used) >= 10, used
    assert used - scraped == set(), f"queried by {GRAFANA_DASHBOARD} but not in /metrics"
