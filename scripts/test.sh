#!/usr/bin/env bash
# README command 2: install, build and run every test (CTest: unit tests, CLI end-to-end tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"
