"""The LocalCluster a campaign runs on (docs/campaigns.md): single-thread worker processes under
nannies, started when first needed and kept until closed, so that campaigns run one after
another from Python pay the start once.

The scheduler has `allowed-failures` 0, so that every task lost with its worker is counted by
the campaign (run.py), and `worker-saturation` 1, so that a worker holds only the task it runs
and its death costs no queued task a loss; the campaign keeps the next task waiting at the
scheduler instead, so that a worker gets it within one round trip.

Dask's periodic housekeeping is slowed down or off: on 2 cores, the default event-loop health
check every 20 ms, memory check every 100 ms, system monitor every 500 ms and work stealing every
100 ms took 9.5 % of a core with the cluster idle (3.4 % the client, scheduler and nannies, 3 %
each worker), and the statistical profiler samples a busy worker every 10 ms. A campaign needs
none of them: its tasks are queued at the scheduler (nothing to steal) and return small rows."""
import logging
import os
import time

CLUSTER_CONFIG = {"distributed.scheduler.allowed-failures": 0,
                  "distributed.scheduler.worker-saturation": 1.0,
                  "distributed.scheduler.work-stealing": False,
                  "distributed.worker.profile.enabled": False,
                  "distributed.admin.tick.interval": "1s",
                  "distributed.worker.memory.monitor-interval": "1s",
                  "distributed.admin.system-monitor.interval": "5s"}


def local_client(workers):
    """A Client of a LocalCluster of `workers` single-thread processes (default: the cores),
    each of which has imported smoothsteer (part of the start, not of the first batch)."""
    import importlib

    import dask
    from distributed import Client, LocalCluster

    with dask.config.set(CLUSTER_CONFIG):
        cluster = LocalCluster(n_workers=workers or os.cpu_count(), threads_per_worker=1,
                               processes=True, dashboard_address=None,
                               silence_logs=logging.CRITICAL)
    client = Client(cluster)
    client.run(importlib.import_module, "smoothsteer.campaign.cases")
    return client, cluster


class LocalCampaignCluster:
    """A LocalCluster of `workers` processes (default: the cores) for run_campaign(client=...),
    started at its first campaign that pays for it (or by `client`) and kept until close() or
    the end of a `with` block.

        with campaign.LocalCampaignCluster(workers=2) as cluster:
            campaign.run_campaign("a.yaml", "out/a", client=cluster)
            campaign.run_campaign("b.yaml", "out/b", client=cluster)  # no second start
    """

    def __init__(self, workers=None):
        self.workers = workers or os.cpu_count()
        self.start_s = None  # how long the start took, once started
        self._client = self._cluster = None

    @property
    def started(self):
        return self._client is not None

    @property
    def client(self):
        """The distributed.Client, the cluster started first if it is not running."""
        if self._client is None:
            started = time.perf_counter()
            self._client, self._cluster = local_client(self.workers)
            self.start_s = time.perf_counter() - started
        return self._client

    def close(self):
        if self._client is not None:
            self._client.close()
            self._cluster.close()
            self._client = self._cluster = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
