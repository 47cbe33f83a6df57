#!/usr/bin/env python3
"""Fails when a field of ControllerParameters or of its SteeringGovernor group
(include/smoothsteer/controller/controller_parameters.hpp) is missing from the parameter table
of docs/controller.md, or when the table names a field the header does not have.

Usage: check_parameter_table.py [source_dir]"""
import re
import sys
from pathlib import Path

FIELD = re.compile(r"^\s*[\w:<>, ]+?[\s&*]([a-z_][a-z0-9_]*)\s*(=[^;]*|\{[^;]*\})?;")
NOT_DATA = ("static ", "return ", "using ", "friend ")


def struct_body(text, name):
    start = re.search(r"\bstruct\s+" + name + r"\s*\{", text)
    if not start:
        raise SystemExit(f"struct {name} not found")
    depth, i = 1, start.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[start.end():i - 1]


def data_members(body):
    """Non-static data members at the struct's own level (not inside member functions)."""
    names, depth = [], 0
    for raw in body.splitlines():
        line = re.sub(r"//.*", "", raw)
        if depth == 0 and "(" not in line.split("=")[0] and not line.strip().startswith(NOT_DATA):
            match = FIELD.match(line)
            if match:
                names.append(match.group(1))
        depth += line.count("{") - line.count("}")
    return names


def table_fields(markdown):
    section = markdown.split("## Parameters (`ControllerParameters`", 1)
    if len(section) < 2:
        raise SystemExit("docs/controller.md has no '## Parameters (`ControllerParameters`' section")
    body = section[1].split("\n## ", 1)[0]
    fields = set()
    for line in body.splitlines():
        match = re.match(r"\|\s*`([a-z0-9_.]+)", line)
        if match:
            fields.add(match.group(1))
    return fields


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
    header = (root / "include/smoothsteer/controller/controller_parameters.hpp").read_text()
    expected = set(data_members(struct_body(header, "ControllerParameters")))
    # The governor group is listed field by field as governor.<field>.
    expected.discard("governor")
    expected |= {"governor." + f for f in data_members(struct_body(header, "SteeringGovernor"))}
    documented = table_fields((root / "docs/controller.md").read_text())
    missing = sorted(expected - documented)
    unknown = sorted(documented - expected)
    for name in missing:
        print(f"docs/controller.md: field '{name}' of controller_parameters.hpp is not in the table")
    for name in unknown:
        print(f"docs/controller.md: the table names '{name}', which controller_parameters.hpp lacks")
    print(f"parameter table: {len(expected)} fields in the header, {len(documented)} in the table")
    return 1 if missing or unknown else 0


if __name__ == "__main__":
    sys.exit(main())
