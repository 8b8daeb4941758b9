#!/usr/bin/env bash
# Builds with the address and undefined-behaviour sanitizers (preset asan-ubsan) and runs the whole test
# suite; the first sanitizer report stops the test that hit it, so any report fails the run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/install-dependencies.sh
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan
ctest --preset asan-ubsan "$@"
