#!/usr/bin/env bash
# README command 2: install, build and run every test (CTest: unit tests, CLI end-to-end tests),
# then the browser build's tests (build-web), then the whole suite again built with
# AddressSanitizer + UndefinedBehaviorSanitizer in build-asan (CMakePresets.json, preset
# asan-ubsan). Arguments go to every ctest run.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each phase's wall time, said at the end (and on a failure, up to the phase that failed): the
# run has a time budget, and this says where it goes.
phases=()
phase_start=$SECONDS
phase() {
  phases+=("$1 $((SECONDS - phase_start)) s")
  phase_start=$SECONDS
}
say_phases() {
  echo "test.sh: wall time by phase: ${phases[*]/%/;} total $SECONDS s" >&2
}
trap say_phases EXIT

bash scripts/build.sh
phase "build"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"
phase "tests"

# The CLI suite once more as an unprivileged user (nobody): to root every file is writable and
# readable, so refusals of read-only or unreadable files are only seen this way. Skipped, saying
# so, when the checkout is not reachable by that user.
if [ "$(id -u)" = 0 ] && [ $# -eq 0 ]; then
  as_nobody=(setpriv --reuid=nobody --regid=nogroup --clear-groups env HOME=/nonexistent)
  if "${as_nobody[@]}" test -x build/tests/foldlab_cli_tests -a -x build/app/foldlab; then
    "${as_nobody[@]}" build/tests/foldlab_cli_tests --gtest_brief=1
  else
    echo "test.sh: the CLI suite as nobody is skipped: $(pwd) is not readable by nobody" >&2
  fi
  phase "cli-as-nobody"
fi

# The browser build (build-web, scripts/web.sh) and its tests: the core suite in WebAssembly under
# node, the paper rows against the desktop program just built, and the page in headless Chromium.
bash scripts/web.sh --native build/app/foldlab
phase "page-build"
ctest --test-dir build-web --output-on-failure "$@"
phase "page-tests"

# The sanitizer pass builds what the tests run (the benchmark is left out of its default target)
# at -O1, and leaves out the fuzz tests, which build their own sanitized fuzzer. The test preset
# holds the sanitizer options and the leak suppressions for Mesa.
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake --preset asan-ubsan
fi
cmake --build --preset asan-ubsan --parallel "$(nproc)"
phase "sanitizer-build"
ctest --preset asan-ubsan --parallel "$(nproc)" "$@"
phase "sanitizer-tests"
