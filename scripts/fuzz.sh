#!/usr/bin/env bash
# Runs every libFuzzer target of the asan build (clang-14, ASan + UBSan) for a bounded time,
# starting from the committed seed corpus fuzz/corpus/<target>/. A crash, a sanitizer report, a
# timeout or running out of memory fails the run (exit 1); the input that did it is kept in
# build/asan/fuzz-artifacts/ and printed so it can be replayed: build/asan/fuzz/<target> <file>.
#   SMOOTHSTEER_FUZZ_SECONDS  time per target (default 25)
#   SMOOTHSTEER_FUZZ_TARGETS  targets to run (default: all six below)
# A target's dictionary fuzz/<target>.dict (YAML anchors and aliases, the schema's keys) is
# passed with -dict when it exists.
# fuzz/known_defects/schedule_region_1e300.csv replays the schedule reader's former int overflow
# of a region cell (now rejected: the reader checks every cell before converting it).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${SMOOTHSTEER_FUZZ_SECONDS:-25}"
targets="${SMOOTHSTEER_FUZZ_TARGETS:-fuzz_scenario fuzz_vehicle fuzz_waypoint_csv fuzz_set_override fuzz_schedule_csv fuzz_controller}"
artifacts="build/asan/fuzz-artifacts"
mkdir -p "$artifacts"
passed=0
failed=0
for target in $targets; do
  binary="build/asan/fuzz/$target"
  [[ -x "$binary" ]] || { echo "fuzz: $binary missing (cmake --build --preset asan)"; exit 1; }
  # New inputs go to a scratch corpus; the committed seeds stay as they are.
  work="$(mktemp -d)"
  log="$work/log"
  dictionary=()
  [[ -f "fuzz/$target.dict" ]] && dictionary=(-dict="fuzz/$target.dict")
  if "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      "${dictionary[@]}" -print_final_stats=1 -artifact_prefix="$artifacts/$target-" "$work" \
      "fuzz/corpus/$target" > "$log" 2>&1; then
    runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')"
    echo "fuzz: $target passed ($runs inputs in ${seconds} s)"
    passed=$((passed + 1))
  else
    echo "fuzz: $target FAILED; the log ends:"
    tail -40 "$log"
    failed=$((failed + 1))
  fi
  rm -rf "$work"
done
echo "fuzzing: $passed passed, $failed failed"
[[ "$failed" -eq 0 ]]
