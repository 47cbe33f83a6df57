"""Cases per second of a campaign: a plain loop over run_scenario() in one process against the
campaign in this process and on a LocalCluster of 1 and 2 workers (docs/benchmarks.md).

    PYTHONPATH=build/ci/python /usr/bin/python3 -m smoothsteer.campaign.benchmark \
        docs/campaigns/lane_change.yaml --cases 400

Every configuration runs the same cases 0 .. N-1 of the spec into a fresh directory, and the
configurations take turns for --rounds rounds (the machine's load drifts; the median is
reported). The cluster's start is timed apart from its run. The per-case overhead of the
cluster is the difference of the 1-worker campaign and the plain loop, per case: both use one
core for the cases, so it is what the scheduling, the transfer of batches and rows, and the CSV
cost. "run in the worker" is the mean of results.csv's elapsed_s: run_scenario() alone, as the
worker measured it."""
import argparse
import os
import sys
import tempfile
import time

import numpy as np

from .. import run_scenario
from .run import local_client, run_cases
from .spec import load_spec


def plain_loop(spec, cases):
    overrides = [spec.case_overrides(case) for case in range(cases)]
    started = time.perf_counter()
    for case_overrides in overrides:
        run_scenario(spec.base, case_overrides)
    return time.perf_counter() - started


def _mean_elapsed(out, spec):
    from .results import read_rows

    return float(read_rows(out, spec)["elapsed_s"].mean())


def campaign_time(spec, directory, workers, batch_size):
    """(wall time of the cases, cluster start, mean run time in the worker)."""
    out = os.path.join(directory, f"workers_{workers}_{time.time_ns()}")
    if workers == 0:
        run = run_cases(spec, out, serial=True, batch_size=batch_size, progress=False)
        return run.elapsed_s, 0.0, _mean_elapsed(out, spec)
    started = time.perf_counter()
    client, cluster = local_client(workers)
    start_s = time.perf_counter() - started
    try:
        run = run_cases(spec, out, client=client, batch_size=batch_size, progress=False)
    finally:
        client.close()
        cluster.close()
    assert run.ran == spec.cases and run.failed == 0, run
    return run.elapsed_s, start_s, _mean_elapsed(out, spec)


def _nothing(spec, cases):
    return []


def task_overhead(spec, tasks=400):
    """Wall time per task of an empty batch on a LocalCluster of 1 worker, sent as the
    campaign sends its batches (the spec travels with each)."""
    from distributed import as_completed

    client, cluster = local_client(1)
    try:
        client.submit(_nothing, spec, [], pure=False).result()  # the worker imports smoothsteer
        started = time.perf_counter()
        for future in as_completed([client.submit(_nothing, spec, [case], pure=False)
                                    for case in range(tasks)]):
            future.result()
        return (time.perf_counter() - started) / tasks
    finally:
        client.close()
        cluster.close()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spec")
    parser.add_argument("--cases", type=int, default=400)
    parser.add_argument("--batch-size", type=int, default=None,
                        help="cases per task (default: the campaign's own choice)")
    parser.add_argument("--rounds", type=int, default=3)
    arguments = parser.parse_args(argv)
    spec = load_spec(arguments.spec)
    spec.cases = arguments.cases
    labels = ["plain loop over run_scenario, one process", "campaign in this process (--serial)",
              "campaign, LocalCluster of 1 worker", "campaign, LocalCluster of 2 workers"]
    measured = {label: [] for label in labels}
    with tempfile.TemporaryDirectory() as directory:
        for _ in range(arguments.rounds):
            measured[labels[0]].append((plain_loop(spec, spec.cases), 0.0, float("nan")))
            for workers, label in enumerate(labels[1:]):
                measured[label].append(campaign_time(spec, directory, workers,
                                                     arguments.batch_size))
    median = {label: [float(np.median([m[i] for m in values])) for i in range(3)]
              for label, values in measured.items()}
    print(f"{spec.name}: {spec.cases} cases, {os.cpu_count()} cores, median of "
          f"{arguments.rounds} rounds, load average {os.getloadavg()[0]:.1f} at the end")
    print("| configuration | cases/s | wall ms per case | run in the worker, ms | "
          "cluster start [s] |")
    print("|---|---|---|---|---|")
    for label in labels:
        elapsed, start_s, in_worker = median[label]
        print(f"| {label} | {spec.cases / elapsed:.1f} | {1e3 * elapsed / spec.cases:.2f} | "
              f"{'' if np.isnan(in_worker) else f'{1e3 * in_worker:.2f}'} | "
              f"{f'{start_s:.1f}' if start_s else ''} |")
    plain = median[labels[0]][0] / spec.cases
    overhead = median[labels[2]][0] / spec.cases - plain
    print(f"per-case overhead of the cluster (1 worker - plain loop): {1e3 * overhead:.2f} ms "
          f"({100.0 * overhead / plain:.1f} % of a case)")
    print(f"one empty task on a LocalCluster of 1 worker: {1e3 * task_overhead(spec):.2f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
