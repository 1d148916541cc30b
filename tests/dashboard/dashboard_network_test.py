"""gearcoupling-dashboard as a server on a LAN (issue 38, findings 4 and 5).

4. A page of another site re-pointed at the dashboard's address (DNS rebinding) sends its own
   name as Host and Origin, and the header the apply button sends: POST /api/apply put a
   proposal in force (200) and /api/state answered. Now any Host or Origin that is not one of the
   dashboard's names (localhost, the listen address, an IP address, --allow-host) gets 403.
5. 70 connections sending a header byte every 3 s, or 100 idle connections that reconnect when
   closed, held all 64 HTTP threads: /, /metrics and /api/state timed out while they lasted. Now
   a request has 5 s in all, a peer at most 8 connections sending at once (429 beyond), and the
   page, /metrics and the API answer another host within a second throughout.

The attacks come from 127.0.0.2, the users from 127.0.0.1 (two hosts on loopback). The
dashboard alone on a private DDS domain, on a free port. Run by ctest
(tests/dashboard/CMakeLists.txt); `-s` prints the figures docs/security.md gives.
"""
import os
import signal
import socket
import subprocess
import threading
import time

import pytest

import domain_claim

SOURCE_DIR = os.environ["GC_SOURCE_DIR"]
DASHBOARD = os.environ["GC_DASHBOARD_BINARY"]
DOMAIN = domain_claim.claim()  # one per test process, held while it runs (domain_claim.py)
ENVIRONMENT = dict(os.environ,
                   CYCLONEDDS_URI="file://" + os.path.join(SOURCE_DIR, "deploy/cyclonedds-loopback.xml"))
ATTACKER = "127.0.0.2"
ATTACK_S = 10.0   # each attack lasts this long: longer than two request deadlines (5 s)


@pytest.fixture
def dashboard():
    child = subprocess.Popen([DASHBOARD, "--domain", str(DOMAIN), "--listen", "127.0.0.1:0",
                              "--operator-cells", "c", "--operator", "tester", "--allow-host", "dyno-hall.example"],
                             env=ENVIRONMENT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)
    try:
        line = child.stdout.readline()
        assert line.startswith("listening on http://127.0.0.1:"), f"dashboard printed {line!r}"
        yield {"child": child, "port": int(line.rsplit(":", 1)[1].strip(" /\n"))}
    finally:
        child.send_signal(signal.SIGTERM)
        try:
            child.wait(timeout=5)
        except subprocess.TimeoutExpired:
            child.kill()
            child.wait()


def request(port, method, path, headers, body=b"", timeout_s=5.0):
    """(status, body, seconds) of one request from 127.0.0.1; status None without an answer."""
    start = time.monotonic()
    head = f"{method} {path} HTTP/1.1\r\n" + "".join(f"{k}: {v}\r\n" for k, v in headers.items())
    head += f"Content-Length: {len(body)}\r\nConnection: close\r\n\r\n"
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=timeout_s) as s:
            s.sendall(head.encode() + body)
            data = b""
            while chunk := s.recv(65536):
                data += chunk
        status = int(data.split(b" ", 2)[1])
        return status, data.split(b"\r\n\r\n", 1)[1].decode(), time.monotonic() - start
    except (OSError, IndexError, ValueError):
        return None, "", time.monotonic() - start


def test_a_rebinding_page_gets_neither_the_state_nor_an_apply(dashboard):
    port = dashboard["port"]
    own = {"Host": f"127.0.0.1:{port}"}
    status, _, _ = request(port, "GET", "/api/state", own)
    assert status == 200
    # The page's own origin, as the browser sends it after the rebinding.
    rebound = {"Host": f"attacker.example:{port}", "Origin": f"http://attacker.example:{port}",
               "X-Gearcoupling-Apply": "1", "Content-Type": "application/x-www-form-urlencoded"}
    status, body, _ = request(port, "GET", "/api/state", rebound)
    assert status == 403 and "Host is not a name of this dashboard" in body, (status, body)
    apply = "/api/apply?test_cell=c&proposal=00000000000000aa"
    form = b""
    status, body, _ = request(port, "POST", apply, rebound, form)
    assert status == 403 and "Host is not a name" in body, (status, body)
    # The same apply under the dashboard's own name reaches the applier (no such proposal here).
    status, body, _ = request(port, "POST", apply, {**rebound, **own, "Origin": f"http://127.0.0.1:{port}"}, form)
    assert status == 404 and "has no proposal" in body, (status, body)
    # Another site's page posting to the right Host (a CSRF, which the header already stops).
    status, body, _ = request(port, "POST", apply, {**rebound, **own}, form)
    assert status == 403 and "Origin is not a name" in body, (status, body)
    for host in (f"localhost:{port}", "dyno-hall.example", f"DYNO-HALL.example:{port}", f"[::1]:{port}"):
        status, _, _ = request(port, "GET", "/metrics", {"Host": host})
        assert status == 200, host
    for host in ("dyno-hall.example.attacker.example", "localhost.attacker.example", "", "a:b:c"):
        status, _, _ = request(port, "GET", "/", {"Host": host})
        assert status == 403, host
    _, metrics, _ = request(port, "GET", "/metrics", own)
    assert 'gearcoupling_dashboard_http_refused_total{reason="foreign_host"} 7' in metrics


