#!/usr/bin/env python3
"""The browser build's figures, measured (not a test: timings are no pass/fail criterion); run
by scripts/web-bench.sh, which says how. Prints a Markdown table and the raw numbers as JSON.

  web_bench.py --site DIR --native FOLDLAB --solve-times-native EXE --solve-times-wasm JS
               [--chromium PATH] [--repeat N] [--first-frame-only]

  first frame   from navigation start to the explorer's first frame drawn (the page's mark
                'foldlab: first frame'), cold (a fresh profile in a browser just started, its
                GPU process too), first visit (a fresh profile in a browser already showing
                WebGL on another site: a student's) and warm (that page reloaded), each cold
                load with its steps (the page's and the program's marks, COLD_STEP_NAMES)
  dragging      tests/web/bench_drag.json (24 drags of the h slider) played at 1280x800: the
                page in headless Chromium (SwiftShader WebGL2, real time) beside `foldlab render`
                (EGL on Mesa's llvmpipe); each frame from its start to glFinish, mean and p95
  solve         time per solve of the 40 realistic benchmark cases, WebAssembly (node) over
                native, each case's fastest of --repeat runs taken by turns; the geometric mean,
                median and range of the per-case ratios
  site          build-web/site's files, raw and gzip -9"""
import argparse
import gzip
import json
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_drive import REPORT_TEXT, Page  # noqa: E402
from page_test import browser_folder  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
QUERY_BASE = "preset=paper-table1-h1400"


# The explorer marks its first frame (app/gui/gui_app.cpp): its time, not that of the poll that
# saw it, and a poll that costs the page nothing.
FIRST_FRAME = ("!window.foldlabBeforeReload && "
               "performance.getEntriesByName('foldlab: first frame').length ? "
               "performance.getEntriesByName('foldlab: first frame')[0].startTime : null")


# Where a cold load's time goes: the page's own marks (app/web/index.html) and the program's
# arrival, in ms from the start of the navigation.
COLD_STEPS = ("Object.fromEntries(performance.getEntriesByType('mark')"
              ".filter((m) => m.name.startsWith('foldlab: '))"
              ".map((m) => [m.name.slice(9), Math.round(m.startTime)])"
              ".concat(performance.getEntriesByType('resource')"
              ".filter((r) => r.name.endsWith('foldlab.wasm'))"
              ".map((r) => ['program downloaded', Math.round(r.responseEnd)])))")


def poll_first_frame(page):
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        try:
            value = page.tools.evaluate(FIRST_FRAME)
        except RuntimeError:
            value = None  # the reloading page's old context is gone, the new one not yet there
        if value is not None:
            return value
        time.sleep(0.01)
    raise RuntimeError("no first frame within 120 s")


def first_frame_ms(args, root):
    """Cold: a fresh browser profile, nothing cached, the browser just started (its GPU process
    too); first visit: a fresh profile in a browser already showing WebGL elsewhere, as a
    student's is; warm: the first visit's page reloaded, its files and compiled module in the
    browser's caches. Each with the page's steps (COLD_STEPS) of the load before it."""
    results = []
    for gpu_running in (False, True):
        page = Page(args, os.path.join(root, f"gpu{int(gpu_running)}"), f"?{QUERY_BASE}",
                    gpu_running=gpu_running)
        try:
            results.append((poll_first_frame(page), page.tools.evaluate(COLD_STEPS)))
            if gpu_running:
                page.tools.evaluate("window.foldlabBeforeReload = true")
                page.tools.evaluate("location.reload()")
                results.append((poll_first_frame(page), None))
        finally:
            page.close()
    return results


def page_drag(args, root):
    os.makedirs(os.path.join(root, "serve"), exist_ok=True)
    os.symlink(HERE, os.path.join(root, "serve", "bench"))
    page = Page(args, root, f"?play=bench/bench_drag.json&report=1&{QUERY_BASE}")
    try:
        deadline = time.monotonic() + 300
        while time.monotonic() < deadline:
            text = page.tools.evaluate(REPORT_TEXT)
            if text:
                result = json.loads(text)
                if result.get("exit_status") != 0:
                    raise RuntimeError(f"the page's drag run failed: {result}")
                report = result["report"]
                return report["mean_ms"], report["p95_ms"], report["frames"]
            time.sleep(0.2)
        raise RuntimeError("the page's drag run did not end within 300 s")
    finally:
        page.close()


def native_drag(args, root):
    run = subprocess.run(
        [os.path.abspath(args.native), "render", "--play", os.path.join(HERE, "bench_drag.json"),
         "--report",
         "--size", "1280x800", "--preset",
         os.path.join(HERE, "..", "..", "presets", "paper-table1-h1400.json")],
        capture_output=True, text=True, cwd=root, timeout=600,
        env={**os.environ, "XDG_CONFIG_HOME": root, "HOME": root})
    if run.returncode != 0:
        raise RuntimeError(f"foldlab render failed: {run.stderr}")
    report = json.loads(run.stdout[run.stdout.index("{"):])
    return report["mean_ms"], report["p95_ms"], report["frames"]


