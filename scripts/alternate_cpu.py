#!/usr/bin/env python3
"""Two or more oscsim builds on one scenario, runs alternated, CPU time compared (issue 31).

    scripts/alternate_cpu.py RUNS SCENARIO BIN [BIN ...]

Runs `BIN run SCENARIO --quiet` for every BIN, RUNS rounds, the order of the builds reversed
every other round (so that neither always runs first after a pause, or always second), and
prints for each build the least and the median CPU time (user + system, of the whole process)
and both as ratios to the first build's. On a shared machine a difference of a few per cent
is only seen this way: one build after the other drifts with the machine's other load, and a
ratio of least times taken in the same minutes does not. docs/performance.md gives the
figures of the changes it judged (the machine's load is printed at the end: judge on a quiet
machine, load below about 1.2 on two cores).
"""

import os
import resource
import statistics
import subprocess
import sys


def cpu_seconds(cmd):
    """CPU time (user + system, s) of one run of `cmd`."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main(argv):
    if len(argv) < 4 or not argv[1].isdigit() or int(argv[1]) < 1:
        sys.exit(__doc__)
    rounds, scenario, builds = int(argv[1]), argv[2], argv[3:]
    if not os.path.isfile(scenario):
        sys.exit(f"{scenario}: no such scenario file")
    times = {b: [] for b in builds}
    for k in range(rounds):
        for b in builds if k % 2 == 0 else reversed(builds):
            times[b].append(cpu_seconds([b, "run", scenario, "--quiet"]))
    least0 = min(times[builds[0]])
    median0 = statistics.median(times[builds[0]])
    width = max(len(b) for b in builds)
    print(f"{'build':{width}}  least s  median s  least/first  median/first  ({rounds} rounds)")
    for b in builds:
        least, median = min(times[b]), statistics.median(times[b])
        print(f"{b:{width}}  {least:7.3f}  {median:8.3f}  {least / least0:11.4f}  "
              f"{median / median0:12.4f}")
    print("load average after:", " ".join(open("/proc/loadavg").read().split()[:3]))


if __name__ == "__main__":
    main(sys.argv)