class Attack:
    """Connections from ATTACKER until stopped: each sends `send(k)` bytes every `every_s`
    (nothing when None) and is opened again when the dashboard closes it."""

    def __init__(self, port, connections, every_s, trickle):
        self.port, self.connections, self.every_s, self.trickle = port, connections, every_s, trickle
        self.stop = threading.Event()
        self.opened = 0
        self.threads = [threading.Thread(target=self.hold, daemon=True) for _ in range(connections)]

    def connect(self):
        s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        s.bind((ATTACKER, 0))
        s.settimeout(1.0)
        s.connect(("127.0.0.1", self.port))
        self.opened += 1
        return s

    def hold(self):
        request_bytes = b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: " + b"x" * 1000
        while not self.stop.is_set():
            try:
                s = self.connect()
            except OSError:
                time.sleep(0.05)
                continue
            sent = 0
            try:
                while not self.stop.is_set():
                    if self.trickle:
                        s.sendall(request_bytes[sent:sent + 1])
                        sent += 1
                    # Closed by the dashboard: read gives b"" (or an answer, then b"").
                    deadline = time.monotonic() + self.every_s
                    closed = False
                    while time.monotonic() < deadline and not self.stop.is_set():
                        try:
                            if s.recv(4096) == b"":
                                closed = True
                                break
                        except socket.timeout:
                            pass
                    if closed:
                        break
            except OSError:
                pass
            finally:
                s.close()

    def __enter__(self):
        for t in self.threads:
            t.start()
        time.sleep(1.0)   # all connected before the users ask
        return self

    def __exit__(self, *exc):
        self.stop.set()
        for t in self.threads:
            t.join(timeout=5)


def users_during(port, seconds):
    """GET /, /metrics and /api/state from 127.0.0.1 in turn for `seconds`: the slowest answer
    [s] and how many got none within 2 s."""
    slowest, unanswered, asked = 0.0, 0, 0
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        for path in ("/", "/metrics", "/api/state"):
            status, _, took = request(port, "GET", path, {"Host": f"127.0.0.1:{port}"}, timeout_s=2.0)
            asked += 1
            if status != 200:
                unanswered += 1
            slowest = max(slowest, took)
        time.sleep(0.2)
    return slowest, unanswered, asked


@pytest.mark.parametrize("kind, connections, every_s, trickle", [
    ("slow headers", 70, 3.0, True),
    ("idle, reconnecting", 100, 1.0, False),
])
def test_a_host_that_holds_connections_leaves_the_page_metrics_and_api_answering(
        dashboard, kind, connections, every_s, trickle):
    port = dashboard["port"]
    with Attack(port, connections, every_s, trickle) as attack:
        slowest, unanswered, asked = users_during(port, ATTACK_S)
    _, metrics, _ = request(port, "GET", "/metrics", {"Host": "127.0.0.1"})
    refused = {reason: next((line.split()[-1] for line in metrics.splitlines()
                             if line.startswith(f'gearcoupling_dashboard_http_refused_total{{reason="{reason}"}}')), None)
               for reason in ("peer_limit", "timeout")}
    print(f"\n{kind}: {connections} connections from {ATTACKER} for {ATTACK_S:.0f} s "
          f"({attack.opened} opened); users: {asked - unanswered} of {asked} answered, slowest "
          f"{slowest:.3f} s; refused peer_limit {refused['peer_limit']}, timeouts {refused['timeout']}")
    assert unanswered == 0, f"{unanswered} of {asked} requests got no answer within 2 s"
    assert slowest < 1.0
    assert float(refused["peer_limit"]) > 0
    assert float(refused["timeout"]) > 0


def test_a_whole_request_from_a_host_at_its_limit_is_answered_and_one_still_sending_is_not(dashboard):
    """The per-peer limit counts connections still sending. With 8 of the attacker's sending a
    head a byte at a time, a 9th whose whole GET has arrived (a proxy's, or a loaded client's
    burst) is answered; a 9th still sending gets 429."""
    port = dashboard["port"]
    slow, stop = [], threading.Event()

    def trickle():   # a byte each 0.5 s: within the 2 s between reads, so they stay counted
        while not stop.wait(0.5):
            for s in slow:
                try:
                    s.sendall(b"x")
                except OSError:
                    pass

    keeper = threading.Thread(target=trickle, daemon=True)
    try:
        for _ in range(8):
            s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            s.bind((ATTACKER, 0))
            s.connect(("127.0.0.1", port))
            s.sendall(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ")
            slow.append(s)
        keeper.start()
        time.sleep(1.0)   # each taken by a thread and counted (5 s for the whole request)

        def ask(head):
            with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
                s.bind((ATTACKER, 0))
                s.settimeout(3.0)
                s.connect(("127.0.0.1", port))
                s.sendall(head)
                data = b""
                while chunk := s.recv(65536):
                    data += chunk
            return int(data.split(b" ", 2)[1])

        assert ask(b"GET /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n") == 200
        assert ask(b"GET /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\n") == 429
        # A body announced is still to come: counted, so refused.
        assert ask(b"POST /api/apply HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 10\r\n\r\n") == 429
    finally:
        stop.set()
        if keeper.is_alive():
            keeper.join(timeout=2)
        for s in slow:
            s.close()
    _, metrics, _ = request(port, "GET", "/metrics", {"Host": "127.0.0.1"})
    refused = next(line.split()[-1] for line in metrics.splitlines()
                   if line.startswith('gearcoupling_dashboard_http_refused_total{reason="peer_limit"}'))
    assert float(refused) == 2