def solve_ratios(args, extra=()):
    """Per case the fastest of `repeat` runs of each program, run by turns: on a shared machine a
    case's time is its own plus whatever else took the core meanwhile, which the minimum drops.
    `extra` goes to both programs (--field: the tension field's cases)."""
    best = {"native": {}, "wasm": {}}
    commands = {"native": [args.solve_times_native, *extra],
                "wasm": ["node", "--no-experimental-fetch", args.solve_times_wasm, *extra]}
    for _ in range(args.repeat):
        for name, command in commands.items():
            result = json.loads(subprocess.run(command, capture_output=True, text=True,
                                               check=True).stdout)
            if "first_run_us" in result:
                best[name]["first run"] = min(best[name].get("first run", float("inf")),
                                              result["first_run_us"])
            for case in result["cases"]:
                times = best[name]
                times[case["label"]] = min(times.get(case["label"], float("inf")),
                                           case["us_per_solve"])
    labels = [label for label in best["native"] if label != "first run"]
    ratios = [best["wasm"][label] / best["native"][label] for label in labels]
    return (ratios, statistics.median(best["native"][label] for label in labels),
            statistics.median(best["wasm"][label] for label in labels), best)


def site_sizes(site):
    rows = []
    for name in sorted(os.listdir(site)):
        data = open(os.path.join(site, name), "rb").read()
        rows.append((name, len(data), len(gzip.compress(data, 9))))
    return rows


FIRST_FRAME_ROWS = (("first frame, cold (fresh profile, the browser just started)", ""),
                    ("first frame, first visit (fresh profile, a browser already showing WebGL)",
                     "≤ 2000 ms"),
                    ("first frame after a reload, warm", ""))
# The page's steps (app/web/index.html) and the program's (app/gui/gui_app.cpp), in the order
# they come.
COLD_STEP_NAMES = ("page script", "program downloaded", "program ready", "window made",
                   "renderer made", "explorer made",
                   "fonts and style ready", "panels built", "panels drawn", "first frame")


def print_first_frames(runs_by_repeat):
    for index, (label, aim) in enumerate(FIRST_FRAME_ROWS):
        runs = [run[index] for run in runs_by_repeat]
        print(f"| {label} | {', '.join(f'{ms:.0f}' for ms, _ in runs)} ms | {aim} |")
        if runs[0][1] is not None:
            print(f"|   its steps, ms from navigation ({', '.join(COLD_STEP_NAMES)}) | " +
                  "; ".join(", ".join(str(marks.get(step, "?")) for step in COLD_STEP_NAMES)
                            for _, marks in runs) + " | |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--native", required=True)
    parser.add_argument("--solve-times-native", required=True)
    parser.add_argument("--solve-times-wasm", required=True)
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--keep-screenshots", default=None)
    parser.add_argument("--first-frame-only", action="store_true",
                        help="only the first frame's three loads (a few minutes, not half an hour)")
    args = parser.parse_args()
    figures = {}
    with browser_folder("foldlab_bench_") as root:
        figures["first_frame_ms"] = [first_frame_ms(args, os.path.join(root, f"first{i}"))
                                     for i in range(args.repeat)]
        if args.first_frame_only:
            print("| figure | measured | aim |\n|---|---|---|")
            print_first_frames(figures["first_frame_ms"])
            print(json.dumps(figures))
            return 0
        figures["page_drag"] = [page_drag(args, os.path.join(root, f"drag{i}"))
                                for i in range(args.repeat)]
        figures["native_drag"] = []
        for i in range(args.repeat):
            os.makedirs(os.path.join(root, f"native{i}"))
            figures["native_drag"].append(native_drag(args, os.path.join(root, f"native{i}")))
    ratios, native_us, wasm_us, _ = solve_ratios(args)
    figures["solve_ratios"] = ratios
    field_ratios, _, _, field_best = solve_ratios(args, ("--field",))
    figures["field_ratios"] = field_ratios
    figures["field_us"] = field_best
    figures["site"] = site_sizes(args.site)

    geo = statistics.geometric_mean(ratios)
    print("| figure | measured | aim |\n|---|---|---|")
    print_first_frames(figures["first_frame_ms"])
    for name, key in (("page (Chromium, SwiftShader)", "page_drag"),
                      ("desktop (llvmpipe)", "native_drag")):
        runs = figures[key]
        print(f"| frame while dragging, {name} | mean "
              f"{', '.join(f'{m:.1f}' for m, _, _ in runs)} ms; p95 "
              f"{', '.join(f'{p:.1f}' for _, p, _ in runs)} ms ({runs[0][2]} frames) | "
              f"{'≤ 16 ms mean' if key == 'page_drag' else ''} |")
    print(f"| solve, WebAssembly / native | geometric mean {geo:.2f}×, median "
          f"{statistics.median(ratios):.2f}×, {min(ratios):.2f}–{max(ratios):.2f}× over "
          f"{len(ratios)} cases (median {wasm_us:.1f} µs against {native_us:.1f} µs) | ≤ 1.3× |")
    if "first run" in field_best["native"]:
        first = {name: field_best[name]["first run"] / 1000 for name in ("native", "wasm")}
        print(f"| field view's first opening in a fresh process (the engine compiling), "
              f"16 cells | {first['wasm']:.1f} ms in WebAssembly against {first['native']:.1f} ms"
              f" | |")
    field_labels = [label for label in field_best["native"] if label != "first run"]
    for ratio, label in zip(field_ratios, field_labels):
        print(f"| {label}, WebAssembly / native | {ratio:.2f}× "
              f"({field_best['wasm'][label] / 1000:.1f} ms against "
              f"{field_best['native'][label] / 1000:.1f} ms) | ≤ 1.5× |")
    raw = sum(r for _, r, _ in figures["site"])
    packed = sum(g for _, _, g in figures["site"])
    print(f"| site | {raw / 1e6:.2f} MB raw, {packed / 1e6:.2f} MB gzip -9 | ≤ 4 MB gzip |")
    for name, r, g in figures["site"]:
        print(f"|   {name} | {r / 1e6:.2f} MB raw, {g / 1e6:.2f} MB gzip -9 | |")
    print(json.dumps(figures))
    return 0


if __name__ == "__main__":
    sys.exit(main())
