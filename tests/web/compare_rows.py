#!/usr/bin/env python3
"""The paper rows in WebAssembly against the desktop program: n and n_capped equal, z_max and Q
bit-identical or within 1e-12 (relative), for both methods, every row `foldlab compare` knows."""
import argparse
import json
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--native", required=True)
    parser.add_argument("--presets", required=True)
    parser.add_argument("--wasm", nargs=argparse.REMAINDER, required=True)
    args = parser.parse_args()
    native = json.loads(subprocess.run(
        [args.native, "compare", "--json"], check=True, capture_output=True, text=True,
        env={"FOLDLAB_PRESETS_DIR": args.presets, "PATH": "/usr/bin:/bin"}).stdout)["rows"]
    wasm = json.loads(subprocess.run(
        args.wasm + [args.presets], check=True, capture_output=True, text=True).stdout)
    wasm_rows = {row["name"]: row for row in wasm}
    problems = []
    identical = 0
    for row in native:
        other = wasm_rows.get(row["name"])
        if other is None:
            problems.append(f"{row['name']}: no row from WebAssembly")
            continue
        for method in ("paper", "exact"):
            for key in ("n", "n_capped", "z_max_mm", "Q"):
                a, b = row[method][key], other[method][key]
                if a == b:
                    identical += 1
                elif isinstance(a, float) and isinstance(b, float) and \
                        abs(a - b) <= 1e-12 * max(abs(a), abs(b)):
                    pass
                else:
                    problems.append(f"{row['name']} {method} {key}: native {a!r}, wasm {b!r}")
    if len(wasm_rows) != len(native):
        problems.append(f"{len(native)} rows native, {len(wasm_rows)} in WebAssembly")
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{len(native)} rows, both methods: {identical} of {len(native) * 8} values "
          f"bit-identical, {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
