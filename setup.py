"""The Python package smoothsteer (docs/python.md, "Install, build, import"), built by
scikit-build from the project's CMake: the libraries and the pybind11 module only (no tests,
benchmarks, apps or examples, so the build takes minutes), Release, and only the package's
install component (python/CMakeLists.txt) goes into the wheel."""
import os
import pathlib
import re
import sys

from skbuild import setup

ROOT = pathlib.Path(__file__).resolve().parent
# The module is built for Debian's python3, whose numpy and pybind11 the build and the package
# use; another interpreter could not import it.
DEBIAN_PYTHON = "/usr/bin/python3"


def project_version():
    """The version has one home: the top-level CMakeLists.txt's project() line."""
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(smoothsteer VERSION ([0-9.]+)", text).group(1)


def check_interpreter():
    """Refuses to build for an interpreter other than Debian's python3 (a venv made from it is
    that interpreter too)."""
    running = os.path.realpath(sys.executable)
    if running != os.path.realpath(DEBIAN_PYTHON):
        sys.exit(f"smoothsteer: build with {DEBIAN_PYTHON} -m pip (or a venv made from it); "
                 f"this is {sys.executable} ({running})")


check_interpreter()
setup(
    name="smoothsteer",
    version=project_version(),
    description="n-smooth, differentially bounded path-tracking control for car-like vehicles",
    license="Apache-2.0",
    python_requires=">=3.11",
    packages=["smoothsteer"],
    package_dir={"": "python"},
    # CMake installs the package into <prefix>/smoothsteer, with the prefix scikit-build's
    # staging directory for python/.
    cmake_install_dir="python",
    cmake_install_target="install_python_package",
    cmake_args=[
        f"-DPython3_EXECUTABLE={DEBIAN_PYTHON}",
        "-DSMOOTHSTEER_BUILD_PYTHON=ON",
        "-DSMOOTHSTEER_PYTHON_INSTALL_DIR=.",
        "-DSMOOTHSTEER_BUILD_TESTS=OFF",
        "-DSMOOTHSTEER_BUILD_BENCHMARKS=OFF",
        "-DSMOOTHSTEER_BUILD_APPS=OFF",
        "-DSMOOTHSTEER_BUILD_EXAMPLES=OFF",
    ],
)
