"""One case of a campaign and a batch of them: what a worker runs (docs/campaigns.md).

A case is the base scenario with the spec's fixed overrides and the case's samples applied as
`--set` applies them, run by run_scenario() (which releases the GIL). The base scenario's
files are parsed once per process (load_scenario(reuse_files=True)). Its row holds the case
index, the seed, the sampled values, the recorded metrics, whether it passed the criteria, and
the overrides as JSON, from which the report writes the command that replays it."""
import json
import math
import time

from .. import load_scenario, run_scenario
from .spec import DERIVED_METRICS

# The run reached the end of its path or its duration; anything else is a failure of the case.
COMPLETED_STOPS = ("path_end", "duration")
MAX_ERROR_CHARS = 400
# Parse the base scenario's files once per process; False: read them for every case as
# run_scenario(file) does (the benchmark's and the tests' comparison, the same rows).
REUSE_BASE_FILES = True


def columns(spec):
    """The CSV columns, in order; elapsed_s is the only one that differs between two runs."""
    return (["case", "seed", "status", "passed", "attempts", "error_kind", "error"]
            + [v.key for v in spec.variables] + spec.metrics
            + ["sim_status", "stop_reason", "overrides", "elapsed_s"])


def cell(value):
    """A value as its CSV text: floats at full precision (repr round-trips), bools as 0/1."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):  # one line per row, so that a cut row is the last line
        return value.replace("\r", " ").replace("\n", " ")
    return json.dumps(value, sort_keys=True)


def _metric(metrics, name):
    if name in DERIVED_METRICS:
        return sum(metrics[part] for part in DERIVED_METRICS[name])
    value = metrics[name]
    return int(value) if isinstance(value, bool) else value


def _one_line(error):
    text = " ".join(f"{type(error).__name__}: {error}".split())
    return text[:MAX_ERROR_CHARS]


def failed_row(spec, case, attempts, kind, error, overrides=None):
    """The row of a case that did not run, with every sampled value it was given."""
    overrides = spec.case_overrides(case) if overrides is None else overrides
    row = {"case": case, "seed": spec.seed, "status": "failed", "passed": 0,
           "attempts": attempts, "error_kind": kind, "error": error,
           "overrides": json.dumps(overrides, sort_keys=False), "elapsed_s": 0.0}
    for variable in spec.variables:
        row[variable.key] = overrides[variable.key]
    return row


def run_case(spec, case):
    """Runs one case, once more if it raises; returns its row."""
    errors = []
    overrides = spec.case_overrides(case)
    for attempt in (1, 2):
        started = time.perf_counter()
        try:
            scenario = load_scenario(spec.base, overrides, reuse_files=REUSE_BASE_FILES)
            _, summary = run_scenario(scenario)
        except Exception as error:  # noqa: BLE001 - every error becomes the case's row
            errors.append(error)
            continue
        elapsed = time.perf_counter() - started
        return completed_row(spec, case, attempt, summary, elapsed, overrides)
    return failed_row(spec, case, 2, type(errors[-1]).__name__, _one_line(errors[-1]),
                      overrides)


def completed_row(spec, case, attempts, summary, elapsed, overrides):
    row = failed_row(spec, case, attempts, "", "", overrides)
    metrics = summary["metrics"]
    for name in spec.metrics:
        row[name] = _metric(metrics, name)
    row["sim_status"], row["stop_reason"] = summary["status"], summary["stop_reason"]
    row["elapsed_s"] = elapsed
    if summary["status"] != "ok" or summary["stop_reason"] not in COMPLETED_STOPS:
        row["error_kind"] = f"stop: {summary['stop_reason']}"
        row["error"] = f"the run stopped with status {summary['status']}: " \
                       f"{summary['stop_reason']}"
        return row
    row["status"] = "ok"
    values = {name: row[name] for name in spec.metrics}
    row["passed"] = int(all(not (isinstance(values[c.metric], float) and
                                 math.isnan(values[c.metric])) and c.holds(values[c.metric])
                            for c in spec.criteria))
    return row


def run_batch(spec, cases):
    """A batch of cases in one task (the per-task overhead is paid once per batch)."""
    return [run_case(spec, case) for case in cases]
