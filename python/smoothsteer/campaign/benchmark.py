"""Parallel efficiency of campaigns (docs/benchmarks.md): the same cases in this process and on
a LocalCluster of N workers, for each campaign size given.

    PYTHONPATH=build/ci/python /usr/bin/python3 -m smoothsteer.campaign.benchmark \
        docs/campaigns/lane_change.yaml --range speed.initial_mps=5:7 --cases 3000 300

Per size and round, three configurations take turns (the machine's load drifts; the median
is reported), each into a fresh directory:
- serial: run_campaign(serial=True);
- kept cluster: run_campaign(client=cluster) on a LocalCampaignCluster started once before the
  rounds (its start is reported apart), as campaigns run one after another from Python;
- fresh: run_campaign(workers=N) as the command line runs it, the start of its cluster (or its
  decision to run in this process) included.
- plain processes: N forked processes, each a plain loop of run_case over its share of the
  cases, no Dask and no results.csv: what the machine's cores give at best at that moment.
Speed-up is the serial time over the configuration's, efficiency the speed-up over N. "case in
its process" is the mean of results.csv's elapsed_s (run_scenario alone, where it ran): against
the serial run's, it shows what the cores' sharing costs a case. "busy" is the sum of elapsed_s
over the wall time of the threads that ran the cases: what the scheduling leaves idle."""
import argparse
import multiprocessing
import os
import sys
import tempfile
import time

import numpy as np
import yaml

from . import LocalCampaignCluster, run_campaign
from .cases import run_case
from .results import read_rows
from .spec import load_spec


def restricted_spec(file, ranges, directory):
    """The spec with each `key=low:high` of `ranges` as its variable's range, written to
    `directory` (its base made absolute); returns the copy's path."""
    with open(file, encoding="utf-8") as handle:
        content = yaml.safe_load(handle)
    content["base"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(file)),
                                                    content["base"]))
    for item in ranges:
        key, bounds = item.split("=", 1)
        low, high = (float(bound) for bound in bounds.split(":"))
        content["variables"][key].update(low=low, high=high)
    path = os.path.join(directory, "benchmark_spec.yaml")
    with open(path, "w", encoding="utf-8") as handle:
        yaml.safe_dump(content, handle, sort_keys=False)
    return path


def timed(directory, spec, **where):
    out = os.path.join(directory, f"run_{time.time_ns()}")
    started = time.perf_counter()
    run = run_campaign(spec, out, progress=False, **where)
    elapsed = time.perf_counter() - started
    assert run.ran == spec.cases and run.failed == 0, run
    return elapsed, run, float(read_rows(out, spec)["elapsed_s"].sum())


def _share(arguments):
    spec, cases = arguments
    return sum(run_case(spec, case)["elapsed_s"] for case in cases)


def plain_processes(spec, workers):
    """Wall time and summed case time of the cases on `workers` forked plain loops."""
    shares = [(spec, range(first, spec.cases, workers)) for first in range(workers)]
    with multiprocessing.get_context("fork").Pool(workers) as pool:
        pool.map(_share, [(spec, []) for _ in range(workers)])  # the processes are up
        started = time.perf_counter()
        busy = sum(pool.map(_share, shares))
        elapsed = time.perf_counter() - started
    return elapsed, None, busy


def measure(spec, directory, cluster, workers, rounds):
    """{configuration: [(wall s, CampaignRun or None, summed case time), ...]} over the rounds."""
    measured = {"serial": [], "kept cluster": [], "fresh": [], "plain processes": []}
    for _ in range(rounds):
        measured["serial"].append(timed(directory, spec, serial=True))
        measured["kept cluster"].append(timed(directory, spec, client=cluster))
        measured["fresh"].append(timed(directory, spec, workers=workers))
        measured["plain processes"].append(plain_processes(spec, workers))
    return measured


def _threads(run, workers):
    return workers if run is None else max(run.workers, 1)


def _place(run, workers):
    if run is None:
        return f"{workers} processes"
    return f"{run.workers} workers" if run.workers else "this process"


def report(spec, measured, workers):
    serial = float(np.median([value[0] for value in measured["serial"]]))
    print(f"\n{spec.cases} cases")
    print("| configuration | wall s | speed-up | efficiency | ran on | case in its process, ms | "
          "busy |")
    print("|---|---|---|---|---|---|---|")
    for label, values in measured.items():
        elapsed = float(np.median([value[0] for value in values]))
        case_ms = float(np.median([1e3 * value[2] / spec.cases for value in values]))
        busy = float(np.median([value[2] / (value[0] * _threads(value[1], workers))
                                for value in values]))
        places = sorted({_place(run, workers) for _, run, _ in values})
        speed_up = serial / elapsed
        print(f"| {label} | {elapsed:.2f} | {speed_up:.2f} | "
              f"{100 * speed_up / (workers if label != 'serial' else 1):.0f} % | "
              f"{', '.join(places)} | {case_ms:.1f} | {100 * busy:.0f} % |")
    probe = [1e3 * run.case_s for _, run, _ in measured["kept cluster"]]
    print(f"case time measured before spreading: {', '.join(f'{v:.1f}' for v in probe)} ms")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spec")
    parser.add_argument("--cases", type=int, nargs="+", default=[3000, 300])
    parser.add_argument("--range", action="append", default=[], metavar="KEY=LOW:HIGH",
                        help="a variable's range instead of the spec's")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=3)
    arguments = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as directory:
        spec = load_spec(restricted_spec(arguments.spec, arguments.range, directory))
        print(f"{spec.name} {' '.join(arguments.range)}: {os.cpu_count()} cores, "
              f"{arguments.workers} workers, median of {arguments.rounds} rounds, load average "
              f"{os.getloadavg()[0]:.2f} at the start")
        with LocalCampaignCluster(arguments.workers) as cluster:
            cluster.client.run(lambda: None)  # started and the workers answering
            print(f"kept cluster's start: {cluster.start_s:.2f} s")
            for cases in arguments.cases:
                spec.cases = cases
                report(spec, measure(spec, directory, cluster, arguments.workers,
                                     arguments.rounds), arguments.workers)
        print(f"\nload average {os.getloadavg()[0]:.2f} at the end")
    return 0


if __name__ == "__main__":
    sys.exit(main())
