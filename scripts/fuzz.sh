#!/usr/bin/env bash
# Builds the preset loader fuzzer (tests/fuzz_preset_loader.cpp, the project tests/fuzz) with
# clang++ and runs it for a bounded time, starting from the shipped presets. Exits non-zero,
# keeping the crashing input under WORK_DIR/artifacts/, if the fuzzer finds a crash, a sanitizer
# report or an exception other than PresetError. The CTest fuzz_preset_loader runs this.
#
#   scripts/fuzz.sh [--seconds 30] [--clang clang++] [--build-dir build/tests/fuzz]
#                   [--generated-dir build/core/generated] [--work-dir build/fuzz_preset_loader_work]
# (--generated-dir: the main build's generated headers, i.e. run the main CMake configure first.)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=30
clang=clang++-14
command -v "$clang" >/dev/null || clang=clang++
build="$root/build/tests/fuzz"
generated="$root/build/core/generated"
work="$root/build/fuzz_preset_loader_work"
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --clang) clang="$2"; shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    --generated-dir) generated="$2"; shift 2 ;;
    --work-dir) work="$2"; shift 2 ;;
    *) echo "fuzz.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

clang="$(command -v "$clang")" || { echo "fuzz.sh: no clang++ (scripts/install-deps.sh installs it)" >&2; exit 2; }
# A build configured with another compiler cannot be switched in place: start it afresh.
if [ -f "$build/CMakeCache.txt" ] && ! grep -qx "CMAKE_CXX_COMPILER:[A-Z]*=$clang" "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$root/tests/fuzz" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER="$clang" -DFOLDLAB_GENERATED_DIR="$generated" >/dev/null
cmake --build "$build" >/dev/null
fuzzer="$build/fuzz_preset_loader"

rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"
cp "$root"/presets/*.json "$work/corpus/"
# The format's keys and names, so that mutations reach past the JSON parser into the reader.
cat > "$work/preset.dict" <<'DICT'
"\"foldlab_preset\""
"\"name\""
"\"description\""
"\"source\""
"\"fabric\""
"\"thickness_mm\""
"\"youngs_modulus_MPa\""
"\"weight_N_per_mm2\""
"\"poisson_ratio\""
"\"hanging\""
"\"height_mm\""
"\"length_mm\""
"\"support_displacement_mm\""
"\"model\""
"\"method\""
"\"load_constant_c\""
"\"span_rule\""
"\"int_rounding\""
"\"simpson_intervals\""
"\"length_tolerance\""
"\"max_iterations\""
"\"length_quadrature\""
"\"published\""
"\"n\""
"\"z_max_mm\""
"\"Q\""
"\"paper\""
"\"exact\""
"\"L-d\""
"\"L-2d\""
"\"nearest\""
"\"floor\""
"\"simpson\""
"\"trapezoid\""
"1e308"
"-0"
"18446744073709551615"
"9223372036854775808"
"null"
"true"
DICT
exec "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -dict="$work/preset.dict" -artifact_prefix="$work/artifacts/" "$work/corpus"
