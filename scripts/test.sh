#!/usr/bin/env bash
# README command 2: install, build and run every test (CTest: unit tests, CLI end-to-end tests),
# then the whole suite again built with AddressSanitizer + UndefinedBehaviorSanitizer in
# build-asan (CMakePresets.json, preset asan-ubsan). Arguments go to both ctest runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"

# The sanitizer pass builds what the tests run (the benchmark is left out of its default target)
# at -O1, and leaves out the fuzz tests, which build their own sanitized fuzzer. The test preset
# holds the sanitizer options and the leak suppressions for Mesa.
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake --preset asan-ubsan
fi
cmake --build --preset asan-ubsan --parallel "$(nproc)"
ctest --preset asan-ubsan --parallel "$(nproc)" "$@"
