"""The path's curvature samples and the rate-limited preview (docs/feedforward.md, section 2)
from Python: the preview is the midpoint of the samples' envelopes of slope 2 L_ff (C++ property
test: CurvaturePreview.IsTheRateEnvelopeOfTheSamplesAtEachPoint)."""
import math

import numpy as np
import pytest

import smoothsteer as ss


def envelope_midpoint(samples, index, slope, bound):
    """The definition at one sample index, from the sample array (inside the path only)."""
    clamped = np.clip(samples, -bound, bound)
    distance = slope * np.abs(np.arange(len(samples)) - index)
    upper = np.min(clamped + distance)
    lower = np.max(clamped - distance)
    return 0.5 * (upper + lower)


def test_curvature_samples_match_the_path():
    path = ss.PathBuilder((0.0, 0.0), 0.0).line(10.0).arc(20.0, 1.0).line(10.0).build()
    samples = path.curvature_samples
    spacing = path.curvature_sample_spacing_m
    assert len(samples) == int(np.ceil(path.length_m / spacing)) + 1
    assert path.curvature_sample(5) == samples[5]
    assert path.curvature_sample(-1) == 0.0  # the straight extension before an open path
    assert abs(samples[int(20.0 / spacing)] - 1.0 / 20.0) < 1e-9  # on the arc
    assert path.sampled_curvature(20.0) == samples[int(round(20.0 / spacing))]


def test_preview_is_the_envelope_midpoint_of_the_samples():
    rng = np.random.default_rng(20240607)
    for case in range(100):
        radius = rng.uniform(5.0, 40.0)
        path = (ss.PathBuilder((0.0, 0.0), 0.0).line(rng.uniform(60.0, 80.0))
                .arc(radius, rng.uniform(0.5, 1.5)).line(rng.uniform(60.0, 80.0)).build())
        spacing = path.curvature_sample_spacing_m
        bound = rng.uniform(0.5, 1.5) / radius
        rate = rng.uniform(0.2, 5.0) * bound / 20.0   # reaches of 4-100 samples
        s = rng.uniform(40.0, path.length_m - 40.0)   # the window stays inside the path
        step = rng.uniform(0.1, 2.0)
        before, at, after = ss.preview_curvature(path, s, step, rate, bound)
        centre = int(np.floor(s / spacing + 0.5))
        offset = max(1, int(np.floor(step / spacing + 0.5)))
        slope = 2.0 * rate * spacing
        samples = path.curvature_samples
        message = f"case {case}: s={s} step={step} rate={rate} bound={bound}"
        assert before == envelope_midpoint(samples, centre - offset, slope, bound), message
        assert at == envelope_midpoint(samples, centre, slope, bound), message
        assert after == envelope_midpoint(samples, centre + offset, slope, bound), message


def test_preview_without_a_rate_reads_the_three_samples():
    path = ss.PathBuilder((0.0, 0.0), 0.0).line(10.0).arc(20.0, 1.0).line(10.0).build()
    before, at, after = ss.preview_curvature(path, 10.2, 0.5, 0.0, 1.0)
    spacing = path.curvature_sample_spacing_m
    centre = int(np.floor(10.2 / spacing + 0.5))
    assert (before, at, after) == (path.curvature_sample(centre - 1), path.curvature_sample(centre),
                                   path.curvature_sample(centre + 1))


@pytest.mark.parametrize("arguments, name", [
    ((math.nan, 0.5, 0.01, 0.1), "arc_length_m"),
    ((1e300, 0.5, 0.01, 0.1), "arc_length_m"),
    ((10.0, 0.0, 0.01, 0.1), "step_m"),
    ((10.0, 1e15, 0.01, 0.1), "step_m"),
    ((10.0, 0.5, math.nan, 0.1), "rate_per_meter"),
    ((10.0, 0.5, -1.0, 0.1), "rate_per_meter"),
    ((10.0, 0.5, 0.01, math.inf), "bound"),
    ((10.0, 0.5, 0.01, 0.0), "bound"),
])
def test_preview_rejects_bad_arguments_by_name(arguments, name):
    path = ss.Path.straight_line((0.0, 0.0), 0.0, 50.0)
    with pytest.raises(ValueError, match=f"preview_curvature: {name} = "):
        ss.preview_curvature(path, *arguments)
