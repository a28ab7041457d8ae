#!/usr/bin/env bash
# README command 1: install, build and start FoldLab. Arguments are passed to `foldlab`; with none,
# it opens the explorer where a display exists and otherwise prints a solve of the default preset.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >&2
exec build/app/foldlab "$@"
