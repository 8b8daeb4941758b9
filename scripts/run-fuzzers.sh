#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, address and undefined-behaviour sanitizers) and runs each one from
# its seed corpus in tests/fuzz/corpus/ for SECONDS seconds (default 20), or for RUNS executions when
# --runs RUNS is given. Any crash, hang, leak or sanitizer report fails the script; a reproducer is kept in
# build/fuzz/findings/.
#   bash scripts/run-fuzzers.sh [--seconds N | --runs N] [harness ...]
# MCPP_FUZZ_MAX_LEN caps an input's bytes (default 65536); smaller runs faster on long runs.
# MCPP_FUZZ_TIMEOUT: seconds one input may take (default 10); raise it when the machine is busy.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
limit=(-max_total_time=20)
if [ "${1:-}" = "--seconds" ]; then limit=(-max_total_time="$2"); shift 2; fi
if [ "${1:-}" = "--runs" ]; then limit=(-runs="$2"); shift 2; fi
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(fuzz_mission fuzz_class_table_csv fuzz_legend_csv fuzz_qgis_style fuzz_raster_legend fuzz_plan_file)
fi
bash scripts/install-dependencies.sh
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
findings="$root/build/fuzz/findings"
mkdir -p "$findings"
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export CPL_DEBUG=OFF
for harness in "${harnesses[@]}"; do
  # The corpus grows in a scratch copy; the seeds in the tree stay as committed.
  corpus="$root/build/fuzz/corpus/$harness"
  mkdir -p "$corpus"
  cp -n tests/fuzz/corpus/"$harness"/* "$corpus"/ 2>/dev/null || true
  log="$root/build/fuzz/$harness.log"
  if ! "build/fuzz/tests/fuzz/$harness" "${limit[@]}" -timeout="${MCPP_FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 -max_len="${MCPP_FUZZ_MAX_LEN:-65536}" \
    -print_final_stats=1 -artifact_prefix="$findings/$harness-" "$corpus" >"$log" 2>&1; then
    tail -40 "$log" >&2
    echo "mcpp: $harness found a problem; reproducer in $findings" >&2
    exit 1
  fi
  runs="$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')"
  seconds="$(grep -m1 'stat::average_exec_per_sec' "$log" | awk '{print $2}')"
  echo "mcpp: $harness: ${runs:-?} executions (${seconds:-?}/s), no crash, hang, leak or sanitizer report"
done
