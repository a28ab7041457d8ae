#!/usr/bin/env bash
# The browser build's figures (docs/web.md, "Figures"): first frame after load, frame time while
# a slider is dragged (the page in headless Chromium with SwiftShader beside the desktop program
# on llvmpipe, both 1280x800), time per solve in WebAssembly against native, and the site's size
# raw and gzipped. Measured, not tested: run by hand on a quiet machine, and say which.
# Usage: scripts/web-bench.sh [NATIVE_BUILD_DIR] [--repeat N] [--first-frame-only]
#        (default build-release;
#        scripts/web.sh must have built build-web/ first)
set -euo pipefail
cd "$(dirname "$0")/.."
native_build=build-release
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then
  native_build=$1
  shift
fi
for needed in build-web/site/foldlab.wasm "$native_build/app/foldlab" \
              "$native_build/tests/foldlab_solve_times" \
              build-web/tests/web/foldlab_solve_times_wasm.js; do
  [ -e "$needed" ] || { echo "web-bench: $needed is missing; build it first" >&2; exit 1; }
done
echo "web-bench: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
exec python3 tests/web/web_bench.py --site build-web/site --native "$native_build/app/foldlab" \
  --solve-times-native "$native_build/tests/foldlab_solve_times" \
  --solve-times-wasm build-web/tests/web/foldlab_solve_times_wasm.js "$@"
