#!/usr/bin/env bash
# Builds FoldLab for the browser into build-web/site/ (index.html, foldlab.js, foldlab.wasm,
# foldlab.data): installs what it needs (Debian's emscripten and chromium; idempotent), fetches
# Dear ImGui's Debian source package into build-web/cache/, and builds with emcc. Serve the folder
# with any static server, e.g. `python3 -m http.server -d build-web/site`. docs/web.md has more.
# Usage: scripts/web.sh [--native FOLDLAB]   (FOLDLAB: the desktop program the web tests compare
#        with; scripts/test.sh passes build/app/foldlab)
set -euo pipefail
cd "$(dirname "$0")/.."
native=""
if [ "${1:-}" = "--native" ]; then
  native=$(realpath "$2")
fi
bash scripts/install-deps.sh
bash scripts/web-deps.sh build-web/cache

# Debian's emcc runs parts of itself with node and needs Debian's node modules (acorn and
# friends), which a node from elsewhere (nodesource) does not look in by itself.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ ! -f build-web/CMakeCache.txt ]; then
  emcmake cmake -S . -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
    -DFOLDLAB_IMGUI_SOURCE_DIR="$(pwd)/build-web/cache/imgui" \
    -DFOLDLAB_NATIVE_EXECUTABLE="$native" >/dev/null
elif [ -n "$native" ]; then
  cmake build-web -DFOLDLAB_NATIVE_EXECUTABLE="$native" >/dev/null
fi
cmake --build build-web --parallel "$(nproc)"
