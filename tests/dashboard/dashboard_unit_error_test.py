"""One unit check, on the dashboard too (issue 39, item 3): moments in kN·m under `_nm` headers are
a 1000-fold slip that `gearcoupling validate` refuses; replay forced through with --force-scale, a
real gearcoupling-monitor flags the cell (tests/live/unit_check_test.cc). Here, against that
monitor and a real gearcoupling-dashboard on the test's own loopback domain:
- the cell's card in headless Chromium shows validate's finding ("unit error: M_sy' measured RMS
  ...") with the stream's fix, and neither a worst region ("far off" explained) nor a proposal;
- /metrics has the cell's learning state as unit_error, and counts the slipped batches;
- `gearcoupling status` prints the same unit error line for the cell.

Run by ctest (tests/dashboard/CMakeLists.txt); skipped, saying so, without Chromium,
chromedriver or Selenium (deploy/install-deps.sh installs them).
"""
import csv
import json
import os
import re
import tempfile
import time
import urllib.request

import pytest

import headless_chromium

headless_chromium.require()
from headless_chromium import WebDriverWait, rerendered  # noqa: E402

import live_cell  # noqa: E402

TEST_CELL = "dyno-slip"
RECORDING = os.path.join(live_cell.SOURCE_DIR, "data/recordings/paper_torque_sweep.csv")
# validate's finding (kFinding in tests/live/unit_check_test.cc), and the fix for a live stream
# (analysis/scale_check.cc, UnitFix::stream) where validate's says to rename the column.
FINDING = "unit error: M_sy' measured RMS"
CLI_FIX = "give the column its unit"
STREAM_FIX = "the publisher must send N·m"
# Seconds the unit error must hold, with no worst region, diagnosis or proposal, once every
# sample is in: several times the monitor's --diagnose-after-s 1 (live_cell.MONITOR_OPTIONS).
HOLD_S = 4.0


def kilonewton_metres_under_nm(path):
    """The bundled torque sweep with its moments divided by 1000: kN·m under msy_nm and msz_nm.
    Its number of samples."""
    rows = 0
    with open(RECORDING, newline="") as source, open(path, "w", newline="") as out:
        reader, writer = csv.reader(source), csv.writer(out)
        header = next(reader)
        writer.writerow(header)
        moments = [header.index("msy_nm"), header.index("msz_nm")]
        for row in reader:
            for k in moments:
                row[k] = repr(float(row[k]) / 1000.0)
            writer.writerow(row)
            rows += 1
    return rows


def card(driver):
    """The cell's card: its data attributes and the texts of its health part, null before it."""
    return driver.execute_script("""
        const box = document.getElementById(arguments[0]);
        if (!box) return null;
        const text = selector => { const e = box.querySelector(selector); return e ? e.textContent : null; };
        const learning = box.querySelector('.learning');
        return Object.assign({
            unit_error: text('.unit-error'), worst_region: text('.worst-region'),
            learning: text('.learning'), proposal: text('.cell-proposal'),
            learning_state: learning ? learning.dataset.learningState : null,
            health: text('.model-health'), head: text('.cell-head'), text: box.innerText}, box.dataset);
    """, "cell-" + TEST_CELL)


def get(url):
    with urllib.request.urlopen(url, timeout=10) as response:
        return response.read().decode()


def taken(shown):
    """Samples taken, from the card's head ("samples taken 1,000, ..."): 0 before the first."""
    found = re.search(r"samples taken ([\d,]+)", (shown or {}).get("head") or "")
    return int(found.group(1).replace(",", "")) if found else 0


