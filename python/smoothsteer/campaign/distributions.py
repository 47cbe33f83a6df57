"""The distributions a campaign samples scenario keys from (docs/campaigns.md): uniform,
log_uniform, normal (optionally truncated to [low, high]), integer and choice, each optionally
rounded to a multiple of `step` (a dead time must be a multiple of the plant sub-step).

A case's value of a key depends only on (campaign seed, case index, key): its generator is
numpy's PCG64 seeded by the SeedSequence of those three, so rows do not depend on the order in
which cases run, and adding a variable leaves the others' samples as they were."""
import math
import zlib
from statistics import NormalDist

import numpy as np

KINDS = ("uniform", "log_uniform", "normal", "integer", "choice")
# The normal's range checked against the scenario's rules when it is not truncated: a draw
# beyond 6 standard deviations has probability 2e-9.
NORMAL_CHECK_SIGMAS = 6.0
# Values of one choice: each is checked by a load of the scenario before any case runs (about
# 1.5 ms each), and the report counts each.
MAX_CHOICE_VALUES = 1000
# Most multiples of `step` in a variable's range of magnitudes: draw / step stays an exact
# float and its rounding cannot overflow.
MAX_STEPS = 1e15


def case_generator(seed, case, key):
    """The generator of one key in one case (the key enters as its CRC-32)."""
    return np.random.default_rng([seed, case, zlib.crc32(key.encode("utf-8"))])


