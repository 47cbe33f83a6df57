"""Running a campaign's cases (docs/campaigns.md): in this process, or on Dask (a LocalCluster
on the machine's cores, or a scheduler's workers), in batches, each batch's rows appended to
results.csv as it finishes.

A batch whose worker dies is lost as a whole (its rows come back only at its end). Its cases are
sent again one per task; a case whose task is lost twice is written as failed (error_kind
`worker_died`) with the last error, so no case is dropped. The LocalCluster's scheduler has
`allowed-failures` 0, so that every loss is counted here, and `worker-saturation` 1, so that a
worker holds only the task it runs and its death costs no queued task a loss. An external
scheduler retries a task itself first (its `distributed.scheduler.allowed-failures`, 3 by
default) and may queue tasks on a worker."""
import collections
import logging
import os
import time
from dataclasses import dataclass

from .cases import failed_row, run_batch
from .results import ResultFile

CASE_FAILURES = 2  # losses of a case before it is written as failed
MAX_BATCH = 32


@dataclass
class CampaignRun:
    """What one call of run_campaign did."""

    results: str  # path of results.csv
    cases: int  # the campaign's cases
    recovered: int  # rows already in results.csv
    ran: int  # cases run by this call
    failed: int  # of those, rows with status failed
    lost_tasks: int  # tasks lost with their worker
    elapsed_s: float
    workers: int  # worker threads (0: in this process)

    @property
    def cases_per_second(self):
        return self.ran / self.elapsed_s if self.elapsed_s > 0 else float("nan")


def default_batch_size(pending, threads):
    """About 8 batches per worker thread, at most MAX_BATCH cases each: small enough that the
    load spreads and a lost worker costs little, large enough that the overhead of a task
    (about a millisecond, docs/benchmarks.md) is small against a case (tens of milliseconds)."""
    return max(1, min(MAX_BATCH, pending // (8 * max(threads, 1))))


def batches(cases, size):
    return [tuple(cases[i:i + size]) for i in range(0, len(cases), size)]


class _Progress:
    def __init__(self, spec, done, enabled):
        from tqdm import tqdm

        self.bar = tqdm(total=spec.cases, initial=done, unit="case", desc=spec.name,
                        disable=not enabled, smoothing=0.05, mininterval=0.5, dynamic_ncols=True)

    def update(self, count, failed):
        self.bar.update(count)
        if failed:
            self.bar.set_postfix(failed=failed, refresh=False)

    def note(self, text):
        if not self.bar.disable:
            self.bar.write(text)

    def close(self):
        self.bar.close()


def local_client(workers):
    """A Client of a LocalCluster of `workers` single-thread processes (default: the cores)."""
    import dask
    from distributed import Client, LocalCluster

    with dask.config.set({"distributed.scheduler.allowed-failures": 0,
                          "distributed.scheduler.worker-saturation": 1.0}):
        cluster = LocalCluster(n_workers=workers or os.cpu_count(), threads_per_worker=1,
                               processes=True, dashboard_address=None,
                               silence_logs=logging.CRITICAL)
    return Client(cluster), cluster


class _Runner:
    def __init__(self, spec, results, progress, batch_runner):
        self.spec, self.results, self.progress = spec, results, progress
        self.batch_runner = batch_runner or run_batch
        self.ran = self.failed = self.lost = 0
        self.losses = collections.Counter()  # tasks of a case lost with their worker

    def record(self, rows):
        for row in rows:  # attempts: the runs in the task plus the tasks lost before
            row["attempts"] += self.losses[row["case"]]
        written = self.results.write(rows)
        failed = sum(row["status"] == "failed" for row in rows)
        self.ran += written
        self.failed += failed
        self.progress.update(written, self.failed)

    def serial(self, pending, size):
        for batch in batches(pending, size):
            self.record(self.batch_runner(self.spec, list(batch)))

    def dask(self, client, pending, size):
        from distributed import as_completed

        threads = sum(client.nthreads().values()) or 1
        queue = collections.deque(batches(pending, size))
        in_flight = {}
        completed = as_completed(with_results=False)

        def fill():
            while queue and len(in_flight) < max(8, 4 * threads):
                batch = queue.popleft()
                future = client.submit(self.batch_runner, self.spec, list(batch), pure=False)
                in_flight[future.key] = batch
                completed.add(future)

        fill()
        for future in completed:
            batch = in_flight.pop(future.key)
            if future.status == "cancelled":  # the scheduler is gone, not the case's fault
                raise RuntimeError(f"{self.spec.name}: the scheduler cancelled the tasks (lost "
                                   "connection?); the finished rows are kept, run the command "
                                   "again to resume")
            try:
                rows = future.result()
            except Exception as error:  # noqa: BLE001 - a lost task; its cases run again
                self.lose(batch, error, queue)
            else:
                self.record(rows)
            future.release()
            fill()

    def lose(self, batch, error, queue):
        self.lost += 1
        kind = "worker_died" if type(error).__name__ == "KilledWorker" else type(error).__name__
        text = " ".join(f"{type(error).__name__}: {error}".split())[:400]
        self.progress.note(f"lost cases {batch[0]}..{batch[-1]} ({kind})")
        for case in batch:
            self.losses[case] += 1
        retry = []
        for case in batch:
            if self.losses[case] >= CASE_FAILURES:
                self.record([failed_row(self.spec, case, 0, kind, text)])
            else:
                retry.append((case,))
        queue.extendleft(reversed(retry))


def run_cases(spec, out, client=None, serial=False, batch_size=None, progress=True,
              batch_runner=None):
    """Runs the cases of `spec` that DIR/results.csv lacks; returns a CampaignRun."""
    results = ResultFile(out, spec)
    pending = [case for case in range(spec.cases) if case not in results.done]
    threads = 0 if serial else sum(client.nthreads().values())
    size = batch_size or spec.batch_size or default_batch_size(len(pending), threads)
    bar = _Progress(spec, len(results.done & set(range(spec.cases))), progress)
    runner = _Runner(spec, results, bar, batch_runner)
    started = time.perf_counter()
    try:
        if serial:
            runner.serial(pending, size)
        else:
            runner.dask(client, pending, size)
    finally:
        bar.close()
        results.close()
    return CampaignRun(results.path, spec.cases, results.recovered, runner.ran, runner.failed,
                       runner.lost, time.perf_counter() - started, threads)
