#!/usr/bin/env python3
"""The page in a real browser: serves build-web/site/ and tests/play/ from a temporary folder on
127.0.0.1, opens the page in headless Chromium (WebGL2 through SwiftShader) with an address, reads
<pre id="foldlab-report"> from the DOM and checks it. Exit 0 when every check holds.

  page_test.py --site DIR --play-dir DIR --query '?play=play/slider_h.json&report=1...'
               [--expect KEY=JSON ...] [--expect-address TEXT] [--expect-address-is-link]
               [--chromium PATH]
KEY is a dotted path into the report (`gui --report`'s JSON). The address is the page's fragment
when the run ended (location.hash): --expect-address compares it with TEXT, and
--expect-address-is-link with the explorer's link then ('#' and the report's `link`)."""
import argparse
import html
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def lookup(report, dotted):
    value = report
    for part in dotted.split("."):
        if not isinstance(value, dict) or part not in value:
            raise KeyError(dotted)
        value = value[part]
    return value


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--play-dir", required=True)
    parser.add_argument("--query", required=True)
    parser.add_argument("--expect", action="append", default=[])
    parser.add_argument("--expect-address")
    parser.add_argument("--expect-address-is-link", action="store_true")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--budget-ms", type=int, default=120000)
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(prefix="foldlab_page_") as root:
        serve = os.path.join(root, "serve")
        os.mkdir(serve)
        for name in os.listdir(args.site):
            os.symlink(os.path.abspath(os.path.join(args.site, name)), os.path.join(serve, name))
        os.symlink(os.path.abspath(args.play_dir), os.path.join(serve, "play"))
        port = free_port()
        server = subprocess.Popen(
            [sys.executable, "-m", "http.server", "--bind", "127.0.0.1", str(port), "-d", serve],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            for _ in range(100):
                try:
                    socket.create_connection(("127.0.0.1", port), timeout=0.1).close()
                    break
                except OSError:
                    time.sleep(0.05)
            url = f"http://127.0.0.1:{port}/index.html{args.query}"
            started = time.monotonic()
            dom = subprocess.run(
                [args.chromium, "--headless=new", "--no-sandbox", "--use-gl=angle",
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-sandbox",
                 "--no-first-run", "--disable-extensions", "--window-size=1280,800",
                 f"--user-data-dir={os.path.join(root, 'profile')}",
                 f"--virtual-time-budget={args.budget_ms}", "--dump-dom", url],
                capture_output=True, text=True, timeout=300).stdout
            seconds = time.monotonic() - started
        finally:
            server.terminate()
            server.wait()

    match = re.search(r'<pre id="foldlab-report">(.*?)</pre>', dom, re.S)
    text = html.unescape(match.group(1)) if match else ""
    if not text.strip():
        status = re.search(r'<div id="foldlab-status"[^>]*>(.*?)</div>', dom, re.S)
        log = re.search(r'<pre id="foldlab-log">(.*?)</pre>', dom, re.S)
        print(f"{url}: no report after {seconds:.1f} s; the page says: "
              f"{html.unescape(status.group(1)) if status else '(nothing)'}\n"
              f"{html.unescape(log.group(1)) if log else ''}", file=sys.stderr)
        return 1
    result = json.loads(text)
    problems = []
    if result.get("exit_status") != 0:
        problems.append(f"exit status {result.get('exit_status')}: "
                        + "\n".join(result.get("stderr") or []))
    report = result.get("report") or {}
    for expect in args.expect:
        key, _, wanted = expect.partition("=")
        try:
            value = lookup(report, key)
        except KeyError:
            problems.append(f"{key}: not in the report")
            continue
        if value != json.loads(wanted):
            problems.append(f"{key} is {json.dumps(value)}, expected {wanted}")
    address = result.get("address")
    if args.expect_address is not None and address != args.expect_address:
        problems.append(f"the address is {address!r}, expected {args.expect_address!r}")
    if args.expect_address_is_link and address != "#" + str(report.get("link")):
        problems.append(f"the address is {address!r}, the explorer's link #{report.get('link')}")
    for problem in problems:
        print(f"{url}: {problem}", file=sys.stderr)
    print(f"{url}: {'ok' if not problems else 'FAILED'} in {seconds:.1f} s")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
