"""Shared set-up of the Python tests: every test runs from the repository root (scenario files
name their vehicle and waypoint files relatively), with the build tree of the ci preset (or
$SMOOTHSTEER_BUILD_DIR) for the CLI and the C++ reference programs."""
import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("SMOOTHSTEER_BUILD_DIR", ROOT / "build" / "ci"))
CLI = BUILD / "apps" / "smoothsteer"


def property_cases(default=40):
    """SMOOTHSTEER_PROPERTY_CASES, as for the C++ property tests."""
    text = os.environ.get("SMOOTHSTEER_PROPERTY_CASES", "")
    return int(text) if text else default


def base_seed():
    text = os.environ.get("SMOOTHSTEER_SEED", "")
    return int(text) if text else 20261122


@pytest.fixture(autouse=True)
def repository_root(monkeypatch):
    monkeypatch.chdir(ROOT)


def python_environment():
    """The environment of a child python3 that imports the module under test."""
    import smoothsteer

    environment = dict(os.environ)
    package_parent = str(pathlib.Path(smoothsteer.__file__).resolve().parents[1])
    environment["PYTHONPATH"] = os.pathsep.join(
        [package_parent] + [p for p in environment.get("PYTHONPATH", "").split(os.pathsep) if p])
    environment["MPLBACKEND"] = "Agg"
    return environment
