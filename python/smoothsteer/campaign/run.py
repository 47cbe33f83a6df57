"""Running a campaign's cases (docs/campaigns.md): in this process, or on Dask (a LocalCluster
on the machine's cores, or a scheduler's workers), in batches, each batch's rows appended to
results.csv as it finishes.

On Dask, a few cases run in this process first to measure a case's time; the batches are then
cut from it (sizing.py), and a LocalCluster that is not running yet is started only if the
cluster is estimated to pay for its start; otherwise the cases run in this process.

A batch whose worker dies is lost as a whole (its rows come back only at its end). Its cases are
sent again one per task; a case whose task is lost twice is written as failed (error_kind
`worker_died`) with the last error, so no case is dropped. The LocalCluster counts every loss
here (cluster.py). An external scheduler retries a task itself first (its
`distributed.scheduler.allowed-failures`, 3 by default) and may queue tasks on a worker."""
import collections
import time
from dataclasses import dataclass

from .cases import failed_row, run_batch
from .cluster import LocalCampaignCluster
from .results import ResultFile
from .sizing import CLUSTER_START_S_PER_WORKER, PROBE_CASES, guided_batch_size, use_cluster

CASE_FAILURES = 2  # losses of a case before it is written as failed
# Rows of a run in this process are flushed at least every this many cases.
MAX_SERIAL_BATCH = 32
# Tasks submitted per worker thread: the one it runs and the next, waiting at the scheduler.
TASKS_PER_THREAD = 2


@dataclass
class CampaignRun:
    """What one call of run_campaign did."""

    results: str  # path of results.csv
    cases: int  # the campaign's cases
    recovered: int  # rows already in results.csv
    ran: int  # cases run by this call
    failed: int  # of those, rows with status failed
    lost_tasks: int  # tasks lost with their worker
    elapsed_s: float  # the cluster's start included, if this call started it
    workers: int  # worker threads (0: in this process)
    cluster_start_s: float = 0.0  # the start of a LocalCluster by this call
    case_s: float = float("nan")  # a case's time measured before the cases were spread

    @property
    def cases_per_second(self):
        return self.ran / self.elapsed_s if self.elapsed_s > 0 else float("nan")


def serial_batch_size(pending):
    """About 8 batches, at most MAX_SERIAL_BATCH cases each: a kill loses few rows."""
    return max(1, min(MAX_SERIAL_BATCH, pending // 8))


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

    def dask(self, client, pending, size, case_s):
        """The cases on the client's workers: batches of `size` cases, else cut as they are
        sent from the remaining cases and `case_s`; lost batches are sent again first."""
        from distributed import as_completed

        threads = sum(client.nthreads().values()) or 1
        fresh = collections.deque(pending)
        retries = collections.deque()
        in_flight = {}
        completed = as_completed(with_results=False)

        def next_batch():
            if retries:
                return retries.popleft()
            count = size or guided_batch_size(len(fresh), threads, case_s)
            return tuple(fresh.popleft() for _ in range(min(count, len(fresh))))

        def fill():
            while (retries or fresh) and len(in_flight) < TASKS_PER_THREAD * threads:
                batch = next_batch()
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
                self.lose(batch, error, retries)
            else:
                self.record(rows)
            future.release()
            fill()

    def probe(self, pending):
        """Runs the first cases here; returns a case's mean wall time."""
        cases = pending[:PROBE_CASES]
        started = time.perf_counter()
        self.serial(cases, len(cases))
        return (time.perf_counter() - started) / max(len(cases), 1)

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
    """Runs the cases of `spec` that DIR/results.csv lacks; returns a CampaignRun. client: a
    distributed.Client, or a LocalCampaignCluster (started here if the cluster pays)."""
    results = ResultFile(out, spec)
    pending = [case for case in range(spec.cases) if case not in results.done]
    size = batch_size or spec.batch_size
    bar = _Progress(spec, len(results.done & set(range(spec.cases))), progress)
    runner = _Runner(spec, results, bar, batch_runner)
    local = client if isinstance(client, LocalCampaignCluster) else None
    threads, case_s, start_s = 0, float("nan"), 0.0
    started = time.perf_counter()
    try:
        if not serial and pending and (size is None or (local and not local.started)):
            case_s = runner.probe(pending)
            pending = pending[PROBE_CASES:]
        if local and not local.started and not use_cluster(
                len(pending), case_s, local.workers, CLUSTER_START_S_PER_WORKER * local.workers):
            serial = True
            bar.note(f"{spec.name}: {len(pending)} cases of {1e3 * case_s:.0f} ms run in this "
                     f"process; starting {local.workers} workers would not pay")
        if serial or not pending:
            runner.serial(pending, size or serial_batch_size(len(pending)))
        else:
            if local:
                was_started = local.started
                client = local.client
                start_s = 0.0 if was_started else local.start_s
            threads = sum(client.nthreads().values())
            runner.dask(client, pending, size, case_s)
    finally:
        bar.close()
        results.close()
    return CampaignRun(results.path, spec.cases, results.recovered, runner.ran, runner.failed,
                       runner.lost, time.perf_counter() - started, threads, start_s, case_s)
