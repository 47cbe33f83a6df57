"""Cases per second of a campaign: a plain loop over run_scenario() in one process against the
campaign in this process and on a LocalCluster of 1 and 2 workers (docs/benchmarks.md).

    PYTHONPATH=build/ci/python /usr/bin/python3 -m smoothsteer.campaign_benchmark \
        docs/campaigns/lane_change.yaml --cases 400

Every configuration runs the same cases 0 .. N-1 of the spec into a fresh directory. The
cluster's start is timed apart from its run. The per-case overhead of the cluster is the
difference of the 1-worker campaign and the plain loop, per case: both use one core for the
cases, so it is what the scheduling, the transfer of batches and rows, and the CSV cost."""
import argparse
import os
import sys
import tempfile
import time

from . import run_scenario
from .campaign_run import local_client, run_cases
from .campaign_spec import load_spec


def plain_loop(spec, cases):
    overrides = [spec.case_overrides(case) for case in range(cases)]
    started = time.perf_counter()
    for case_overrides in overrides:
        run_scenario(spec.base, case_overrides)
    return time.perf_counter() - started


def campaign_time(spec, directory, workers, batch_size):
    out = os.path.join(directory, f"workers_{workers}")
    if workers == 0:
        run = run_cases(spec, out, serial=True, batch_size=batch_size, progress=False)
        return run.elapsed_s, 0.0
    started = time.perf_counter()
    client, cluster = local_client(workers)
    start_s = time.perf_counter() - started
    try:
        run = run_cases(spec, out, client=client, batch_size=batch_size, progress=False)
    finally:
        client.close()
        cluster.close()
    assert run.ran == spec.cases and run.failed == 0, run
    return run.elapsed_s, start_s


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spec")
    parser.add_argument("--cases", type=int, default=400)
    parser.add_argument("--batch-size", type=int, default=None,
                        help="cases per task (default: the campaign's own choice)")
    arguments = parser.parse_args(argv)
    spec = load_spec(arguments.spec)
    spec.cases = arguments.cases
    rows = [("plain loop over run_scenario, one process", plain_loop(spec, spec.cases), 0.0)]
    with tempfile.TemporaryDirectory() as directory:
        for workers, label in ((0, "campaign in this process (--serial)"),
                               (1, "campaign, LocalCluster of 1 worker"),
                               (2, "campaign, LocalCluster of 2 workers")):
            elapsed, start_s = campaign_time(spec, directory, workers, arguments.batch_size)
            rows.append((label, elapsed, start_s))
    plain = rows[0][1] / spec.cases
    print(f"{spec.name}: {spec.cases} cases, {os.cpu_count()} cores")
    print("| configuration | cases/s | ms per case | cluster start [s] |")
    print("|---|---|---|---|")
    for label, elapsed, start_s in rows:
        start = f"{start_s:.1f}" if start_s else ""
        print(f"| {label} | {spec.cases / elapsed:.1f} | {1e3 * elapsed / spec.cases:.2f} | "
              f"{start} |")
    overhead = rows[2][1] / spec.cases - plain
    print(f"per-case overhead of the cluster (1 worker - plain loop): {1e3 * overhead:.2f} ms "
          f"({100.0 * overhead / plain:.1f} % of a case)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
