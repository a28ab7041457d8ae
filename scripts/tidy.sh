#!/usr/bin/env bash
# clang-tidy-14 with the repository's .clang-tidy over our sources (core/, app/, tests/), using
# a configured build's compile_commands.json. Exits non-zero on any finding. Not run by CI: it
# takes several minutes.
#
#   scripts/tidy.sh [--build-dir build] [--jobs N] [regex ...]
# (regex: limit to the files whose path matches, e.g. core/analysis/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
jobs="$(nproc)"
files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$(cd "$2" && pwd)"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    *) files+=("$1"); shift ;;
  esac
done
[ ${#files[@]} -gt 0 ] || files=("$root/(core|app|tests)/")
if [ ! -f "$build/compile_commands.json" ]; then
  echo "tidy.sh: no $build/compile_commands.json; configure first (scripts/build.sh)" >&2
  exit 2
fi
tidy="$(command -v run-clang-tidy-14 || command -v run-clang-tidy)" || {
  echo "tidy.sh: run-clang-tidy-14 not found (Debian: clang-tidy-14)" >&2
  exit 2
}
# The compile commands are GCC's: clang does not know some of its warning options, and its
# -Wconversion also means -Wsign-conversion, which GCC's (the build's) does not.
exec "$tidy" -p "$build" -j "$jobs" -quiet -extra-arg=-Wno-unknown-warning-option \
  -extra-arg=-Wno-sign-conversion "${files[@]}"
