#!/usr/bin/env bash
# Builds everything with warnings as errors and runs every test:
#   1. the formatting of every C++ file against .clang-format,
#   2. the full suite (ci preset: Release, -Werror), with the Python module and its pytest suite
#      (python/tests) and every example (examples/, C++ and Python),
#   3. a consumer project built against the installed package (find_package(smoothsteer)), with
#      the core, the tuning module and io; it also checks that every installed module declares
#      PUBLIC what its installed headers include,
#   4. the standard-library core alone (-DSMOOTHSTEER_CORE_ONLY=ON: no yaml-cpp, Ipopt, Eigen,
#      Boost),
#   5. the Python package pip installs into a fresh venv, imported from outside the tree
#      (scripts/test_python_package.sh),
#   6. the suite again under AddressSanitizer + UndefinedBehaviorSanitizer, float-cast-overflow
#      included (asan preset, clang-14),
#   7. every libFuzzer target for a bounded time from the seed corpus (scripts/fuzz.sh).
# SMOOTHSTEER_PROPERTY_CASES sets the number of randomized cases per property (default 40; CI
# uses more). SMOOTHSTEER_SKIP_ASAN=1 skips steps 6 and 7.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs="$(nproc)"

git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror
echo "formatting: 1 passed, 0 failed"

cmake --preset ci
cmake --build --preset ci -j"$jobs"
# Every test process appends how many closed loops it ran (tests/support/closed_loop_report.cpp)
# to SMOOTHSTEER_LOOP_COUNT_FILE (.ci/run sets it to add its own pass; else a temporary file).
loop_counts="${SMOOTHSTEER_LOOP_COUNT_FILE:-$(mktemp)}"
SMOOTHSTEER_LOOP_COUNT_FILE="$loop_counts" ctest --preset ci -j"$jobs"
echo "closed loops run by the suite: $(awk '{n += $1} END {print n + 0}' "$loop_counts")" \
  "(SMOOTHSTEER_PROPERTY_CASES=${SMOOTHSTEER_PROPERTY_CASES:-default})"
[[ -n "${SMOOTHSTEER_LOOP_COUNT_FILE:-}" ]] || rm -f "$loop_counts"

prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install build/ci --prefix "$prefix" > /dev/null
cmake -S cmake/consumer_test -B "$prefix/consumer-build" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$prefix/consumer-build" > /dev/null
"$prefix/consumer-build/consumer"
echo "consumer: 1 passed, 0 failed"

cmake -S . -B build/core-only -DCMAKE_BUILD_TYPE=Release -DSMOOTHSTEER_WERROR=ON \
  -DSMOOTHSTEER_CORE_ONLY=ON > /dev/null
cmake --build build/core-only -j"$jobs" > /dev/null
echo "core only: 1 passed, 0 failed"

bash scripts/test_python_package.sh

if [[ "${SMOOTHSTEER_SKIP_ASAN:-0}" != "1" ]]; then
  cmake --preset asan
  cmake --build --preset asan -j"$jobs"
  # The sanitizers run the suite at the default case count: they look for memory errors and
  # undefined behaviour, not for rare inputs.
  SMOOTHSTEER_PROPERTY_CASES= SMOOTHSTEER_LOOP_COUNT_FILE= ctest --preset asan -j"$jobs"
  bash scripts/fuzz.sh
fi
