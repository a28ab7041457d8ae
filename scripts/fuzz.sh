#!/usr/bin/env bash
# Builds the loader fuzzers (tests/fuzz_*.cpp, the project tests/fuzz) with clang++ and runs one
# for a bounded time, starting from the shipped files. Exits non-zero, keeping the crashing input
# under WORK_DIR/artifacts/, if the fuzzer finds a crash, a sanitizer report or an exception other
# than the loader's own error. The CTests fuzz_build and fuzz_TARGET run this.
#
#   scripts/fuzz.sh [--target preset_loader|measurements|session|settings|calibration|play_script|export_names]
#                   [--seconds 30]
#                   [--clang clang++] [--build-dir build/tests/fuzz]
#                   [--generated-dir build/core/generated] [--work-dir build/fuzz_TARGET_work]
#                   [--build-only | --no-build]
# (--generated-dir: the main build's generated headers, i.e. run the main CMake configure first.
#  --build-only and --no-build split building from fuzzing, so that parallel runs share a build.)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=30
target=preset_loader
build_step=1
fuzz_step=1
clang=clang++-14
command -v "$clang" >/dev/null || clang=clang++
build="$root/build/tests/fuzz"
generated="$root/build/core/generated"
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --target) target="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --build-only) fuzz_step=0; shift ;;
    --no-build) build_step=0; shift ;;
    --clang) clang="$2"; shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    --generated-dir) generated="$2"; shift 2 ;;
    --work-dir) work="$2"; shift 2 ;;
    *) echo "fuzz.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

case "$target" in
  preset_loader|measurements|session|settings|calibration|play_script|export_names) ;;
  *) echo "fuzz.sh: unknown target $target" >&2; exit 2 ;;
esac
[ -n "$work" ] || work="$root/build/fuzz_${target}_work"

if [ "$build_step" = 1 ]; then
  clang="$(command -v "$clang")" || { echo "fuzz.sh: no clang++ (scripts/install-deps.sh installs it)" >&2; exit 2; }
  # A build configured with another compiler cannot be switched in place: start it afresh.
  if [ -f "$build/CMakeCache.txt" ] && ! grep -qx "CMAKE_CXX_COMPILER:[A-Z]*=$clang" "$build/CMakeCache.txt"; then
    rm -rf "$build"
  fi
  cmake_args=()
  command -v ninja >/dev/null && cmake_args=(-G Ninja)
  # The fuzzers compile the loaders afresh with clang: ccache, when present, makes reruns quick.
  command -v ccache >/dev/null && cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$root/tests/fuzz" -B "$build" "${cmake_args[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER="$clang" -DFOLDLAB_GENERATED_DIR="$generated" >/dev/null
  cmake --build "$build" >/dev/null
fi
[ "$fuzz_step" = 1 ] || exit 0
fuzzer="$build/fuzz_$target"

rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"
# Seeds from the shipped files, and the formats' keys and names as a dictionary, so that mutations
# reach past the parsers into the readers.
case "$target" in
  preset_loader)
    cp "$root"/presets/*.json "$work/corpus/" ;;
  measurements)
    cp "$root"/data/*.csv "$root"/data/*.json "$work/corpus/"
    head -n 1 "$root"/data/*.csv | grep -v '^==>' | tr ',' '\n' | grep -v '^$' | sort -u |
      sed 's/.*/"&"/' > "$work/extra.dict" ;;
  session)
    # A session holds the edited and the loaded preset and the view settings.
    for preset in "$root"/presets/*.json; do
      printf '{"foldlab_session": 1, "current": %s, "loaded": %s, "loaded_preset_path": "%s", "view": {"grid_resolution": 128, "wireframe": false, "fold_lines": true, "ground": true}}\n' \
        "$(cat "$preset")" "$(cat "$preset")" "$preset" > "$work/corpus/$(basename "$preset")"
    done
    printf '"\\"%s\\""\n' foldlab_session current loaded loaded_preset_path view \
      grid_resolution wireframe fold_lines ground > "$work/extra.dict" ;;
  settings)
    # Every key of the input table (read from it), set to the values the shipped presets hold:
    # a preset's "thickness_mm": 0.25 becomes t=0.25 through the table's preset pointers.
    table="$root/core/model/settings.cpp"
    grep -o '\.key = "[^"]*"' "$table" | sed 's/\.key = "\(.*\)"/"\1="/' > "$work/extra.dict"
    awk -F'"' '/\.key = /{key=$2} /\.preset = /{n=split($2,part,"/"); print part[n], key}' \
      "$table" > "$work/keys.map"
    i=0
    for preset in "$root"/presets/*.json; do
      grep -o '"[a-zA-Z_]*": *"*[-0-9.e+a-zA-Z]*"*[,}]*$' "$preset" | tr -d '",}' |
        awk -v map="$work/keys.map" 'BEGIN{while((getline l < map) > 0){split(l,f," "); k[f[1]]=f[2]}}
          {split($0,f,": *"); if (f[1] in k) print k[f[1]] "=" f[2]}' > "$work/corpus/seed$i.txt"
      i=$((i + 1))
    done ;;
  calibration)
    # The shipped presets' calibration blocks, each the whole input.
    for preset in "$root"/presets/*.json; do
      python3 -c 'import json,sys; c=json.load(open(sys.argv[1])).get("calibration")
if c is not None: print(json.dumps(c))' "$preset" > "$work/corpus/$(basename "$preset")"
    done
    printf '"\\"%s\\""\n' calibrated_on method K p fit_rows equally_good leave_one_out \
      > "$work/extra.dict" ;;
  export_names)
    # Names as the presets give them, and the bytes that broke the writers: a line break that
    # starts an OBJ statement, markup, an escape.
    grep -ho '"name": *"[^"]*"' "$root"/presets/*.json | sed 's/"name": *"\(.*\)"/\1/' |
      awk -v dir="$work/corpus" '{print > (dir "/name" NR ".txt")}'
    printf 'Evil\nv 1e9 1e9 1e9\n<b>&\033[2J' > "$work/corpus/hostile.txt"
    cat > "$work/extra.dict" <<'NAMES'
"\x0av "
"<"
"&"
"\x1b["
NAMES
    ;;
  play_script)
    cp "$root"/tests/play/*.json "$work/corpus/"
    printf '"\\"%s\\""\n' steps drag dx click at ctrl click_photo key type resize frames \
      screenshot expect ctrl+z escape 1280x800 > "$work/extra.dict" ;;
esac
touch "$work/extra.dict"
cat "$work/extra.dict" - > "$work/loader.dict" <<'DICT'
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
  -dict="$work/loader.dict" -artifact_prefix="$work/artifacts/" "$work/corpus"
