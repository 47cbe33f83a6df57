"""Campaigns on a LocalCluster give the rows of a serial run; a killed worker loses no case, a
case that kills its worker twice is written as failed, and a killed campaign resumes without
repeating a finished case."""
import json
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

from campaign_support import data_lines, fatal_batch, rows, slow_batch, write_spec
from conftest import ROOT, python_environment
from smoothsteer import campaign
from smoothsteer.campaign.cases import run_batch
from smoothsteer.campaign.results import ResultFile
from smoothsteer.campaign.cluster import local_client
from smoothsteer.campaign.spec_file import CampaignSpecError


@pytest.fixture(scope="module")
def client():
    client, cluster = local_client(2)
    yield client
    client.close()
    cluster.close()


def serial_rows(spec, out):
    campaign.run_campaign(spec, out, serial=True, progress=False)
    return rows(out)


def test_a_cluster_of_two_workers_gives_the_serial_rows(tmp_path, client):
    spec = write_spec(tmp_path, cases=24)
    # By the scheduler's address, as --scheduler tcp://host:8786 connects to a real cluster.
    run = campaign.run_campaign(spec, tmp_path / "cluster", scheduler=client.scheduler.address,
                                batch_size=3, progress=False)
    assert (run.ran, run.failed, run.lost_tasks, run.workers) == (24, 0, 0, 2)
    cluster = rows(tmp_path / "cluster")
    serial = serial_rows(spec, tmp_path / "serial")
    assert list(cluster["case"]) == list(range(24))
    assert cluster.equals(serial)
    assert set(serial["status"]) == {"ok"} and 0 < serial["passed"].sum() <= 24


def kill_one_worker_when(client, out, lines):
    """SIGKILLs a worker that is running a task once results.csv has `lines` rows."""
    pids = client.run(os.getpid)

    def kill():
        deadline = time.monotonic() + 60.0
        while data_lines(out) < lines and time.monotonic() < deadline:
            time.sleep(0.01)
        while time.monotonic() < deadline:
            busy = [address for address, keys in client.processing().items() if keys]
            if busy:
                os.kill(pids[busy[0]], signal.SIGKILL)
                return
            time.sleep(0.005)

    thread = threading.Thread(target=kill)
    thread.start()
    return thread


def test_a_killed_worker_still_yields_every_case_exactly_once(tmp_path, client):
    spec = write_spec(tmp_path, cases=40)
    out = tmp_path / "cluster"
    killer = kill_one_worker_when(client, out, lines=4)
    run = campaign.run_campaign(spec, out, client=client, batch_size=2, progress=False,
                                batch_runner=slow_batch)
    killer.join()
    assert run.lost_tasks >= 1 and run.failed == 0
    cluster = rows(out)
    assert list(cluster["case"]) == list(range(40))  # each case once, none missing
    assert cluster["attempts"].max() == 2  # the lost cases ran again, once
    serial = serial_rows(spec, tmp_path / "serial")
    assert cluster.drop(columns="attempts").equals(serial.drop(columns="attempts"))


def test_a_case_that_kills_its_worker_twice_is_written_as_failed(tmp_path, client):
    spec = write_spec(tmp_path, cases=12)
    out = tmp_path / "cluster"
    run = campaign.run_campaign(spec, out, client=client, batch_size=4, progress=False,
                                batch_runner=fatal_batch)
    table = rows(out)
    assert list(table["case"]) == list(range(12))
    failed = table[table["status"] == "failed"]
    assert list(failed["case"]) == [3] and run.failed == 1
    assert failed.iloc[0]["error_kind"] == "worker_died" and failed.iloc[0]["attempts"] == 2
    assert "KilledWorker" in failed.iloc[0]["error"]
    # Its sampled values and overrides are in the row, for the replay.
    spec_object = campaign.load_spec(spec)
    assert json.loads(failed.iloc[0]["overrides"]) == spec_object.case_overrides(3)
    # The other cases of its batch ran again one by one and passed through.
    assert set(table[table["case"].isin([0, 1, 2])]["attempts"]) == {2}


def test_a_killed_campaign_resumes_without_repeating_a_finished_case(tmp_path):
    spec = write_spec(tmp_path, cases=150, batch_size=5)
    out = tmp_path / "out"
    process = subprocess.Popen([sys.executable, "-m", "smoothsteer.campaign", str(spec), "--out",
                                str(out), "--serial", "--no-report", "--quiet"], cwd=ROOT,
                               env=python_environment())
    deadline = time.monotonic() + 60.0
    while data_lines(out) < 20 and time.monotonic() < deadline and process.poll() is None:
        time.sleep(0.005)
    process.send_signal(signal.SIGKILL)
    process.wait()
    before = rows(out)
    finished = set(before["case"])
    assert 20 <= len(finished) < 150, "the campaign ended before it could be killed"

    ran = []

    def counting_batch(spec_object, cases):
        ran.extend(cases)
        return run_batch(spec_object, cases)

    run = campaign.run_campaign(spec, out, serial=True, progress=False,
                                batch_runner=counting_batch)
    assert not finished & set(ran)
    assert sorted(ran) == sorted(set(range(150)) - finished)
    assert (run.recovered, run.ran) == (len(finished), 150 - len(finished))
    after = rows(out)
    assert list(after["case"]) == list(range(150))
    assert after[after["case"].isin(finished)].reset_index(drop=True).equals(before)
    # Nothing is left to run; more cases extend the campaign by the new ones only.
    assert campaign.run_campaign(spec, out, serial=True, progress=False).ran == 0
    ran.clear()
    campaign.run_campaign(write_spec(tmp_path, cases=160, batch_size=5), out, serial=True,
                          progress=False, batch_runner=counting_batch)
    assert sorted(ran) == list(range(150, 160))


def test_a_cut_last_row_is_dropped_and_its_case_runs_again(tmp_path):
    spec = campaign.load_spec(write_spec(tmp_path, cases=6))
    out = tmp_path / "out"
    campaign.run_campaign(spec, out, serial=True, progress=False)
    text = (out / "results.csv").read_text()
    cut = text[:text.rstrip("\n").rfind("\n") + 1] + text.rstrip("\n").rsplit("\n", 1)[1][:30]
    (out / "results.csv").write_text(cut)
    results = ResultFile(str(out), spec)
    results.close()
    assert len(results.done) == 5 and (out / "results.csv").read_text().endswith("\n")
    assert campaign.run_campaign(spec, out, serial=True, progress=False).ran == 1
    assert list(rows(out)["case"]) == list(range(6))


def test_a_directory_of_another_campaign_is_refused(tmp_path):
    out = tmp_path / "out"
    campaign.run_campaign(write_spec(tmp_path, cases=3), out, serial=True, progress=False)
    with pytest.raises(CampaignSpecError, match="holds the rows of another campaign"):
        campaign.run_campaign(write_spec(tmp_path, cases=3, seed=9), out, serial=True,
                              progress=False)
