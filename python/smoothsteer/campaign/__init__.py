"""Validation campaigns: sample an operating domain around a base scenario, run every case on a
Dask cluster (a local one by default) or in this process, and report the worst cases, the
spread and every failure with the command that replays it (docs/campaigns.md).

    PYTHONPATH=build/ci/python /usr/bin/python3 -m smoothsteer.campaign SPEC.yaml --out DIR
        [--scheduler tcp://host:8786 | --workers N | --serial] [--batch-size N] [--report-only]

From Python:

    from smoothsteer import campaign
    run = campaign.run_campaign("docs/campaigns/lane_change.yaml", "out/lane_change")
    campaign.write_report("docs/campaigns/lane_change.yaml", "out/lane_change")
    with campaign.LocalCampaignCluster(workers=2) as cluster:  # started once, kept
        campaign.run_campaign("a.yaml", "out/a", client=cluster)
        campaign.run_campaign("b.yaml", "out/b", client=cluster)

Results go to DIR/results.csv as they come (one row per case); running the same command again
resumes a killed campaign without repeating a finished case. The report is DIR/report.md and
its PNGs."""
import argparse
import sys

from .cluster import LocalCampaignCluster
from .run import CampaignRun, run_cases
from .spec import CampaignSpec, load_spec
from .spec_file import CampaignSpecError


def _spec(spec):
    return spec if isinstance(spec, CampaignSpec) else load_spec(spec)


def run_campaign(spec, out, scheduler=None, workers=None, client=None, serial=False,
                 batch_size=None, progress=True, batch_runner=None):
    """Runs the cases of a campaign that `out` does not hold yet; returns a CampaignRun.

    spec: a spec file or a CampaignSpec. Where: `client` (a distributed.Client, or a
    LocalCampaignCluster kept across calls), else `scheduler` (its address), else `serial=True`
    (this process), else a LocalCluster of `workers` processes (default: the machine's cores),
    started only if it pays for its start (else the cases run in this process) and closed at
    the end. batch_size: cases per task (default: the spec's, else cut from a measured case's
    time, docs/campaigns.md). batch_runner replaces cases.run_batch (tests)."""
    spec = _spec(spec)
    owned = None
    if not serial and client is None:
        if scheduler:
            from distributed import Client

            try:
                client = owned = Client(scheduler)
            except Exception as error:  # noqa: BLE001 - any failure to connect is the address's
                raise CampaignSpecError(f"--scheduler {scheduler}: cannot connect to a Dask "
                                        f"scheduler: {type(error).__name__}: {error}") from None
        else:
            client = owned = LocalCampaignCluster(workers)
    try:
        return run_cases(spec, str(out), client=client, serial=serial, batch_size=batch_size,
                         progress=progress, batch_runner=batch_runner)
    finally:
        if owned is not None:
            owned.close()


def write_report(spec, out, replay_trace=True):
    """Writes DIR/report.md and its PNGs from DIR/results.csv; returns the report's path."""
    from .report import write_report as write

    return write(_spec(spec), str(out), replay_trace=replay_trace)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m smoothsteer.campaign",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("spec", help="campaign spec (YAML, docs/campaigns.md)")
    parser.add_argument("--out", required=True, help="results directory (resumed if it exists)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", help="address of a Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--workers", type=int, help="LocalCluster processes (default: cores)")
    where.add_argument("--serial", action="store_true", help="run in this process")
    parser.add_argument("--batch-size", type=int, help="cases per task")
    parser.add_argument("--report-only", action="store_true", help="write the report only")
    parser.add_argument("--no-report", action="store_true", help="run the cases only")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    arguments = parser.parse_args(argv)
    if arguments.workers is not None and arguments.workers < 1:
        parser.error("--workers must be >= 1")
    if arguments.batch_size is not None and arguments.batch_size < 1:
        parser.error("--batch-size must be >= 1")
    try:
        spec = load_spec(arguments.spec)
        if not arguments.report_only:
            run = run_campaign(spec, arguments.out, scheduler=arguments.scheduler,
                               workers=arguments.workers, serial=arguments.serial,
                               batch_size=arguments.batch_size, progress=not arguments.quiet)
            where = f"{run.workers} workers" if run.workers else "this process"
            print(f"{spec.name}: ran {run.ran} cases ({run.recovered} were done) on {where} in "
                  f"{run.elapsed_s:.1f} s, {run.cases_per_second:.1f} cases/s, "
                  f"{run.failed} failed, {run.lost_tasks} tasks lost -> {run.results}")
        if not arguments.no_report:
            print(f"wrote {write_report(spec, arguments.out)}")
    except CampaignSpecError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except OSError as error:  # a file of the results directory that cannot be written
        print(f"error: --out {arguments.out}: {error.filename or ''}: {error.strerror or error}",
              file=sys.stderr)
        return 2
    return 0


__all__ = ["CampaignRun", "CampaignSpec", "CampaignSpecError", "LocalCampaignCluster", "load_spec",
           "run_campaign", "write_report", "main"]
