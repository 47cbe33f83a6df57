"""A LocalCampaignCluster is started only by a campaign that pays for its start, and then kept:
campaigns run one after another on the same worker processes, with batches cut from the
measured case time, and give the rows of a serial run."""
import os

from campaign_support import rows, write_spec
from smoothsteer import campaign
from smoothsteer.campaign.sizing import PROBE_CASES


def test_a_small_campaign_runs_here_and_leaves_the_cluster_unstarted(tmp_path):
    spec = write_spec(tmp_path, cases=12)
    with campaign.LocalCampaignCluster(workers=2) as cluster:
        run = campaign.run_campaign(spec, tmp_path / "small", client=cluster, progress=False)
        assert not cluster.started
    assert (run.ran, run.failed, run.workers, run.cluster_start_s) == (12, 0, 0, 0.0)
    assert run.case_s > 0
    assert list(rows(tmp_path / "small")["case"]) == list(range(12))


def test_a_kept_cluster_runs_campaigns_one_after_another_on_the_same_workers(tmp_path):
    spec = write_spec(tmp_path, cases=40)
    serial = tmp_path / "serial"
    campaign.run_campaign(spec, serial, serial=True, progress=False)
    with campaign.LocalCampaignCluster(workers=2) as cluster:
        pids = set(cluster.client.run(os.getpid).values())
        start_s = cluster.start_s
        runs = [campaign.run_campaign(spec, tmp_path / name, client=cluster, progress=False)
                for name in ("first", "second")]
        assert set(cluster.client.run(os.getpid).values()) == pids
        assert cluster.start_s == start_s
    assert len(pids) == 2 and not cluster.started
    for name, run in zip(("first", "second"), runs):
        assert (run.ran, run.failed, run.lost_tasks, run.workers) == (40, 0, 0, 2)
        assert run.cluster_start_s == 0.0 and run.case_s > 0
        assert rows(tmp_path / name).equals(rows(serial))


def test_the_probe_cases_run_here_and_the_rest_on_the_workers(tmp_path):
    spec = write_spec(tmp_path, cases=30)
    ran_here = []

    def counting_batch(spec_object, cases):
        if os.getpid() == here:
            ran_here.extend(cases)
        from smoothsteer.campaign.cases import run_batch
        return run_batch(spec_object, cases)

    here = os.getpid()
    with campaign.LocalCampaignCluster(workers=2) as cluster:
        cluster.client  # started before the campaign: no decision to make
        run = campaign.run_campaign(spec, tmp_path / "out", client=cluster, progress=False,
                                    batch_runner=counting_batch)
    assert ran_here == list(range(PROBE_CASES))
    assert (run.ran, run.workers) == (30, 2)
