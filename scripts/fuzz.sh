#!/usr/bin/env bash
# Runs every libFuzzer target of the asan build (clang-14, ASan + UBSan) for a bounded time,
# starting from the committed seed corpus fuzz/corpus/<target>/. A crash, a sanitizer report, a
# timeout or running out of memory fails the run (exit 1); the input that did it is kept in
# build/asan/fuzz-artifacts/ and printed so it can be replayed: build/asan/fuzz/<target> <file>.
#   SMOOTHSTEER_FUZZ_SECONDS  time per target (default 25)
#   SMOOTHSTEER_FUZZ_TARGETS  targets to run (default: all six below)
#   SMOOTHSTEER_FUZZ_JOBS     targets fuzzed at once, one core each (default: the number of cores)
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
jobs="${SMOOTHSTEER_FUZZ_JOBS:-$(nproc)}"
for target in $targets; do
  binary="build/asan/fuzz/$target"
  [[ -x "$binary" ]] || { echo "fuzz: $binary missing (cmake --build --preset asan)"; exit 1; }
done

# Fuzzes one target; its verdict goes to "$results/$target" (0 = passed), its log beside it.
fuzz_one() {
  local target="$1" results="$2"
  # New inputs go to a scratch corpus; the committed seeds stay as they are.
  local work
  work="$(mktemp -d)"
  local log="$results/$target.log"
  local dictionary=()
  [[ -f "fuzz/$target.dict" ]] && dictionary=(-dict="fuzz/$target.dict")
  if "build/asan/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=16384 "${dictionary[@]}" -print_final_stats=1 \
      -artifact_prefix="$artifacts/$target-" "$work" "fuzz/corpus/$target" > "$log" 2>&1; then
    echo 0 > "$results/$target"
  else
    echo 1 > "$results/$target"
  fi
  rm -rf "$work"
}

# The targets are independent: run them `jobs` at a time (each libFuzzer process uses one core).
results="$(mktemp -d)"
trap 'rm -rf "$results"' EXIT
running=0
for target in $targets; do
  fuzz_one "$target" "$results" &
  running=$((running + 1))
  if [[ "$running" -ge "$jobs" ]]; then
    wait -n
    running=$((running - 1))
  fi
done
wait

passed=0
failed=0
for target in $targets; do
  log="$results/$target.log"
  if [[ "$(cat "$results/$target")" == 0 ]]; then
    runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')"
    echo "fuzz: $target passed ($runs inputs in ${seconds} s)"
    passed=$((passed + 1))
  else
    echo "fuzz: $target FAILED; the log ends:"
    tail -40 "$log"
    failed=$((failed + 1))
  fi
done
echo "fuzzing: $passed passed, $failed failed"
[[ "$failed" -eq 0 ]]
