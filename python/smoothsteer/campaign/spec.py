"""A campaign spec (docs/campaigns.md): a base scenario, distributions for scenario keys, the
number of cases, a seed, the metrics to record and the criteria a case must pass.

load_spec() checks everything before any case runs: the spec's own keys (spec_file), then
the scenario's rules, by loading the base scenario through the scenario loader with the fixed
overrides and each end of every variable's range applied as `--set` applies them. The first
rejection names the spec's key and quotes the loader's message."""
import hashlib
import json
import os

from .. import ConfigError
from .. import load_scenario, run_scenario
from .distributions import Variable
from .spec_file import CampaignSpecError, read

KEYS = ("name", "description", "base", "cases", "seed", "batch_size", "overrides", "variables",
        "metrics", "criteria", "report")
# Cases of one campaign: 10^6 rows of results.csv are about 300 MB and 12 hours at 24 cases/s
# (docs/campaigns.md); the pending cases and the report's table fit in memory.
MAX_CASES = 10**6
# Sums of summary.json's counts, as the comparison study's columns (docs/metrics.md).
DERIVED_METRICS = {
    "held_above_limits": ("angle_violations", "held_rate_violations",
                          "held_acceleration_violations"),
    "actual_above_limits": ("actual_rate_violations", "actual_acceleration_violations"),
}
DEFAULT_METRICS = ("max_abs_rear_error_m", "rms_rear_error_m", "final_abs_rear_error_m",
                   "reached", "reaching_time_s", "held_rate_max_radps",
                   "held_acceleration_max_radps2", "held_above_limits", "max_abs_side_slip_rad")


def display_path(path):
    """A path relative to the working directory when it lies below it (the repository root)."""
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative


class Criterion:
    """metric <= max and/or metric >= min."""

    def __init__(self, node):
        self.metric = node.key.split(".", 1)[1]
        node.mapping(("max", "min"))
        if not node.value:
            node.fail("must give max, min or both")
        self.max = node.child("max").number() if "max" in node.value else None
        self.min = node.child("min").number() if "min" in node.value else None
        if self.max is not None and self.min is not None and self.min > self.max:
            node.child("min").fail(f"value {self.min!r} must be <= max = {self.max!r}")

    def holds(self, value):
        return (self.max is None or value <= self.max) and (self.min is None or value >= self.min)

    def describe(self):
        parts = [f"{self.metric} >= {self.min:g}"] if self.min is not None else []
        if self.max is not None:
            parts.append(f"{self.metric} <= {self.max:g}")
        return " and ".join(parts)


