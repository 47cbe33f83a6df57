"""The results of a campaign on disk (docs/campaigns.md): DIR/results.csv, one row per case
appended as its batch finishes, and DIR/campaign.json, what the rows depend on.

Rows are written whole and flushed after every batch, so a killed campaign leaves at most one
cut line at the end; the next run removes it, keeps every complete row and runs only the cases
that have none. A directory holding another campaign's rows (another base file, seed,
distributions, metrics or criteria) is refused; more cases than before extend the campaign."""
import csv
import fcntl
import io
import json
import os
import stat

from .cases import cell, columns
from .spec_file import CampaignSpecError

RESULTS = "results.csv"
METADATA = "campaign.json"


def _out_error(out, problem):
    return CampaignSpecError(f"--out {out}: {problem}")


def _kind(path):
    """What a path that is not a directory is, in words."""
    if os.path.islink(path) and not os.path.exists(path):
        return f"a symbolic link to {os.readlink(path)}, which does not exist"
    mode = os.stat(path).st_mode
    if stat.S_ISREG(mode):
        return "a file"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "not a directory"


def check_out(out):
    """The results directory, created if it does not exist; CampaignSpecError naming `--out`
    and the problem when it is not a directory or cannot be written."""
    if os.path.lexists(out) and not os.path.isdir(out):
        raise _out_error(out, f"is {_kind(out)}, not a directory; give a directory (it is "
                              "created if missing)")
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as error:
        raise _out_error(out, f"cannot create the results directory: {error.strerror}") from None
    results = os.path.join(out, RESULTS)
    if os.path.lexists(results) and not os.path.isfile(results):
        raise CampaignSpecError(f"--out {out}: {RESULTS} is "
                                f"{'a directory' if os.path.isdir(results) else _kind(results)}"
                                ", not a file; give another --out")


def read_metadata(out):
    """DIR/campaign.json as a dict, or None if the directory has none."""
    path = os.path.join(out, METADATA)
    if not os.path.lexists(path):
        return None
    try:
        with open(path, encoding="utf-8") as handle:
            metadata = json.load(handle)
    except (OSError, UnicodeDecodeError, ValueError) as error:
        reason = error.strerror if isinstance(error, OSError) else f"not valid JSON ({error})"
        raise _out_error(out, f"{METADATA} cannot be read: {reason}; it says which campaign "
                              f"the rows of {RESULTS} belong to: restore it or give another "
                              "--out") from None
    if not isinstance(metadata, dict):
        raise _out_error(out, f"{METADATA} is not a campaign's metadata (a JSON object); give "
                              "another --out")
    return metadata


class ResultFile:
    """results.csv of one campaign, opened for appending; `done` is the set of cases it has."""

    def __init__(self, out, spec):
        check_out(out)
        self.out, self.path = out, os.path.join(out, RESULTS)
        self.columns = columns(spec)
        try:
            self._check_metadata(spec)
            self.done = set()
            exists = os.path.exists(self.path)
            self.handle = open(self.path, "a+", newline="", encoding="utf-8")
        except OSError as error:
            raise _out_error(out, f"cannot write {os.path.basename(error.filename or self.path)}"
                                  f": {error.strerror}") from None
        try:
            fcntl.flock(self.handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self.handle.close()
            raise CampaignSpecError(f"{out}: another campaign is writing to this directory") \
                from None
        if exists and os.path.getsize(self.path) > 0:
            self._recover()
        else:
            self._append([self.columns])
        self.recovered = len(self.done)

    def _check_metadata(self, spec):
        path = os.path.join(self.out, METADATA)
        identity = spec.identity()
        previous = read_metadata(self.out)
        if previous is not None:
            if previous.get("identity") != identity:
                raise CampaignSpecError(
                    f"{self.out}: holds the rows of another campaign ({previous.get('spec')}, "
                    f"{previous.get('name')}): its base file, seed, overrides, variables, "
                    "metrics or criteria differ; give another --out")
        metadata = {"name": spec.name, "spec": spec.file, "base": spec.base, "seed": spec.seed,
                    "cases": spec.cases, "identity": identity, "columns": self.columns}
        temporary = path + ".tmp"
        with open(temporary, "w", encoding="utf-8") as handle:
            json.dump(metadata, handle, indent=1)
        os.replace(temporary, path)

    def _recover(self):
        self.handle.seek(0)
        text = self.handle.read()
        end = text.rfind("\n") + 1
        if end < len(text):  # a row cut by a kill: drop it, its case runs again
            self.handle.truncate(len(text[:end].encode("utf-8")))
            text = text[:end]
        rows = list(csv.reader(io.StringIO(text)))
        if not rows:  # killed while writing the header
            self.handle.seek(0, os.SEEK_END)
            self._append([self.columns])
            return
        if rows[0] != self.columns:
            raise CampaignSpecError(f"{self.path}: its columns are not this campaign's "
                                    f"({', '.join(self.columns)}); give another --out")
        for number, row in enumerate(rows[1:], start=2):
            if len(row) != len(self.columns):
                raise CampaignSpecError(f"{self.path}: line {number} has {len(row)} fields, "
                                        f"not {len(self.columns)}")
            self.done.add(int(row[0]))
        self.handle.seek(0, os.SEEK_END)

    def _append(self, rows):
        buffer = io.StringIO()
        csv.writer(buffer, lineterminator="\n").writerows(rows)
        self.handle.write(buffer.getvalue())
        self.handle.flush()

    def write(self, rows):
        """Appends the rows of cases not yet in the file (a case is never written twice)."""
        fresh = [row for row in rows if row["case"] not in self.done]
        self._append([[cell(row.get(name)) for name in self.columns] for row in fresh])
        self.done.update(row["case"] for row in fresh)
        return len(fresh)

    def close(self):
        if not self.handle.closed:
            self.handle.flush()
            os.fsync(self.handle.fileno())
            self.handle.close()


def read_rows(out, spec):
    """The rows of DIR/results.csv for cases 0 .. spec.cases - 1, sorted by case (pandas)."""
    import pandas as pd

    path = os.path.join(out, RESULTS)
    if not os.path.isdir(out):
        raise _out_error(out, "no such results directory; run the campaign first (without "
                              "--report-only)")
    check_out(out)
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        raise _out_error(out, f"holds no {RESULTS}; run the campaign first (without "
                              "--report-only)")
    frame = pd.read_csv(path, keep_default_na=False, na_values=[""],
                        float_precision="round_trip",
                        dtype={"error_kind": str, "error": str, "status": str,
                               "overrides": str, "stop_reason": str, "sim_status": str})
    frame = frame[frame["case"] < spec.cases]
    return frame.sort_values("case").reset_index(drop=True)
