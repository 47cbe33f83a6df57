"""How a campaign spreads its cases: batches cut from the measured case time cover every case
once, hold at most about a second of work and shrink as the campaign ends; a cluster that would
have to start is used only when it pays for its start. The count of random cases is
SMOOTHSTEER_PROPERTY_CASES; a failure prints the seed and the inputs."""
import math

import numpy as np

from conftest import base_seed, property_cases
from smoothsteer.campaign.sizing import (BATCHES_PER_THREAD, TARGET_BATCH_S, guided_batch_size,
                                         use_cluster)


def cut(cases, threads, case_s):
    """The batch sizes of `cases` cut one after another, as the campaign sends them."""
    sizes, remaining = [], cases
    while remaining:
        sizes.append(guided_batch_size(remaining, threads, case_s))
        remaining -= sizes[-1]
    return sizes


def test_batches_cover_every_case_hold_a_bounded_work_and_shrink_to_the_end():
    seed = base_seed()
    rng = np.random.default_rng(seed)
    for case in range(property_cases()):
        cases = int(rng.integers(1, 20000))
        threads = int(rng.integers(1, 17))
        case_s = float(10 ** rng.uniform(-4, 1))
        sizes = cut(cases, threads, case_s)
        inputs = f"seed {seed}, case {case}: {cases} cases, {threads} threads, {case_s} s"
        assert sum(sizes) == cases and min(sizes) >= 1, inputs
        # About TARGET_BATCH_S of work, one case at least however long it takes.
        assert max(sizes) <= max(1, math.floor(TARGET_BATCH_S / case_s)), (inputs, sizes)
        assert sizes == sorted(sizes, reverse=True), (inputs, sizes)
        # Every thread gets several batches, so that the last ones even out the workers.
        assert len(sizes) >= min(cases, BATCHES_PER_THREAD * threads), (inputs, len(sizes))
        # The last batches are small: the workers end within a fraction of a batch.
        tail = sizes[-threads:]
        assert max(tail) <= max(1, math.ceil(sizes[0] / BATCHES_PER_THREAD)), (inputs, sizes)


def test_the_lane_change_campaign_cuts_batches_of_about_a_second():
    sizes = cut(3000, 2, 0.014)
    assert sizes[0] == int(TARGET_BATCH_S / 0.014)
    assert sizes[-1] == 1


def test_a_cluster_that_must_start_runs_only_large_campaigns():
    start_s = 3.0
    assert use_cluster(3000, 0.014, 2, start_s)
    assert not use_cluster(300, 0.014, 2, start_s)
    # Started already (its start paid), the same 300 cases go to its workers.
    assert use_cluster(300, 0.014, 2, 0.0)
    # One worker runs the cases one at a time, as this process does.
    assert not use_cluster(100000, 0.014, 1, 0.0)
    assert not use_cluster(1, 10.0, 2, 0.0)
