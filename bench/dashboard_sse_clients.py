#!/usr/bin/env python3
"""N Server-Sent-Event clients of gearcoupling-dashboard, each doing what the page does with an
update (read it, parse its JSON), for bench/dashboard_bench.sh. Latency of an update: the time
it is received minus when the monitor published the newest residual batch it summarises
(ResidualAggregate.latest_published_unix_s; one host, one clock).

    dashboard_sse_clients.py URL CLIENTS SECONDS
prints: clients served, clients refused (503 beyond --max-streams), updates received per
served client per second, latency p50 and p99 [ms], residual
aggregates received, and this process's CPU time as a share of one core.
"""
import http.client
import json
import statistics
import sys
import threading
import time
import urllib.parse


def client(url, seconds, latencies, counts, refused, lock):
    parts = urllib.parse.urlsplit(url)
    connection = http.client.HTTPConnection(parts.hostname, parts.port, timeout=seconds + 5)
    connection.request("GET", "/events")
    response = connection.getresponse()
    if response.status != 200:  # 503 beyond the dashboard's --max-streams
        connection.close()
        with lock:
            refused.append(response.status)
        return
    end = time.monotonic() + seconds
    mine, updates = [], 0
    while time.monotonic() < end:
        line = response.fp.readline()
        if not line:
            break
        if not line.startswith(b"data: "):
            continue
        received = time.time()
        state = json.loads(line[6:])
        updates += 1
        for cell in state.get("test_cells", []):
            for aggregate in cell.get("residuals", []):
                mine.append(received - aggregate["latest_published_unix_s"])
    connection.close()
    with lock:
        latencies.extend(mine)
        counts.append(updates)


def main():
    url, clients, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    cpu_start, wall_start = time.process_time(), time.monotonic()
    latencies, counts, refused, lock = [], [], [], threading.Lock()
    threads = [threading.Thread(target=client, args=(url, seconds, latencies, counts, refused, lock))
               for _ in range(clients)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    latencies.sort()
    p = lambda q: 1e3 * latencies[min(len(latencies) - 1, int(q * len(latencies)))] if latencies else float("nan")
    mean = statistics.mean(counts) if counts else 0.0
    print(f"clients={len(counts)} refused={len(refused)} updates_per_client_per_s={mean / seconds:.2f} "
          f"latency_p50_ms={p(0.50):.1f} latency_p99_ms={p(0.99):.1f} aggregates={len(latencies)} "
          f"cpu={100 * (time.process_time() - cpu_start) / (time.monotonic() - wall_start):.1f}%")


if __name__ == "__main__":
    main()
