#!/usr/bin/env python3
"""The page in a real browser: serves build-web/site/ and tests/play/ from a temporary folder on
127.0.0.1, opens the page in headless Chromium (WebGL2 through SwiftShader) with an address, reads
<pre id="foldlab-report"> from the DOM and checks it. Exit 0 when every check holds.

  page_test.py --site DIR --play-dir DIR --query '?play=play/slider_h.json&report=1...'
               [--expect KEY=JSON ...] [--expect-address TEXT] [--expect-address-is-link]
               [--expect-result KEY=JSON ...] [--expect-prefix KEY=JSON ...] [--page FILE]
               [--serve NAME=PATH ...] [--checks FILE] [--chromium PATH]
KEY is a dotted path into the report (`gui --report`'s JSON); a number in it picks a list's
entry. The address is the page's fragment when the run ended (location.hash): --expect-address
compares it with TEXT, and --expect-address-is-link with the explorer's link then ('#' and the
report's `link`). --expect-result looks into the page's whole result instead (`downloads`, and
with reload.html `earlier` and `storage`); --expect-prefix checks that the text there starts with
the JSON string given. --checks reads such checks from a JSON file ({"report": {KEY: VALUE},
"result": {...}, "prefix": {KEY: TEXT}}, and "query" in place of --query), free of a shell's or
CMake's quoting. --page opens FILE (served beside index.html, e.g. tests/web/reload.html)
instead of index.html; --serve serves PATH as NAME beside it. Chromium's home folder is a temporary one: downloads land there."""
import argparse
import contextlib
import html
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time


@contextlib.contextmanager
def browser_folder(prefix):
    """A temporary folder for a browser's profile and files, removed afterwards. Chromium's helper
    processes may still write the profile ("Default") for a moment after the browser has exited,
    so the removal is tried again for a few seconds rather than failing a test that passed."""
    root = tempfile.mkdtemp(prefix=prefix)
    try:
        yield root
    finally:
        deadline = time.monotonic() + 10
        while True:
            try:
                shutil.rmtree(root)
                break
            except FileNotFoundError:
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.2)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def serve_folder(folder, port):
    """A static server of `folder` on 127.0.0.1:`port`, once it answers; the caller ends it."""
    server = subprocess.Popen(
        [sys.executable, "-m", "http.server", "--bind", "127.0.0.1", str(port), "-d", folder],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(100):
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.1).close()
            break
        except OSError:
            time.sleep(0.05)
    return server


def lookup(report, dotted):
    value = report
    for part in dotted.split("."):
        if isinstance(value, list) and part.isdigit() and int(part) < len(value):
            value = value[int(part)]
        elif isinstance(value, dict) and part in value:
            value = value[part]
        else:
            raise KeyError(dotted)
    return value


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--play-dir", required=True)
    parser.add_argument("--query", help="the address after the page's name; else the checks "
                        "file's \"query\"")
    parser.add_argument("--expect", action="append", default=[])
    parser.add_argument("--expect-address")
    parser.add_argument("--expect-address-is-link", action="store_true")
    parser.add_argument("--expect-result", action="append", default=[])
    parser.add_argument("--expect-prefix", action="append", default=[])
    parser.add_argument("--checks", help="a JSON file: {\"report\": {KEY: VALUE}, \"result\": "
                        "{KEY: VALUE}, \"prefix\": {KEY: TEXT}}, as the options of those names, "
                        "and optionally \"query\"")
    parser.add_argument("--page", default="index.html")
    parser.add_argument("--serve", action="append", default=[],
                        help="NAME=PATH: PATH served as NAME beside the page too")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--budget-ms", type=int, default=120000)
    args = parser.parse_args()
    more = {}
    if args.checks:
        with open(args.checks, encoding="utf-8") as f:
            more = json.load(f)
    if args.query is None:
        args.query = more.get("query")
        if args.query is None:
            parser.error("--query, or a checks file with \"query\", is required")

    with browser_folder("foldlab_page_") as root:
        serve = os.path.join(root, "serve")
        os.mkdir(serve)
        for name in os.listdir(args.site):
            os.symlink(os.path.abspath(os.path.join(args.site, name)), os.path.join(serve, name))
        os.symlink(os.path.abspath(args.play_dir), os.path.join(serve, "play"))
        for extra in args.serve:
            name, _, path = extra.partition("=")
            os.symlink(os.path.abspath(path), os.path.join(serve, name))
        page = os.path.basename(args.page)
        if not os.path.exists(os.path.join(serve, page)):
            os.symlink(os.path.abspath(args.page), os.path.join(serve, page))
        home = os.path.join(root, "home")
        os.mkdir(home)
        port = free_port()
        server = serve_folder(serve, port)
        try:
            url = f"http://127.0.0.1:{port}/{page}{args.query}"
            started = time.monotonic()
            dom = subprocess.run(
                [args.chromium, "--headless=new", "--no-sandbox", "--use-gl=angle",
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-sandbox",
                 "--no-first-run", "--disable-extensions", "--window-size=1280,800",
                 f"--user-data-dir={os.path.join(root, 'profile')}",
                 f"--virtual-time-budget={args.budget_ms}", "--dump-dom", url],
                capture_output=True, text=True, timeout=300,
                env=dict(os.environ, HOME=home, XDG_CONFIG_HOME=os.path.join(home, ".config"),
                         XDG_DOWNLOAD_DIR=os.path.join(home, "Downloads"))).stdout
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
    if more:
        for option, entries in (("expect", "report"), ("expect_result", "result"),
                                ("expect_prefix", "prefix")):
            getattr(args, option).extend(f"{key}={json.dumps(value)}"
                                         for key, value in more.get(entries, {}).items())
    checks = ([(report, e, False) for e in args.expect] +
              [(result, e, False) for e in args.expect_result] +
              [(result, e, True) for e in args.expect_prefix])
    for where, expect, prefix in checks:
        key, _, wanted = expect.partition("=")
        try:
            value = lookup(where, key)
        except KeyError:
            problems.append(f"{key}: not in the {'report' if where is report else 'result'}")
            continue
        wanted_value = json.loads(wanted)
        if (not prefix and value != wanted_value) or (
                prefix and not (isinstance(value, str) and value.startswith(wanted_value))):
            problems.append(f"{key} is {json.dumps(value)}, expected "
                            f"{'a text starting ' if prefix else ''}{wanted}")
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