class Variable:
    """One sampled scenario key."""

    def __init__(self, node):
        self.key = node.key.split(".", 1)[1]  # without 'variables.'
        self.node = node
        self.raw = node.value  # as written, for the campaign's identity
        known = {"uniform": ("low", "high", "step"), "log_uniform": ("low", "high", "step"),
                 "normal": ("mean", "std", "low", "high", "step"), "integer": ("low", "high"),
                 "choice": ("values", "weights")}
        node.mapping(None, required=("distribution",))
        self.kind = node.child("distribution").value
        if self.kind not in KINDS:
            node.child("distribution").fail(f"unknown distribution {self.kind!r} (known: "
                                            f"{', '.join(KINDS)})")
        node.mapping(("distribution",) + known[self.kind],
                     required={"uniform": ("low", "high"), "log_uniform": ("low", "high"),
                               "normal": ("mean", "std"), "integer": ("low", "high"),
                               "choice": ("values",)}[self.kind])
        getattr(self, "_parse_" + self.kind)(node)

    def _bounds(self, node, positive=False):
        self.low = node.child("low").number()
        self.high = node.child("high").number()
        if not self.low <= self.high:
            node.child("high").fail(f"value {self.high!r} must be >= low = {self.low!r}")
        if positive and not self.low > 0:
            node.child("low").fail(f"value {self.low!r} must be > 0 (a log-uniform range)")

    def _parse_step(self, node):
        self.step = node.child("step").number(0.0, rule="must be > 0") if "step" in node.value \
            else None
        if self.step == 0.0:
            node.child("step").fail("value 0 must be > 0")
        if self.step:
            ends = [getattr(self, name, None) for name in ("low", "high", "mean")]
            magnitude = max(abs(v) for v in ends if v is not None) + \
                NORMAL_CHECK_SIGMAS * getattr(self, "std", 0.0)
            if magnitude / self.step > MAX_STEPS:
                node.child("step").fail(f"value {self.step!r} is too small for the range: at "
                                        f"most {MAX_STEPS:g} steps up to {magnitude:g}")
        for name in ("low", "high"):
            value = getattr(self, name, None)
            if self.step and value is not None and self._round(value) != value:
                node.child(name).fail(f"value {value!r} must be a multiple of step = {self.step!r}")

    def _parse_uniform(self, node):
        self._bounds(node)
        self._parse_step(node)

    def _parse_log_uniform(self, node):
        self._bounds(node, positive=True)
        self._parse_step(node)

    def _parse_normal(self, node):
        self.mean = node.child("mean").number()
        self.std = node.child("std").number(0.0, rule="must be >= 0")
        self.low = node.child("low").number() if "low" in node.value else None
        self.high = node.child("high").number() if "high" in node.value else None
        for name, inside in (("low", lambda v: v <= self.mean), ("high", lambda v: v >= self.mean)):
            value = getattr(self, name)
            if value is not None and not inside(value):
                node.child(name).fail(f"value {value!r} must lie on its side of mean = "
                                      f"{self.mean!r}")
        self._parse_step(node)

    def _parse_integer(self, node):
        self.low = node.child("low").integer(-2**62, 2**62)
        self.high = node.child("high").integer(self.low, 2**62)
        self.step = None

    def _parse_choice(self, node):
        values = node.child("values")
        self.values = [item.value for item in values.items(most=MAX_CHOICE_VALUES)]
        if not self.values:
            values.fail("must list at least one value")
        self.weights = None
        if "weights" in node.value:
            weights = node.child("weights")
            self.weights = [item.number(0.0, rule="must be >= 0") for item in weights.items()]
            if len(self.weights) != len(self.values) or not sum(self.weights) > 0:
                weights.fail(f"must give one weight >= 0 per value ({len(self.values)}), not all 0")
            total = sum(self.weights)
            self.weights = [w / total for w in self.weights]
        self.step = None

    def _round(self, value):
        # 12 significant digits drop the binary noise of k * step (9 * 0.001 = 0.009000000000000001)
        return float(f"{round(value / self.step) * self.step:.12g}")

    def sample(self, seed, case):
        rng = case_generator(seed, case, self.key)
        if self.kind == "choice":
            return self.values[int(rng.choice(len(self.values), p=self.weights))]
        if self.kind == "integer":
            return int(rng.integers(self.low, self.high, endpoint=True))
        if self.kind == "uniform":
            value = float(rng.uniform(self.low, self.high))
        elif self.kind == "log_uniform":
            value = math.exp(rng.uniform(math.log(self.low), math.log(self.high)))
        elif self.low is None and self.high is None:
            value = float(rng.normal(self.mean, self.std))
        else:  # the truncated normal by its inverse CDF
            value = self._truncated_normal(rng)
        if self.step:
            value = self._round(value)
        if self.kind != "normal" or self.low is not None:
            value = max(value, self.low)
        if self.kind != "normal" or self.high is not None:
            value = min(value, self.high)
        return value

    def _truncated_normal(self, rng):
        if self.std == 0.0:
            return self.mean
        normal = NormalDist(self.mean, self.std)
        low = normal.cdf(self.low) if self.low is not None else 0.0
        high = normal.cdf(self.high) if self.high is not None else 1.0
        u = min(max(float(rng.uniform(low, high)), 1e-300), 1.0 - 1e-16)
        return normal.inv_cdf(u)

    def checkpoints(self):
        """(key of the spec, value, note): the values the scenario's own rules must accept."""
        node = self.node
        if self.kind == "choice":
            return [(node.child("values").child(i), v, "") for i, v in enumerate(self.values)]
        if self.kind == "normal":
            points = []
            for name, sign in (("low", -1.0), ("high", 1.0)):
                value = getattr(self, name)
                if value is None:
                    value = self.mean + sign * NORMAL_CHECK_SIGMAS * self.std
                    points.append((node.child("std"), value,
                                   f" (mean {'-+'[sign > 0]} 6 std; give low and high to "
                                   "truncate the normal)"))
                else:
                    points.append((node.child(name), value, ""))
            return points
        return [(node.child("low"), self.low, ""), (node.child("high"), self.high, "")]

    def describe(self):
        step = f", step {self.step:g}" if self.step else ""
        if self.kind == "choice":
            weights = f", weights {', '.join(f'{w:.3g}' for w in self.weights)}" \
                if self.weights else ""
            return f"choice of {', '.join(map(str, self.values))}{weights}"
        if self.kind == "normal":
            bounds = ""
            if self.low is not None or self.high is not None:
                bounds = f", truncated to [{self.low if self.low is not None else '-inf'}, " \
                         f"{self.high if self.high is not None else 'inf'}]"
            return f"normal, mean {self.mean:g}, std {self.std:g}{bounds}{step}"
        if self.kind == "integer":
            return f"integer in [{self.low}, {self.high}]"
        return f"{self.kind.replace('_', '-')} in [{self.low:g}, {self.high:g}]{step}"
