"""How a campaign spreads its cases (docs/campaigns.md): cases per batch from the measured time
of a case, and whether a cluster pays for itself against running the cases in this process.

Figures from docs/benchmarks.md ("Validation campaigns on Dask"), on a 2-core machine: a task
costs about 10 ms of round trips (scheduler and worker), a LocalCluster of 2 workers takes about
3 s to start, a case of the lane-change campaign 10-50 ms."""
import math

# Work per batch: a task's round trips stay about 1 % of it, and a lost worker loses at most
# this much work.
TARGET_BATCH_S = 1.0
# Batches of the remaining cases per worker thread when they are cut: the batches shrink as the
# campaign ends (guided self-scheduling), so that the workers finish within one small batch of
# each other instead of one waiting for another's last full batch.
BATCHES_PER_THREAD = 4
# Cases run in this process to measure a case's time before the cases are spread.
PROBE_CASES = 3
# What a LocalCluster's start costs, per worker process (each imports distributed, numpy and
# smoothsteer), when run_campaign would have to start one.
CLUSTER_START_S_PER_WORKER = 1.5
# Round trips of one task, client to scheduler to worker and back.
TASK_OVERHEAD_S = 0.01
# The cluster must be estimated this much faster than this process, so that the estimate's
# error (the machine's load, the probe's few cases) does not make a campaign slower.
REQUIRED_GAIN = 1.2


def guided_batch_size(remaining, threads, case_s, largest=None):
    """Cases of the next batch: the remaining cases over BATCHES_PER_THREAD per thread, at most
    TARGET_BATCH_S of work (and at most `largest`), at least one case."""
    share = math.ceil(remaining / (BATCHES_PER_THREAD * max(threads, 1)))
    cap = max(1, int(TARGET_BATCH_S / case_s)) if case_s > 0 else share
    if largest is not None:
        cap = min(cap, largest)
    return max(1, min(share, cap, remaining))


def cluster_time_s(cases, case_s, workers, start_s):
    """Estimated wall time of `cases` on `workers` single-thread workers, start included: each
    worker's share of the cases (whole cases), its task round trips, and a last batch as the
    tail."""
    threads = max(workers, 1)
    work = math.ceil(cases / threads) * case_s
    tasks = cases / guided_batch_size(cases, threads, case_s)
    return start_s + work + TASK_OVERHEAD_S * tasks / threads + min(TARGET_BATCH_S,
                                                                    cases * case_s) / threads


def use_cluster(cases, case_s, workers, start_s):
    """True if starting `workers` workers (`start_s`) and running the cases on them is estimated
    at least REQUIRED_GAIN times faster than running them in this process. One worker never is:
    it runs the cases one at a time, as this process would, after its start."""
    if workers < 2:
        return False
    return REQUIRED_GAIN * cluster_time_s(cases, case_s, workers, start_s) < cases * case_s
