#!/usr/bin/env bash
# Installs smoothsteer's build and test dependencies from Debian 12 packages.
# Skips apt entirely when everything is already installed, unless --force is given.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libeigen3-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev coinor-libipopt-dev libalglib-dev
  libgtest-dev libgmock-dev libbenchmark-dev libboost-dev
  python3-numpy python3-scipy python3-matplotlib python3-dev python3-pybind11 pybind11-dev python3-pytest
  python3-distributed python3-pandas python3-tqdm python3-yaml python3-pil
  python3-pip python3-venv python3-setuptools python3-wheel python3-skbuild
  clang-14 libclang-rt-14-dev
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done

if [[ ${#missing[@]} -eq 0 && "${1:-}" != "--force" ]]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [[ "$(id -u)" -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update
$sudo apt-get install -y --no-install-recommends "${packages[@]}"
