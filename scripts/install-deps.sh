#!/usr/bin/env bash
# Installs the Debian 12 packages FoldLab builds, tests and runs with. Idempotent: packages already
# present are not fetched again, and `apt-get update` runs only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format clang-tidy
  libeigen3-dev nlohmann-json3-dev libcli11-dev libtinygltf-dev
  libimgui-dev libstb-dev libglfw3-dev fonts-dejavu-core libepoxy-dev libegl-dev libgl-dev
  libegl-mesa0 libgl1-mesa-dri
  googletest libgtest-dev libbenchmark-dev
  clang libclang-rt-14-dev libfuzzer-14-dev
  xvfb xauth xdotool
  dpkg-dev file lintian desktop-file-utils appstream man-db librsvg2-bin
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
