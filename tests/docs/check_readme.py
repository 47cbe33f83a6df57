#!/usr/bin/env python3
"""Checks the README against its rules and its sources:
* at most 220 lines; the first 60 hold what it is, the two commands for a fresh Debian 12 machine
  and the whole C++ example;
* every figure of "How it compares" is the committed table's value at the README's precision:
  the comparison table against docs/results/tuning_rule.md (max_abs_e_m, circle_sections
  rms_e_m, "diverges" where the table says diverged), the reaching ratios against
  docs/results/roc_vx.md, the road-suite totals against road_suite_summary.md and the
  robustness totals against robustness_summary.md.

Usage: check_readme.py [source_dir]"""
import re
import sys
from pathlib import Path

COMMANDS = ["bash scripts/demo.sh", "bash scripts/test.sh"]
COLUMNS = ["lane_change_10", "lane_change_15", "lane_change_19", "circle_sections"]


def markdown_table(text, heading):
    """Rows (lists of cells) of the first table after the line starting with `heading`."""
    lines = (heading + text.split(heading, 1)[1]).splitlines()
    rows, started = [], False
    for line in lines:
        if line.startswith("|"):
            started = True
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not all(set(c) <= set("-: ") for c in cells):
                rows.append(cells)
        elif started:
            break
    return rows


def section(text, title):
    return text.split("\n## " + title, 1)[1].split("\n## ", 1)[0]


def decimals(number_text):
    return len(number_text.split(".")[1]) if "." in number_text else 0


def same(readme_number, source_value):
    """The README's number is the source's value rounded to the README's digits."""
    return abs(float(readme_number) - round(float(source_value), decimals(readme_number))) < 1e-9


def check_layout(readme, errors):
    lines = readme.splitlines()
    if len(lines) > 220:
        errors.append(f"README.md has {len(lines)} lines, at most 220")
    head = "\n".join(lines[:60])
    for command in COMMANDS:
        if command not in head:
            errors.append(f"README.md: '{command}' is not in the first 60 lines")
    block = re.search(r"```cpp\n.*?\n```", head, re.S)
    if not block or "int main(" not in block.group(0):
        errors.append("README.md: the C++ example (a whole program) does not end within the first"
                      " 60 lines")
    if not re.search(r"!\[[^\]]*\]\([^)]+\.png\)", head):
        errors.append("README.md: no picture in the first 60 lines")


def check_comparison(readme, root, errors):
    compares = section(readme, "How it compares")
    source = (root / "docs/results/tuning_rule.md").read_text()
    rows = markdown_table(source, "| scenario | controller")
    header, body = rows[0], rows[1:]
    table = {(r[header.index("scenario")], r[header.index("controller")]): dict(zip(header, r))
             for r in body}
    readme_rows = markdown_table(compares, "| controller |")[1:]
    if not readme_rows:
        errors.append("README.md: no comparison table in 'How it compares'")
    checked = 0
    for cells in readme_rows:
        controller = re.sub(r"[*`]|\(.*?\)", "", cells[0]).strip()
        for scenario, cell in zip(COLUMNS, cells[1:]):
            row = table.get((scenario, controller))
            if row is None:
                errors.append(f"README.md: {controller} on {scenario} is not in tuning_rule.md")
                continue
            number = re.search(r"(\d+\.\d+|\d+) m", cell)
            column = "rms_e_m" if scenario == "circle_sections" else "max_abs_e_m"
            if not number or not same(number.group(1), row[column]):
                errors.append(f"README.md: {controller} on {scenario} says '{cell}', "
                              f"tuning_rule.md {column} = {row[column]}")
            if ("diverges" in cell) != (row["diverged"] == "yes"):
                errors.append(f"README.md: {controller} on {scenario} says '{cell}', "
                              f"tuning_rule.md diverged = {row['diverged']}")
            checked += 1
    roc = markdown_table((root / "docs/results/roc_vx.md").read_text(), "| psi0_rad")
    names = roc[0]
    for label, column in (("optimal distance", "proposed/optimal_relaxed"),
                          ("HOSM", "hosm/optimal_relaxed")):
        values = [float(r[names.index(column)]) for r in roc[1:]]
        match = re.search(r"(\d+\.\d+)-(\d+\.\d+) times the\s+optimal distance" if label !=
                          "HOSM" else r"HOSM (\d+\.\d+)-(\d+\.\d+) times", compares)
        if not match or not (same(match.group(1), min(values)) and
                             same(match.group(2), max(values))):
            errors.append(f"README.md: the reaching ratio range ({label}) does not match "
                          f"roc_vx.md {column} {min(values)}-{max(values)}")
        checked += 2
    summary = markdown_table((root / "docs/results/road_suite_summary.md").read_text(),
                             "| plant | controller")
    columns = summary[0]
    totals = {r[columns.index("controller")]: dict(zip(columns, r)) for r in summary[1:]
              if r[columns.index("plant")] == "single-track"}
    for controller, pattern in (
            ("stanley", r"Stanley\s+held\s+to\s+the\s+same\s+limits\s+on\s+(\d+)\s.*?"
                        r"with\s+(\d+\.\d+) m"),
            ("certified", r"the certified route\s+has the smallest max \|e\| on (\d+) of the 21"
                          r".*?mean max \|e\| of (\d+\.\d+) m")):
        match = re.search(pattern, compares, re.S)
        row = totals.get(controller)
        if not match or row is None or match.group(1) != row["best_of"] or \
                not same(match.group(2), row["mean_max_e_m"]):
            errors.append(f"README.md: the road-suite figures of {controller} do not match "
                          f"road_suite_summary.md")
        checked += 2
    robustness = (root / "docs/results/robustness_summary.md").read_text()
    totals = re.search(r"Over the (\d+) cases: (\d+) within 1.2x \+ 2 cm, (\d+) at most the best",
                       robustness)
    match = re.search(r"at most the best baseline's max \|e\| in (\d+) of (\d+) cases and\s+"
                      r"within 1.2x its nominal figure \+ 2 cm in (\d+)", compares)
    if not totals or not match or (match.group(2), match.group(3), match.group(1)) != \
            totals.groups():
        errors.append("README.md: the robustness totals do not match robustness_summary.md")
    checked += 3
    return checked


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
    readme = (root / "README.md").read_text()
    errors = []
    check_layout(readme, errors)
    checked = check_comparison(readme, root, errors)
    for error in errors:
        print(error)
    print(f"README: {checked} figures checked against their tables, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
