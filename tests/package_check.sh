#!/usr/bin/env bash
# The Debian package as a user gets it: cpack builds foldlab_<version>_<arch>.deb from the build
# folder; lintian (no errors), desktop-file-validate and appstreamcli check it; then the package is
# unpacked into a temporary root and its foldlab runs from another folder, with FOLDLAB_PRESETS_DIR
# unset, far from the build folder and the source tree: it must find the presets under that root
# and print and draw exactly what the build tree's foldlab does. Writes only into a temporary
# folder. The CTest package_deb runs this.
#
#   tests/package_check.sh --build-dir build --source-dir . --version 0.1.0
set -euo pipefail
build="" source="" version=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$(cd "$2" && pwd)"; shift 2 ;;
    --source-dir) source="$(cd "$2" && pwd)"; shift 2 ;;
    --version) version="$2"; shift 2 ;;
    *) echo "package_check.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -n "$build" ] && [ -n "$source" ] && [ -n "$version" ] || { echo "package_check.sh: --build-dir, --source-dir and --version are needed" >&2; exit 2; }
for tool in cpack dpkg-deb dpkg-shlibdeps lintian desktop-file-validate appstreamcli; do
  command -v "$tool" >/dev/null || { echo "package_check.sh: $tool missing (scripts/install-deps.sh installs it)" >&2; exit 2; }
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

echo "== cpack -G DEB"
(cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/cpack" >"$work/cpack.log" 2>&1) || {
  cat "$work/cpack.log" >&2
  exit 1
}
arch="$(dpkg --print-architecture)"
deb="$work/cpack/foldlab_${version}_${arch}.deb"
[ -f "$deb" ] || { ls "$work/cpack" >&2; echo "FAIL: no $deb" >&2; exit 1; }
echo "$(basename "$deb"): $(stat -c %s "$deb") bytes"

echo "== control fields"
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = foldlab ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', not $version"
[ "$(field Section)" = science ] || fail "Section is '$(field Section)', not science"
[[ "$(field Maintainer)" =~ ^[^\<]+\ \<[^@]+@[^\>]+\>$ ]] || fail "Maintainer '$(field Maintainer)' is not 'Name <address>'"
depends="$(field Depends)"
echo "Depends: $depends"
# dpkg-shlibdeps' list: the C and C++ runtimes and the window and GL libraries the program links.
# libegl1 and fonts-dejavu-core are named by hand (opened at run time, not linked).
for package in libc6 libstdc++6 libglfw3 libepoxy0 libegl1 fonts-dejavu-core; do
  [[ ", $depends," =~ ,\ "$package"[\ ,] ]] || fail "Depends lacks $package"
done

echo "== files"
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's#^\./#/#' >"$work/files"
for path in /usr/bin/foldlab /usr/share/foldlab/presets/default.json \
  /usr/share/foldlab/presets/paper-table1-h1400.json /usr/share/foldlab/presets/fabric-denim-13oz.json \
  /usr/share/foldlab/data/paper-measurements.csv /usr/share/applications/foldlab.desktop \
  /usr/share/icons/hicolor/scalable/apps/foldlab.svg /usr/share/icons/hicolor/256x256/apps/foldlab.png \
  /usr/share/icons/hicolor/48x48/apps/foldlab.png /usr/share/man/man1/foldlab.1.gz \
  /usr/share/bash-completion/completions/foldlab /usr/share/doc/foldlab/copyright \
  /usr/share/doc/foldlab/changelog.gz; do
  grep -qx "$path" "$work/files" || fail "the package lacks $path"
done
grep -q '^/usr/share/metainfo/.*\.metainfo\.xml$' "$work/files" || fail "the package lacks AppStream metadata"
# Nothing but the program and its data: no headers, libraries or test programs, nothing outside /usr.
if grep -v -e '^/usr/$' -e '^/usr/bin/' -e '^/usr/share/' "$work/files" | grep -q .; then
  fail "unexpected files: $(grep -v -e '^/usr/$' -e '^/usr/bin/' -e '^/usr/share/' "$work/files" | tr '\n' ' ')"
fi
[ "$(grep -c '^/usr/bin/.' "$work/files")" = 1 ] || fail "more than one program in /usr/bin"

echo "== lintian"
# Errors fail the test; warnings and infos are printed.
lintian_status=0
lintian --display-info --fail-on error "$deb" >"$work/lintian" 2>&1 || lintian_status=$?
grep -v '^running with root privileges' "$work/lintian" || true
[ "$lintian_status" = 0 ] || fail "lintian reports errors (exit $lintian_status)"