class CampaignSpec:
    """A checked campaign spec; plain data, sent to the workers with every batch."""

    def __init__(self, file):
        root = read(file)
        root.mapping(KEYS, required=("base", "cases", "seed", "variables"))
        spec = root.value
        self.file = os.path.abspath(file)
        self.name = root.child("name").text() if "name" in spec else \
            os.path.splitext(os.path.basename(file))[0]
        self.description = root.child("description").text() if "description" in spec else ""
        base = root.child("base")
        self.base = os.path.normpath(os.path.join(os.path.dirname(self.file), base.text()))
        if not os.path.isfile(self.base):
            base.fail(f"no scenario file {self.base}")
        self.cases = root.child("cases").integer(1, MAX_CASES)
        self.seed = root.child("seed").integer(0, 2**63 - 1)
        self.batch_size = root.child("batch_size").integer(1, 10000) if "batch_size" in spec \
            else None
        self.overrides = {}
        if "overrides" in spec:
            node = root.child("overrides")
            for key in node.mapping(None):
                self.overrides[key] = node.child(key).value
        variables = root.child("variables")
        if not variables.mapping(None):
            variables.fail("must give at least one variable")
        self.variables = [Variable(variables.child(key)) for key in variables.value]
        for variable in self.variables:
            if variable.key in self.overrides:
                variable.node.fail("is also fixed under 'overrides'")
        self._check_against_scenario(root)
        known = self._metric_names(root)
        self.criteria = []
        if "criteria" in spec:
            node = root.child("criteria")
            self.criteria = [Criterion(node.child(key)) for key in node.mapping(known)]
        metrics = [m.text() for m in root.child("metrics").items()] if "metrics" in spec \
            else list(DEFAULT_METRICS)
        if not metrics:
            root.child("metrics").fail("must list at least one metric")
        for index, name in enumerate(metrics):
            if name not in known:
                root.child("metrics").child(index).fail(
                    f"unknown metric {name!r} (summary.json's metrics, docs/metrics.md, and "
                    f"{', '.join(DERIVED_METRICS)})")
        self.metrics = list(dict.fromkeys(metrics + [c.metric for c in self.criteria]))
        self._report(root)
        for variable in self.variables:
            variable.node = None  # the spec's tree stays on the client

    def _report(self, root):
        self.primary_metric = self.criteria[0].metric if self.criteria else self.metrics[0]
        self.worst_cases = 5
        if "report" in root.value:
            node = root.child("report")
            node.mapping(("primary_metric", "worst_cases"))
            if "primary_metric" in node.value:
                self.primary_metric = node.child("primary_metric").text()
                if self.primary_metric not in self.metrics:
                    node.child("primary_metric").fail(
                        f"{self.primary_metric!r} is not among the recorded metrics "
                        f"({', '.join(self.metrics)})")
            if "worst_cases" in node.value:
                self.worst_cases = node.child("worst_cases").integer(1, 100)

    def _check_against_scenario(self, root):
        """The scenario loader's own rules on the fixed overrides and each variable's range."""
        def load(node, overrides, note=""):
            try:
                load_scenario(display_path(self.base), overrides)
            except ConfigError as error:
                node.fail(f"the scenario rejects it{note}: {error}")

        load(root.child("overrides") if self.overrides else root.child("base"), self.overrides)
        for variable in self.variables:
            for node, value, note in variable.checkpoints():
                load(node, dict(self.overrides, **{variable.key: value}),
                     f" ({variable.key} = {value!r}{note})")
        for end in (0, 1):  # rules between keys: every variable at its low, then its high end
            overrides = dict(self.overrides)
            for variable in self.variables:
                overrides[variable.key] = variable.checkpoints()[-end][1]
            load(root.child("variables"), overrides,
                 f" with every variable at its {('low', 'high')[end]} end")

    def _metric_names(self, root):
        """summary.json's metric names, from a run of the base scenario's first 0.1 s."""
        try:
            _, summary = run_scenario(self.base, dict(self.overrides, **{
                "simulation.duration_s": 0.1}))
        except Exception as error:  # noqa: BLE001 - any failure of the base is the spec's
            root.child("base").fail(f"the base scenario does not run: {error}")
        return set(summary["metrics"]) | set(DERIVED_METRICS)

    def case_overrides(self, case):
        """The overrides of one case, fixed ones first, as `--set` applies them."""
        overrides = dict(self.overrides)
        for variable in self.variables:
            overrides[variable.key] = variable.sample(self.seed, case)
        return overrides

    def identity(self):
        """What the rows depend on: a results directory refuses a spec with another identity.
        The number of cases is not part of it (a campaign can be extended)."""
        with open(self.base, "rb") as handle:
            base_hash = hashlib.sha256(handle.read()).hexdigest()
        content = {"base": self.base, "base_sha256": base_hash, "seed": self.seed,
                   "overrides": self.overrides, "metrics": self.metrics,
                   "criteria": [(c.metric, c.min, c.max) for c in self.criteria],
                   "variables": [(v.key, v.raw) for v in self.variables]}
        return hashlib.sha256(json.dumps(content, sort_keys=True, default=str).encode()).hexdigest()


def load_spec(file):
    """Loads and checks a campaign spec; raises CampaignSpecError naming the key."""
    return CampaignSpec(file)


__all__ = ["CampaignSpec", "CampaignSpecError", "Criterion", "load_spec"]
