#!/usr/bin/env python3
"""Fails when a member of a group of ControllerParameters
(include/smoothsteer/controller/controller_parameters.hpp: chain, law, feedforward, the optional
compensations, governor) is missing from the member column of docs/controller.md's parameter
table, or when the table names a member the header does not have. The table itself is generated
from the field table (parameter_fields.cpp) and compared by ParameterFields.DocsTableIsTheFieldTable,
so a member missing here is one the field table lacks. The groups' `enabled` switches are not
fields of the table (the flat fields switch them), except the governor's.

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


def table_members(markdown):
    section = markdown.split("## Parameters (`ControllerParameters`", 1)
    if len(section) < 2:
        raise SystemExit("docs/controller.md has no '## Parameters (`ControllerParameters`' section")
    body = section[1].split("<!-- parameter table: generated from parameter_fields.cpp -->", 1)
    if len(body) < 2:
        raise SystemExit("docs/controller.md has no generated parameter table")
    table = body[1].split("<!-- end of parameter table -->", 1)[0]
    members = set()
    for line in table.splitlines():
        match = re.match(r"\|\s*`[^`]+`\s*\|\s*`([a-z0-9_.]+)`", line)
        if match:
            members.add(match.group(1))
    return members


GROUPS = {"chain": "ChainParameters", "law": "SwitchingLawParameters",
          "feedforward": "FeedforwardParameters", "delay_compensation": "DelayCompensation",
          "single_track": "SingleTrackInversion", "disturbance_estimation": "DisturbanceEstimation",
          "friction_guard": "FrictionGuard", "actuator_inversion": "ActuatorInversion",
          "governor": "SteeringGovernor"}


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
    header = (root / "include/smoothsteer/controller/controller_parameters.hpp").read_text()
    groups = data_members(struct_body(header, "ControllerParameters"))
    if set(groups) != set(GROUPS):
        print(f"controller_parameters.hpp: groups {sorted(groups)}, expected {sorted(GROUPS)}")
        return 1
    expected = set()
    for group, struct in GROUPS.items():
        for member in data_members(struct_body(header, struct)):
            if member == "enabled" and group != "governor":
                continue
            expected.add(f"{group}.{member}")
    documented = table_members((root / "docs/controller.md").read_text())
    missing = sorted(expected - documented)
    unknown = sorted(documented - expected)
    for name in missing:
        print(f"docs/controller.md: member '{name}' of controller_parameters.hpp is not in the table")
    for name in unknown:
        print(f"docs/controller.md: the table names '{name}', which controller_parameters.hpp lacks")
    print(f"parameter table: {len(expected)} members in the header, {len(documented)} in the table")
    return 1 if missing or unknown else 0


if __name__ == "__main__":
    sys.exit(main())