echo "== unpacked into $work/root"
root="$work/root"
dpkg-deb -x "$deb" "$root"
desktop-file-validate "$root/usr/share/applications/foldlab.desktop" || fail "desktop-file-validate"
# A clicked foldlab: link opens the installed explorer on its fabric.
grep -qx 'MimeType=x-scheme-handler/foldlab;' "$root/usr/share/applications/foldlab.desktop" ||
  fail "the desktop entry does not register the foldlab: scheme"
grep -qx 'Exec=foldlab gui %u' "$root/usr/share/applications/foldlab.desktop" ||
  fail "the desktop entry does not pass a clicked link to foldlab gui"
appstreamcli validate --no-net "$root"/usr/share/metainfo/*.metainfo.xml || fail "appstreamcli validate"
appstreamcli validate-tree --no-net "$root" || fail "appstreamcli validate-tree"
file "$root/usr/bin/foldlab" | grep -q 'stripped' || fail "foldlab is not stripped"
man_text="$(LC_ALL=C.UTF-8 MANWIDTH=100 man -l "$root/usr/share/man/man1/foldlab.1.gz" 2>&1)"
for section in 'foldlab solve' 'foldlab compare' 'foldlab render' '--version'; do
  [[ "$man_text" == *"$section"* ]] || fail "the manual page lacks '$section'"
done

# Both programs run from a folder of their own, with a home and configuration of their own.
run_in() {
  local dir="$1"
  shift
  mkdir -p "$dir/home"
  (cd "$dir" && env -u FOLDLAB_PRESETS_DIR -u DISPLAY -u WAYLAND_DISPLAY HOME="$dir/home" \
    XDG_CONFIG_HOME="$dir/home/.config" "$@")
}
installed="$work/as-installed"
built="$work/as-built"
mkdir -p "$installed" "$built"

echo "== foldlab --version"
run_in "$installed" "$root/usr/bin/foldlab" --version >"$work/version" || fail "--version failed"
cat "$work/version"
[[ "$(sed -n 1p "$work/version")" =~ ^FoldLab\ ${version//./\\.}(\ \([0-9a-f]+(-dirty)?\))?$ ]] ||
  fail "--version's first line is not 'FoldLab $version (commit)'"
[ "$(sed -n 2p "$work/version")" = "presets: $root/usr/share/foldlab/presets" ] ||
  fail "the unpacked foldlab does not take its presets from $root/usr/share/foldlab/presets"

echo "== solve, compare, render: the unpacked program against the build tree's"
for program in installed built; do
  dir="$work/as-$program"
  exe="$root/usr/bin/foldlab"
  presets="$root/usr/share/foldlab/presets"
  if [ "$program" = built ]; then
    exe="$build/app/foldlab"
    presets="$source/presets"
  fi
  run_in "$dir" "$exe" solve >"$dir/solve.txt"
  run_in "$dir" "$exe" solve --preset "$presets/fabric-denim-13oz.json" --json |
    sed "s#$presets/##g" >"$dir/solve-denim.json"
  run_in "$dir" "$exe" compare >"$dir/compare.md"
  run_in "$dir" "$exe" render --size 640x400 --view present=presets --out "$dir/presets.png" >/dev/null
  run_in "$dir" "$exe" render --size 640x400 --out "$dir/explorer.png" >/dev/null
done
for output in solve.txt solve-denim.json compare.md presets.png explorer.png; do
  cmp -s "$installed/$output" "$built/$output" || fail "$output differs from the build tree's"
done
grep -q 'Table 1' "$installed/compare.md" || fail "compare found none of the paper's presets"
[ "$(grep -c '^|' "$installed/compare.md")" -ge 9 ] || fail "compare lists fewer than the paper's 7 rows"

echo "== bash completion"
completion="$(PATH="$root/usr/bin:$PATH" bash -c '
  source "$1"
  COMP_WORDS=(foldlab so); COMP_CWORD=1; _foldlab; echo "${COMPREPLY[*]}"
  COMP_WORDS=(foldlab solve --pre); COMP_CWORD=2; _foldlab; echo "${COMPREPLY[*]}"
' bash "$root/usr/share/bash-completion/completions/foldlab")"
[ "$completion" = "$(printf 'solve\n--preset')" ] || fail "bash completion gave: $completion"

if [ "$failures" -gt 0 ]; then
  echo "package_check.sh: $failures check(s) failed" >&2
  exit 1
fi
echo "package_check.sh: the package passed every check"
