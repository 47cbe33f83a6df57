"""The studies' tests share python/tests/conftest.py: the repository root as working directory,
the seeded property counts and the environment of child processes."""
import importlib.util
import pathlib

_spec = importlib.util.spec_from_file_location(
    "smoothsteer_tests_conftest",
    pathlib.Path(__file__).resolve().parents[2] / "python" / "tests" / "conftest.py")
_shared = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_shared)

ROOT = _shared.ROOT
BUILD = _shared.BUILD
base_seed = _shared.base_seed
property_cases = _shared.property_cases
python_environment = _shared.python_environment
repository_root = _shared.repository_root
