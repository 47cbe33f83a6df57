#!/usr/bin/env bash
# Checks that a change keeps every shipped scenario's trace byte-identical: runs each
# scenarios/*.yaml and scenarios/roads/*.yaml with the CLI and compares trace.csv with cmp
# against a saved folder or against the traces of a reference CLI (e.g. a build of main).
#
#   scripts/check_trace_identity.sh --save DIR            # keep the current traces in DIR
#   scripts/check_trace_identity.sh --against DIR         # compare with traces saved there
#   scripts/check_trace_identity.sh --reference-cli BIN   # compare with what BIN writes
# Options: --cli BIN (default build/ci/apps/smoothsteer), --scenarios DIR (default scenarios).
# Exit status 0 when every trace is identical, 1 when one differs or a run fails.
set -euo pipefail

cli=build/ci/apps/smoothsteer
scenarios=scenarios
mode=""
target=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --cli) cli="$2"; shift 2 ;;
    --scenarios) scenarios="$2"; shift 2 ;;
    --save | --against | --reference-cli) mode="$1"; target="$2"; shift 2 ;;
    *) echo "unknown argument: $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
if [[ -z "$mode" ]]; then
  echo "give --save DIR, --against DIR or --reference-cli BIN (see the header of $0)" >&2
  exit 2
fi

# Writes every scenario's trace.csv as $2/<relative path without .yaml>/trace.csv with CLI $1.
run_all() {
  local binary="$1" out="$2" file name
  for file in "$scenarios"/*.yaml "$scenarios"/roads/*.yaml; do
    [[ -e "$file" ]] || continue
    name="${file#"$scenarios"/}"
    name="${name%.yaml}"
    mkdir -p "$out/$name"
    if ! "$binary" run "$file" --out "$out/$name" > "$work/log.txt" 2>&1; then
      echo "FAILED run: $binary run $file:" >&2
      cat "$work/log.txt" >&2
      return 1
    fi
  done
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case "$mode" in
  --save)
    run_all "$cli" "$target"
    echo "saved the traces of $(find "$target" -name trace.csv | wc -l) scenarios in $target"
    exit 0 ;;
  --against) reference="$target" ;;
  --reference-cli) reference="$work/reference"; run_all "$target" "$reference" ;;
esac

run_all "$cli" "$work/current"
same=0
different=0
while IFS= read -r trace; do
  name="${trace#"$reference"/}"
  if [[ ! -f "$work/current/$name" ]]; then
    echo "MISSING: $name has no current trace"
    different=$((different + 1))
  elif cmp -s "$trace" "$work/current/$name"; then
    same=$((same + 1))
  else
    echo "DIFFERS: $name ($(cmp "$trace" "$work/current/$name" | head -1))"
    different=$((different + 1))
  fi
done < <(find "$reference" -name trace.csv | sort)
echo "$same identical, $different different"
[[ $different -eq 0 && $same -gt 0 ]]
