#!/usr/bin/env python3
"""Where a round trip's threads ran, 100 ms at a time, from a `perf sched` trace.

With one CPU hog per core, a blocking round trip (three threads woken in turn: the caller, the
client's receive thread, the server's receive thread) is fast while the scheduler keeps the
three on one core and slow while it splits them over both (docs/architecture.md, "Few
wake-ups besides the round trip's own"). This reads `perf sched timehist` output and, for each 100 ms window, says on which CPU
each of the three threads mostly ran and how many times the least frequent of them ran (about
one run per round trip), then sums up the windows where all three shared a CPU ("together")
and the others ("split").

    perf sched record -o trace.data -- COMMAND...      # while the hogs run
    perf sched timehist -i trace.data > trace.txt
    bench/sched_regimes.py trace.txt [THREAD ...]

THREAD is a task name as timehist prints it (`recvUC[1234/1230]`); by default the three most
often scheduled tasks other than `sh` (the hogs), `perf` and Cyclone's `tev`.
"""
import collections
import statistics
import sys

WINDOW_S = 0.1


def read_runs(path):
    """(time_s, cpu, task) for every switch-out line of timehist's output."""
    runs = []
    with open(path) as text:
        for line in text:
            fields = line.split()
            if len(fields) < 6 or not fields[1].startswith("["):
                continue
            try:
                runs.append((float(fields[0]), int(fields[1].strip("[]")), fields[2]))
            except ValueError:
                continue  # the header
    return runs


def default_threads(runs):
    counts = collections.Counter(task for _, _, task in runs)
    skip = ("sh[", "perf", "tev[", "<idle>", "timeout[")
    return [task for task, _ in counts.most_common() if not task.startswith(skip)][:3]


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    runs = read_runs(argv[1])
    if not runs:
        print(f"{argv[1]}: no perf sched timehist lines", file=sys.stderr)
        return 1
    threads = argv[2:] or default_threads(runs)
    start = runs[0][0]
    windows = collections.defaultdict(lambda: collections.defaultdict(collections.Counter))
    for time_s, cpu, task in runs:
        if task in threads:
            windows[int((time_s - start) / WINDOW_S)][task][cpu] += 1
    together, split = [], []
    print("window_s " + " ".join(threads) + "  (runs@cpu)")
    for index in sorted(windows):
        window = windows[index]
        if any(task not in window for task in threads):
            continue
        cpus = [window[task].most_common(1)[0][0] for task in threads]
        runs_in_window = min(sum(window[task].values()) for task in threads)
        (together if len(set(cpus)) == 1 else split).append(runs_in_window)
        cells = [f"{sum(window[t].values())}@{c}" for t, c in zip(threads, cpus)]
        print(f"{index * WINDOW_S:6.1f}   " + " ".join(cells))
    for name, counts in (("together", together), ("split", split)):
        median = statistics.median(counts) if counts else 0
        print(f"{name}: {len(counts)} windows, median {median:.0f} runs per 100 ms")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
