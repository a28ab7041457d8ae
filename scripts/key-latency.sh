#!/usr/bin/env bash
# How long an arrow key on a focused slider takes to show (docs/performance.md, "Key latency"):
# the explorer in a real window under Xvfb, a slider clicked to focus it, then an arrow key
# pressed N times by xdotool through the X server, each after the window has come to rest, and the
# report's `latency` printed: the median and 90th percentile of the whole, from the key callback
# to the end of the frame that shows the new value, and of its parts. Measured, not tested: run it
# by hand and say how loaded the machine was (the first line gives the load average).
# Usage: scripts/key-latency.sh [BUILD_DIR] [--presses N] [--gap S] [--slider KEY] [--size WxH]
#        (defaults: build, 40 presses, 0.25 s apart, slider h, 1280x800)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then
  build=$1
  shift
fi
presses=40
gap=0.25
slider=h
size=1280x800
while [ $# -gt 0 ]; do
  case $1 in
    --presses) presses=$2; shift 2 ;;
    --gap) gap=$2; shift 2 ;;
    --slider) slider=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    *) echo "key-latency: unknown option $1" >&2; exit 2 ;;
  esac
done
foldlab=$build/app/foldlab
[ -x "$foldlab" ] || { echo "key-latency: $foldlab is missing; build it first" >&2; exit 1; }
for program in xvfb-run xdotool python3; do
  command -v $program >/dev/null || { echo "key-latency: $program is not installed" >&2; exit 1; }
done
echo "key-latency: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)," \
  "$presses presses of Right on $slider, $gap s apart, $size" >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export HOME=$work XDG_CONFIG_HOME=$work/config
preset=$PWD/presets/default.json
# Where the slider's handle is: the window below lays out the same (same preset, no saved layout).
xvfb-run -a -s "-screen 0 1920x1080x24" "$foldlab" gui --fresh --size "$size" --preset "$preset" \
  --frames 3 --report > "$work/where.json"
read -r x y < <(python3 -c 'import json,sys
h = json.load(open(sys.argv[1]))["sliders"][sys.argv[2]]["handle"]
print(round(h[0]), round(h[1]))' "$work/where.json" "$slider")
xvfb-run -a -s "-screen 0 1920x1080x24" bash -c '
  set -eu
  "$1" gui --size "$2" --preset "$3" --report > "$4" 2> "$5" &
  pid=$!
  WID=$(xdotool search --sync --onlyvisible --name "^FoldLab$" | head -n1)
  xdotool windowfocus --sync $WID
  sleep 2
  xdotool mousemove --window $WID "$6" "$7" click 1
  sleep 1
  for i in $(seq "$8"); do xdotool key Right; sleep "$9"; done
  sleep 1
  kill -TERM $pid
  wait $pid' bash "$foldlab" "$size" "$preset" "$work/report.json" "$work/stderr.txt" "$x" "$y" \
  "$presses" "$gap"
python3 - "$work/report.json" <<'EOF'
import json, sys
latency = json.load(open(sys.argv[1])).get("latency")
if not latency:
    sys.exit("key-latency: the report counted no key that changed the slider")
whole = latency["key_to_frame_ms"]
print(f"{latency['keys']} keys shown: key to frame median {whole['median']:.1f} ms, "
      f"p90 {whole['p90']:.1f} ms, max {whole['max']:.1f} ms")
print(f"{'part':10} {'median':>8} {'p90':>8}")
for name, part in latency["parts"].items():
    print(f"{name:10} {part['median']:8.2f} {part['p90']:8.2f}")
EOF
