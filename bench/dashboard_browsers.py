#!/usr/bin/env python3
"""N headless Chromium pages (each its own browser: Chromium allows only 6 connections to one
host per browser, and each page holds one event stream) on gearcoupling-dashboard, for
bench/dashboard_bench.sh with DASHBOARD_BENCH_CLIENT=browser. Each page is polled about once a
second for its test cell's newest drawn point: drawn (the page's clock) minus published (the
monitor's), one host.

    dashboard_browsers.py URL BROWSERS SECONDS
prints: browsers, updates a page received per second, drawn-latency p50 and p99 [ms], samples.
"""
import statistics
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

READ = ("const c = document.querySelector('.cell[data-latest-drawn-unix-s]');"
        "return [Number(document.getElementById('updates').dataset.count),"
        " c ? Number(c.dataset.latestDrawnUnixS) - Number(c.dataset.latestPublishedUnixS) : null];")


def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,2000"):
        options.add_argument(argument)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def main():
    url, count, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    drivers = []
    try:
        for _ in range(count):
            drivers.append(browser())
            drivers[-1].get(url)
        print("ready", flush=True)  # the pages are open: the caller starts its phase
        start = [d.execute_script(READ)[0] for d in drivers]
        begin = time.monotonic()
        latencies = []
        while time.monotonic() - begin < seconds:
            for driver in drivers:
                _, latency = driver.execute_script(READ)
                if latency is not None:
                    latencies.append(latency)
        elapsed = time.monotonic() - begin
        end = [d.execute_script(READ)[0] for d in drivers]
        rates = [(b - a) / elapsed for a, b in zip(start, end)]
        latencies.sort()
        p = lambda q: 1e3 * latencies[min(len(latencies) - 1, int(q * len(latencies)))] if latencies else float("nan")
        print(f"browsers={count} updates_per_page_per_s={statistics.mean(rates):.2f} "
              f"(min {min(rates):.2f}) drawn_latency_p50_ms={p(0.5):.1f} p99_ms={p(0.99):.1f} "
              f"samples={len(latencies)}")
    finally:
        for driver in drivers:
            driver.quit()


if __name__ == "__main__":
    main()
