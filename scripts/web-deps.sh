#!/usr/bin/env bash
# Installs what the browser build needs beyond scripts/install-deps.sh: Debian's emscripten and
# chromium (idempotent, apt-get only for what is missing), and fetches Dear ImGui's source package
# (the same 1.86 the desktop links as libimgui-dev) into a git-ignored cache. The system's apt
# configuration is left untouched: the deb-src entry lives in a sources folder of our own.
# Usage: scripts/web-deps.sh CACHE_DIR   (prints nothing on success when all is there)
set -euo pipefail
cache=${1:?usage: web-deps.sh CACHE_DIR}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

packages=(emscripten chromium googletest python3 fonts-dejavu-core dpkg-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "web-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "web-deps: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# ImGui's sources: the version of the installed libimgui-dev when there is one, so that desktop
# and browser draw with the same library.
imgui_dir="$cache/imgui"
if [ ! -f "$imgui_dir/imgui.h" ]; then
  apt_dir="$cache/apt"
  mkdir -p "$apt_dir/sources.list.d" "$apt_dir/lists/partial" "$apt_dir/src"
  # The same archive and suite the machine already uses.
  suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
  mirror=http://deb.debian.org/debian
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    found=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources)
    [ -n "$found" ] && mirror=$found
  fi
  echo "deb-src $mirror $suite main" >"$apt_dir/sources.list.d/foldlab-src.list"
  apt_opts=(-o "Dir::Etc::SourceParts=$apt_dir/sources.list.d" -o Dir::Etc::SourceList=/dev/null
    -o "Dir::State::Lists=$apt_dir/lists" -o Debug::NoLocking=1 -o APT::Sandbox::User=root)
  apt-get "${apt_opts[@]}" -qq update
  rm -rf "$apt_dir/src" && mkdir -p "$apt_dir/src"
  version=$(dpkg-query -W -f='${source:Version}' libimgui-dev 2>/dev/null || true)
  (cd "$apt_dir/src" && apt-get "${apt_opts[@]}" -qq source --download-only "imgui${version:+=$version}" >/dev/null)
  (cd "$apt_dir/src" && dpkg-source --no-check -x ./*.dsc imgui >/dev/null)
  rm -rf "$imgui_dir"
  mv "$apt_dir/src/imgui" "$imgui_dir"
fi
