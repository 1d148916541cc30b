"""A live test cell for the dashboard's browser tests: a real gearcoupling-monitor, dashboards and
headless Chromium on the test's own loopback DDS domain, all stopped when the `with` block ends
(terminated, killed after 10 s). The binaries come from the environment ctest sets
(tests/dashboard/CMakeLists.txt).

    with live_cell.LiveCell(domain_offset=131) as cell:
        cell.start_monitor("paper", "--diagnose-after-s", "1")
        url = cell.start_dashboard()
        driver = cell.browser(url)
        cell.cli("replay", "--in", recording, "--test-cell", "dyno", "--speed", "20", "--wait-s", "20")

A test module that uses browser() calls headless_chromium.require() at its top, as before.
"""
import os
import subprocess

import domain_claim
import headless_chromium

SOURCE_DIR = os.environ["GC_SOURCE_DIR"]
DASHBOARD = os.environ["GC_DASHBOARD_BINARY"]
MONITOR = os.environ["GC_MONITOR_BINARY"]
CLI = os.environ["GC_GEARCOUPLING_BINARY"]
ENVIRONMENT = dict(os.environ,
                   CYCLONEDDS_URI="file://" + os.path.join(SOURCE_DIR, "deploy/cyclonedds-loopback.xml"))
# The monitor's options for a test: a 20 s window (a 50 Hz cell fills it, issue 39), healths
# five times a second, a cell neither stale nor disposed during a test, diagnoses soon and at
# full priority.
MONITOR_OPTIONS = ("--window-s", "20", "--health-period-s", "0.2", "--stale-s", "60",
                   "--dispose-s", "120", "--diagnose-after-s", "1", "--diagnosis-nice", "0")


def domain(offset):
    """The test's loopback DDS domain: one per process, `offset` apart from the other modules'."""
    return domain_claim.claim(offset)


class LiveCell:
    """The processes and browsers of one test module on DDS domain `domain(domain_offset)`."""

    def __init__(self, domain_offset):
        self.domain = domain(domain_offset)
        self.children = []
        self.drivers = []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()
        return False

    def start(self, args, env=ENVIRONMENT, **kwargs):
        child = subprocess.Popen(args, env=env, **kwargs)
        self.children.append(child)
        return child

    def start_monitor(self, model, *extra):
        """gearcoupling-monitor with MONITOR_OPTIONS and then `extra` (later flags win)."""
        return self.start([MONITOR, "--domain", str(self.domain), "--model", model, *MONITOR_OPTIONS, *extra],
                          stderr=subprocess.DEVNULL)

    def start_dashboard(self, *extra, identity=None):
        """gearcoupling-dashboard on a free loopback port; its URL ("http://127.0.0.1:PORT/")."""
        env = dict(ENVIRONMENT, GC_IDENTITY=identity) if identity else ENVIRONMENT
        child = self.start([DASHBOARD, "--domain", str(self.domain), "--listen", "127.0.0.1:0", *extra],
                           env=env, stdout=subprocess.PIPE, text=True)
        line = child.stdout.readline()
        assert line.startswith("listening on http://"), f"dashboard printed {line!r}"
        return line.split("listening on ", 1)[1].strip()

    def browser(self, url, window_size="1400,2400"):
        """Headless Chromium showing `url`, quit when the cell stops."""
        driver = headless_chromium.new_driver(window_size)
        self.drivers.append(driver)
        driver.get(url)
        return driver

    def cli(self, command, *args, check=True, on_domain=True, env=ENVIRONMENT):
        """`gearcoupling COMMAND ARGS --domain D` (without --domain unless `on_domain`): the
        completed process, its stdout and stderr as text."""
        domain = ("--domain", str(self.domain)) if on_domain else ()
        return subprocess.run([CLI, command, *args, *domain], env=env, check=check,
                              capture_output=True, text=True)

    def stop(self):
        try:
            for driver in self.drivers:
                driver.quit()
        finally:
            self.drivers.clear()
            self.stop_processes()

    def stop_processes(self):
        for child in self.children:
            child.terminate()
        for child in self.children:
            try:
                child.wait(timeout=10)
            except subprocess.TimeoutExpired:
                child.kill()
                child.wait()
        self.children.clear()