@pytest.fixture(scope="module")
def slipped():
    with live_cell.LiveCell(domain_offset=173) as cell, tempfile.TemporaryDirectory() as scratch:
        recording = os.path.join(scratch, "knm_under_nm.csv")
        samples = kilonewton_metres_under_nm(recording)
        validated = cell.cli("validate", "--data", recording, "--model", "paper", check=False, on_domain=False)
        assert validated.returncode == 2, validated.stderr
        # validate's finding, its numbers included, without its fix (the CLI's, not a stream's).
        finding = validated.stderr[validated.stderr.index(FINDING):].splitlines()[0]
        assert CLI_FIX in finding, finding
        finding = finding[:finding.index("; a fit to moments 1000 times off says nothing")]

        cell.start_monitor("paper")
        url = cell.start_dashboard()
        driver = cell.browser(url)
        started = time.monotonic()
        cell.cli("replay", "--in", recording, "--test-cell", TEST_CELL, "--speed", "20", "--wait-s", "20",
                 "--force-scale")
        WebDriverWait(driver, 30.0, poll_frequency=0.2, ignored_exceptions=rerendered()).until(
            lambda d: taken(card(d)) == samples and (card(d) or {}).get("unit_error"))
        shown_after_s = time.monotonic() - started
        # A diagnosis would start a second after the cell is beyond the noise: none may.
        time.sleep(HOLD_S)
        yield {"cell": cell, "driver": driver, "url": url, "finding": finding, "samples": samples,
               "card": card(driver), "shown_after_s": shown_after_s}


def test_the_card_shows_validates_finding_and_the_streams_fix_and_no_far_off_explanation(slipped):
    shown = slipped["card"]
    print(f"the card showed the unit error {slipped['shown_after_s']:.1f} s after the replay began; "
          f"model health badge: {shown['health']!r}")
    assert taken(shown) == slipped["samples"], shown["head"]
    error = shown["unit_error"]
    assert error is not None, shown["text"]
    assert error.startswith(f"test cell {TEST_CELL}: {FINDING}"), error
    assert slipped["finding"] in error, (error, slipped["finding"])   # validate's words and numbers
    assert "too small by about 1000" in error and STREAM_FIX in error, error
    assert "no diagnosis meanwhile" in error, error
    assert CLI_FIX not in error and "--force-scale" not in error, error   # no fix for a file
    # No region explains a 1000-fold error, no diagnosis ran, nothing is proposed.
    assert shown["worst_region"] is None and "Worst region" not in shown["text"], shown["text"]
    assert "errs most" not in shown["text"], shown["text"]
    assert shown["learning_state"] == "unit_error", shown
    assert shown["health"] == "unit error", shown["health"]   # the badge: not "model far off"
    assert shown["proposal"] is None, shown["proposal"]
    state = json.loads(get(slipped["url"] + "api/state"))
    assert [p for p in state.get("proposals", []) if p.get("test_cell") == TEST_CELL] == [], state["proposals"]
    assert state.get("monitors"), state
    for monitor in state["monitors"]:   # uint64 as a JSON string, as protobuf writes it
        assert int(monitor.get("diagnoses_run", 0)) == 0 and not monitor.get("diagnosing"), monitor


def test_metrics_expose_the_cells_learning_state_as_the_unit_error(slipped):
    text = get(slipped["url"] + "metrics")
    cell_label = f'test_cell="{TEST_CELL}"'
    states = [line for line in text.splitlines()
              if line.startswith("gearcoupling_cell_learning_state{") and cell_label in line]
    assert len(states) == 1, states   # one state at a time
    assert 'state="unit_error"' in states[0] and states[0].endswith(" 1"), states
    batches = [line for line in text.splitlines()
               if line.startswith("gearcoupling_cell_unit_slip_batches_total{") and cell_label in line]
    assert len(batches) == 1 and float(batches[0].split()[-1]) > 0, batches
    healths = [line for line in text.splitlines()
               if line.startswith("gearcoupling_cell_model_health{") and cell_label in line and line.endswith(" 1")]
    assert len(healths) == 1 and 'health="unit_error"' in healths[0], healths   # not far_off


def test_status_prints_the_unit_error_line_for_the_cell(slipped):
    printed = slipped["cell"].cli("status").stdout
    lines = printed.splitlines()
    error = [line for line in lines if line.startswith(f"{TEST_CELL}: test cell {TEST_CELL}: {FINDING}")]
    assert len(error) == 1, printed
    assert slipped["finding"] in error[0] and STREAM_FIX in error[0], error[0]
    assert slipped["card"]["unit_error"] == error[0][len(f"{TEST_CELL}: "):], (error[0], slipped["card"])
    # The unit error and the learning loop's state, and no worst region between them.
    said = [line for line in lines if line.startswith(f"{TEST_CELL}: ")]
    assert said == [error[0], f"{TEST_CELL}: learning: {error[0][len(TEST_CELL) + 2:]}"], printed
