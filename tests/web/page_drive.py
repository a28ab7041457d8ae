#!/usr/bin/env python3
"""The page driven as a person's hands drive it: headless Chromium (SwiftShader WebGL2) with its
DevTools protocol, real mouse and touch events at CSS pixels, the explorer's state read at any
time through the page's Module.foldlabState() (what `gui --report` prints), screenshots.

  page_drive.py --site DIR --check NAME [--chromium PATH] [--keep-screenshots DIR]
                [--native FOLDLAB --presets DIR]

Checks (each its own ctest):
  dpr       devicePixelRatio 2 beside 1: the canvas backing store twice as big, the layout the
            same in CSS pixels, text rasterised at twice the size, a real click hitting its slider,
            a wheel notch zooming the 3D view one step
  touch     a tap on a slider focuses it; a one-finger drag moves a slider and orbits the 3D view; a
            two-finger pinch zooms it by the pinch's ratio; holding a finger on a slider opens its
            typed value with the on-screen keyboard's field focused (asking for the number
            keyboard), and typed text arrives
  touch_first  a touch never jumps from where the last one was: a tap on the 3D view after one
            elsewhere leaves its camera, a tap on the fold plot its ranges; two equal swipes turn
            the cloth equally; a pinch after another touch zooms and does not turn
  fingers   with a touch screen the hints speak of fingers (a played script reads the drawn
            words), every slider is 44 CSS px tall, a drag four slider heights away from a slider
            moves it a quarter as far, and two fingers scroll a panel
  phone     at 390 x 844 CSS px (ratio 3) with touch: one view at a time, switched by the row of
            views under the read-out; no "Back to the tiles"
  phone_flows  the phone opened from a link, driven by touch through every view: orbit, pinch,
            a slider dragged (the toast says so), a long press and typed value; nothing cut or
            wrapped inside a word, no target below 44 CSS px; then the phone held sideways
  tablet    1024 x 768 CSS px (ratio 2), touch, from a link: the tiles, a drag, a long press and
            typed value, orbit, pinch, the fold plot presented and back; nothing cut, targets
  scheme    the theme follows the browser's prefers-color-scheme and the text size its default
            font size, with no stored session
  layout    a tile resized with the mouse (the fold plot's grip) is where it was after a reload
  address   the link in the address edited after the page opened: the page opens the edited link
  clipboard Ctrl+V pastes the browser's clipboard into a typed value, Ctrl+C copies one onto it
  picture   the page's picture of a preset beside the desktop's (--native: `render`) at the same
            size and pixel ratio 1: at most PICTURE_MAX_OVER pixels differ by more than
            PICTURE_THRESHOLD in a channel (png_compare.py)
  regime_map  tests/web/regime_map_slices.json played in real time (a virtual clock stands still
            while a slice runs, so it would run the whole map in one frame): three frames after
            the tab opens the map is part done, so frames keep coming while it runs; at the end
            its cells are those of the desktop program (--native: `render --play
            regime_map_done.json`): the digest of every cell's n, regime and flags, the sum of n,
            and the sum of z_max (floats, to 1e-9 of it)
Exit 0 when every check holds. The DevTools websocket is spoken here (RFC 6455, client side): the
test needs nothing beyond Python's standard library."""
import argparse
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request

from page_test import browser_folder, free_port, serve_folder


class DevTools:
    """One websocket to a page target; send() waits for its answer, events are dropped."""

    def __init__(self, url):
        rest = url[len("ws://"):]
        host_port, path = rest.split("/", 1)
        host, port = host_port.split(":")
        self.sock = socket.create_connection((host, int(port)), timeout=60)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall((f"GET /{path} HTTP/1.1\r\nHost: {host_port}\r\nUpgrade: websocket\r\n"
                           f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
                           "Sec-WebSocket-Version: 13\r\n\r\n").encode())
        head = b""
        while b"\r\n\r\n" not in head:
            chunk = self.sock.recv(1)
            if not chunk:
                raise RuntimeError("DevTools closed the connection during the handshake")
            head += chunk
        if b" 101 " not in head.split(b"\r\n")[0]:
            raise RuntimeError("DevTools refused the websocket: " + head.decode(errors="replace"))
        self.next_id = 0

    def _read(self, n):
        data = b""
        while len(data) < n:
            chunk = self.sock.recv(n - len(data))
            if not chunk:
                raise RuntimeError("DevTools closed the connection")
            data += chunk
        return data

    def _message(self):
        payload = b""
        while True:
            b0, b1 = self._read(2)
            length = b1 & 0x7F
            if length == 126:
                length = struct.unpack(">H", self._read(2))[0]
            elif length == 127:
                length = struct.unpack(">Q", self._read(8))[0]
            payload += self._read(length)
            if b0 & 0x80:
                return payload.decode()

    def send(self, method, **params):
        self.next_id += 1
        data = json.dumps({"id": self.next_id, "method": method, "params": params}).encode()
        mask = os.urandom(4)
        header = bytes([0x81])
        if len(data) < 126:
            header += bytes([0x80 | len(data)])
        elif len(data) < 65536:
            header += bytes([0x80 | 126]) + struct.pack(">H", len(data))
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", len(data))
        masked = bytes(b ^ mask[i % 4] for i, b in enumerate(data))
        self.sock.sendall(header + mask + masked)
        while True:
            message = json.loads(self._message())
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})

    def evaluate(self, expression):
        result = self.send("Runtime.evaluate", expression=expression, returnByValue=True,
                           awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")


class Page:
    """A served site and one headless Chromium showing it."""

    def __init__(self, args, root, query, flags=(), play_dir=None, touch=False, metrics=None,
                 gpu_running=False):
        self.root = root
        serve = os.path.join(root, "serve")
        os.makedirs(serve, exist_ok=True)
        if play_dir:
            os.symlink(os.path.abspath(play_dir), os.path.join(serve, "play"))
        for name in os.listdir(args.site):
            target = os.path.join(serve, name)
            if not os.path.exists(target):
                os.symlink(os.path.abspath(os.path.join(args.site, name)), target)
        port = free_port()
        self.server = serve_folder(serve, port)
        profile = tempfile.mkdtemp(prefix="profile_", dir=root)
        self.url = f"http://127.0.0.1:{port}/index.html{query}"
        self.browser = subprocess.Popen(
            [args.chromium, "--headless=new", "--no-sandbox", "--use-gl=angle",
             "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-sandbox",
             "--no-first-run", "--disable-extensions", "--window-size=1280,800",
             "--remote-debugging-port=0", f"--user-data-dir={profile}", *flags, "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        active = os.path.join(profile, "DevToolsActivePort")
        deadline = time.monotonic() + 60
        while not os.path.exists(active) or len(open(active).read().split()) < 2:
            if time.monotonic() > deadline or self.browser.poll() is not None:
                raise RuntimeError("Chromium did not open its DevTools port")
            time.sleep(0.1)
        debug_port = open(active).read().split()[0]
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{debug_port}/json/list"))
        page = next(t for t in targets if t["type"] == "page")
        self.tools = DevTools(page["webSocketDebuggerUrl"])
        self.tools.send("Page.enable")
        if touch:
            # A touch screen from the first frame: (pointer: coarse) holds before the page starts.
            self.tools.send("Emulation.setTouchEmulationEnabled", enabled=True, maxTouchPoints=5)
        if metrics:
            # A phone's or tablet's screen: (width, height) in CSS px and its pixel ratio.
            width, height, ratio = metrics
            self.tools.send("Emulation.setDeviceMetricsOverride", width=width, height=height,
                            deviceScaleFactor=ratio, mobile=True)
        if gpu_running:
            # A browser already showing WebGL elsewhere (its GPU process up), as a student's is:
            # another origin's page, so nothing of this site is cached or compiled by it.
            self.tools.send("Page.navigate", url="data:text/html,<canvas></canvas><script>"
                            "window.gl = document.querySelector('canvas').getContext('webgl2')"
                            "</script>")
            deadline = time.monotonic() + 60
            while self.tools.evaluate("Boolean(window.gl)") is not True:
                if time.monotonic() > deadline:
                    raise RuntimeError("no WebGL2 context on the warm-up page")
                time.sleep(0.05)
        self.tools.send("Page.navigate", url=self.url)

    def close(self):
        for process in (self.browser, self.server):
            process.terminate()
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()

    def state(self):
        return self.tools.evaluate("window.Module && Module.foldlabState ? Module.foldlabState() "
                                   ": null")

    def wait(self, what, condition, timeout_s=90):
        deadline = time.monotonic() + timeout_s
        while True:
            state = self.state()
            if state and condition(state):
                return state
            if time.monotonic() > deadline:
                log = self.tools.evaluate("document.getElementById('foldlab-log').textContent")
                raise AssertionError(f"{what}: not within {timeout_s} s; the page's log: {log}")
            time.sleep(0.1)

    def settle(self, frames=3, timeout_s=120):
        """Waits on the page's own state, never on a time: until the page has passed on all the
        input it was given (its touch handling's queue, Module.foldlabPendingInput, is empty),
        and then until the explorer has drawn `frames` more frames or has come to rest
        (Module.foldlabResting: the frames after the last input drawn and no input unseen; a
        resting explorer draws nothing until the next input). `timeout_s` only says when the
        page is stuck."""
        deadline = time.monotonic() + timeout_s
        start = None
        while True:
            done = self.tools.evaluate(
                "(() => { const s = Module.foldlabState();"
                " return [Module.foldlabPendingInput ? Module.foldlabPendingInput() : 0,"
                " Module.foldlabResting(), s.renderer.frames]; })()")
            pending, resting, frames_drawn = done
            if pending == 0:
                if start is None:
                    start = frames_drawn
                if resting or frames_drawn >= start + frames:
                    return self.state()
            if time.monotonic() > deadline:
                raise AssertionError(f"the page did not settle within {timeout_s} s "
                                     f"({pending} inputs pending, {frames_drawn} frames)")
            time.sleep(0.02)

    def wait_for(self, what, expression, timeout_s=120):
        """Waits until the JavaScript `expression` is true in the page."""
        deadline = time.monotonic() + timeout_s
        last_error = None
        while True:
            try:
                if self.tools.evaluate(expression):
                    return
            except RuntimeError as error:
                # While the page loads again its old context is gone and the new one not yet
                # there ("Execution context was destroyed"): asked again, as a person waits.
                last_error = error
            if time.monotonic() > deadline:
                raise AssertionError(f"{what}: not within {timeout_s} s (last: {last_error})")
            time.sleep(0.02)

    def mouse(self, kind, x, y, buttons=0, modifiers=0):
        self.tools.send("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left",
                        buttons=buttons, clickCount=1, modifiers=modifiers)

    def reload_by(self, what, action):
        """Runs `action` (a JavaScript expression) that makes the page load again, and waits for
        the new page's first frames: the old page's flag is gone once the new one runs."""
        self.tools.evaluate("window.foldlabBeforeReload = true")
        self.tools.evaluate(action)
        self.wait_for(what, "!window.foldlabBeforeReload && window.Module && Module.foldlabState && "
                            "Module.foldlabState() && Module.foldlabState().renderer.frames >= 5")
        return self.settle()

    def ctrl(self, down):
        """The Ctrl key pressed or released: the page's GLFW knows a modifier by its key."""
        self.tools.send("Input.dispatchKeyEvent", type="rawKeyDown" if down else "keyUp",
                        windowsVirtualKeyCode=17, key="Control", code="ControlLeft",
                        modifiers=2 if down else 0)
        self.settle(1)

    def key(self, key, code, key_code, modifiers=0, commands=()):
        """A key pressed and released, as a keyboard does: `modifiers` 2 is Ctrl (held, its own
        key pressed first), `commands` the editing command the browser runs for it ("paste")."""
        if modifiers & 2:
            self.ctrl(True)
        self.tools.send("Input.dispatchKeyEvent", type="rawKeyDown", windowsVirtualKeyCode=key_code,
                        key=key, code=code, modifiers=modifiers, commands=list(commands))
        self.settle(1)
        self.tools.send("Input.dispatchKeyEvent", type="keyUp", windowsVirtualKeyCode=key_code,
                        key=key, code=code, modifiers=modifiers)
        if modifiers & 2:
            self.settle(1)
            self.ctrl(False)

    def open_typed_value(self, state, key):
        """Ctrl+click on a slider: its typed value opens, its text selected."""
        x, y = slider_css(state, key, 1)
        self.mouse("mouseMoved", x, y)
        self.ctrl(True)
        self.mouse("mousePressed", x, y, 1, modifiers=2)
        self.settle(1)
        self.mouse("mouseReleased", x, y, 0, modifiers=2)
        self.settle(1)
        self.ctrl(False)
        return self.settle()

    def touch(self, kind, points, at_s=None):
        """A touch event stamped `at_s` (seconds since the epoch; now by default): the page judges
        a long press by its events' own times, so a test gives the finger's timeline, which a
        busy machine's late delivery (each event waits for the page to take the last) cannot
        stretch. Returns the stamp."""
        stamp = time.time() if at_s is None else at_s
        self.tools.send("Input.dispatchTouchEvent", type=kind, timestamp=stamp,
                        touchPoints=[{"x": x, "y": y, "id": i} for i, (x, y) in enumerate(points)])
        return stamp

    def tap(self, x, y):
        """A finger down and up 50 ms later at (x, y), and the page settled."""
        down_s = self.touch("touchStart", [(x, y)])
        self.touch("touchEnd", [], down_s + 0.05)
        return self.settle()

    def swipe(self, points):
        """A finger down at the first point and through the others, 30 ms apart, then up."""
        down_s = self.touch("touchStart", [points[0]])
        for step, point in enumerate(points[1:], 1):
            self.touch("touchMove", [point], down_s + 0.03 * step)
            self.settle(1)
        self.touch("touchEnd", [], down_s + 0.03 * len(points))
        return self.settle()

    def screenshot(self, path, clip=None):
        """The page as a PNG (device pixels); `clip` (x, y, w, h) in CSS pixels: that part."""
        extra = {}
        if clip:
            extra["clip"] = dict(zip(("x", "y", "width", "height"), clip), scale=1)
        data = base64.b64decode(
            self.tools.send("Page.captureScreenshot", format="png", **extra)["data"])
        with open(path, "wb") as f:
            f.write(data)
        return struct.unpack(">II", data[16:24])  # IHDR: width, height


def ready(page):
    return page.wait("the first frames", lambda s: s["renderer"]["frames"] >= 5)


def check(problems, ok, text):
    if not ok:
        problems.append(text)


def slider_css(state, key, ratio, fraction=None):
    """A slider's handle (or a point at `fraction` of its width) in CSS pixels."""
    slider = state["sliders"][key]
    if fraction is None:
        x, y = slider["handle"]
    else:
        x = slider["left"] + fraction * (slider["right"] - slider["left"])
        y = slider["handle"][1]
    return x / ratio, y / ratio


def panel_centre_css(state, key, ratio):
    rect = state["layout"]["panels"][key]
    return (rect["x"] + rect["w"] / 2) / ratio, (rect["y"] + rect["h"] * 0.6) / ratio


QUERY = "?preset=paper-table1-h1400#L=4000"
# What a scripted run reported, or '' (also while the page is still about:blank).
REPORT_TEXT = "(document.getElementById('foldlab-report') || {}).textContent || ''"


def check_dpr(args, root, problems):
    states = {}
    for ratio in (1, 2):
        page = Page(args, os.path.join(root, f"dpr{ratio}"), QUERY,
                    [f"--force-device-scale-factor={ratio}"])
        try:
            state = ready(page)
            states[ratio] = state
            shot = os.path.join(page.root, f"page-dpr{ratio}.png")
            size = page.screenshot(shot)
            if args.keep_screenshots:
                shutil.copy(shot, args.keep_screenshots)
                page.screenshot(os.path.join(args.keep_screenshots, f"page-dpr{ratio}-part.png"),
                                (0, 20, 400, 200))
            # The window's viewport in CSS pixels (headless Chromium's window keeps some of its
            # 1280 x 800 for itself), the same at both ratios.
            css = page.tools.evaluate("[innerWidth, innerHeight, devicePixelRatio]")
            check(problems, css[2] == ratio, f"DPR {ratio}: the page's devicePixelRatio is {css[2]}")
            check(problems, list(size) == [css[0] * ratio, css[1] * ratio],
                  f"DPR {ratio}: the screenshot is {size[0]}x{size[1]} for a viewport of "
                  f"{css[0]}x{css[1]} CSS px")
            check(problems, state["display"] == [css[0] * ratio, css[1] * ratio],
                  f"DPR {ratio}: the explorer's display is {state['display']}")
            check(problems, state["appearance"]["pixel_ratio"] == ratio,
                  f"DPR {ratio}: the explorer's pixel ratio is {state['appearance']['pixel_ratio']}")
            if ratio == 2:
                # A real click (CSS pixels) at a quarter of the h slider lands on it: it takes
                # the focus and leaves the value. Pressed there and dragged 12 CSS px, the handle
                # follows the pointer.
                x, y = slider_css(state, "h", ratio, 0.25)
                h_before = state["parameters"]["h_mm"]
                page.mouse("mouseMoved", x, y)
                page.mouse("mousePressed", x, y, 1)
                page.mouse("mouseReleased", x, y)
                after = page.settle()
                check(problems, after["parameters"]["h_mm"] == h_before,
                      f"DPR 2: a click on the h slider moved h to {after['parameters']['h_mm']}")
                page.mouse("mousePressed", x, y, 1)
                for step in range(1, 5):
                    page.mouse("mouseMoved", x + 3 * step, y, 1)
                    page.settle(1)
                page.mouse("mouseReleased", x + 12, y)
                after = page.settle()
                handle_x = after["sliders"]["h"]["handle"][0] / ratio
                check(problems, after["parameters"]["h_mm"] != h_before,
                      "DPR 2: a drag on the h slider left h as it was")
                check(problems, abs(handle_x - (x + 12)) <= 3,
                      f"DPR 2: dragged to x = {x + 12:.1f} CSS px, the handle is at {handle_x:.1f}")
                # One notch of the wheel up over the 3D view: one zoom step in (emscripten's GLFW
                # alone would give a hundred steps, the wrong way).
                cx, cy = panel_centre_css(after, "cloth", ratio)
                page.mouse("mouseMoved", cx, cy)
                before = page.settle()["camera"]["distance_mm"]
                page.tools.send("Input.dispatchMouseEvent", type="mouseWheel", x=cx, y=cy,
                                deltaX=0, deltaY=-100)
                zoomed = page.settle()["camera"]["distance_mm"] / before
                check(problems, abs(zoomed - 0.85) < 1e-3,
                      f"DPR 2: a wheel notch up left the 3D view at {zoomed:.4f} of its distance, "
                      "not 0.85")
        finally:
            page.close()
    one, two = states[1], states[2]
    for key, rect in one["layout"]["panels"].items():
        other = two["layout"]["panels"].get(key)
        if other is None:
            problems.append(f"DPR 2: no panel {key}")
            continue
        for side in ("x", "y", "w", "h"):
            check(problems, abs(other[side] / 2 - rect[side]) <= 2,
                  f"DPR 2: {key}.{side} is {other[side] / 2} CSS px, at DPR 1 {rect[side]}")


def check_touch(args, root, problems):
    # A touch screen from the start: its sliders a finger's height tall, which leaves t, E and w
    # in sight in the Parameters panel at this size (h and L below them, scrolled away).
    page = Page(args, os.path.join(root, "touch"), QUERY, touch=True)
    try:
        state = ready(page)
        # A tap is a click: on a slider it takes the focus and leaves the value.
        x, y = slider_css(state, "t", 1, 0.75)
        t_before = state["parameters"]["t_mm"]
        # The finger lifts 50 ms after it touched, whenever the page gets to either event.
        down_s = page.touch("touchStart", [(x, y)])
        page.touch("touchEnd", [], down_s + 0.05)
        state = page.settle()
        check(problems, state["parameters"]["t_mm"] == t_before,
              f"a tap at 3/4 of the t slider moved t to {state['parameters']['t_mm']} "
              f"(was {t_before})")
        # A one-finger drag on a slider drags it. Every move is longer than the page's still
        # finger (10 px), so that a slow machine's frames cannot turn the drag into a long press.
        x, y = slider_css(state, "w", 1)
        w_before = state["parameters"]["w_N_per_mm2"]
        # 12 px every 30 ms.
        down_s = page.touch("touchStart", [(x, y)])
        for step in range(1, 6):
            page.touch("touchMove", [(x + 12 * step, y)], down_s + 0.03 * step)
            page.settle(1)
        page.touch("touchEnd", [], down_s + 0.18)
        state = page.settle()
        check(problems, state["parameters"]["w_N_per_mm2"] > w_before,
              f"a drag to the right on the w slider left w at {state['parameters']['w_N_per_mm2']}")
        # A one-finger drag on the 3D view orbits it.
        cx, cy = panel_centre_css(state, "cloth", 1)
        yaw_before = state["camera"]["yaw_rad"]
        down_s = page.touch("touchStart", [(cx, cy)])
        for step in range(1, 6):
            page.touch("touchMove", [(cx + 12 * step, cy)], down_s + 0.03 * step)
            page.settle(1)
        page.touch("touchEnd", [], down_s + 0.18)
        state = page.settle()
        check(problems, state["camera"]["yaw_rad"] < yaw_before - 0.1,
              f"a drag on the 3D view left its yaw at {state['camera']['yaw_rad']} ({yaw_before})")
        # Two fingers spreading from 60 to 120 px apart: the view comes twice as close.
        distance_before = state["camera"]["distance_mm"]
        down_s = page.touch("touchStart", [(cx - 30, cy), (cx + 30, cy)])
        for step in range(1, 7):
            page.touch("touchMove", [(cx - 30 - 5 * step, cy), (cx + 30 + 5 * step, cy)],
                       down_s + 0.03 * step)
            page.settle(1)
        page.touch("touchEnd", [], down_s + 0.21)
        state = page.settle()
        ratio = state["camera"]["distance_mm"] / distance_before
        check(problems, abs(ratio - 0.5) < 0.02,
              f"a pinch from 60 to 120 px left the distance at {ratio:.3f} of what it was, not 0.5")
        # Holding a finger on the t slider opens its typed value; the keyboard's field has focus
        # and what the keyboard types (an IME's text, no key events) replaces the value's text,
        # which the field opens selected.
        x, y = slider_css(state, "t", 1)
        page.touch("touchStart", [(x, y)])
        # The finger stays down until the page has turned it into a Ctrl+click (its timer, then
        # frames): on a busy machine the lift could otherwise reach the page before the timer.
        page.wait_for("the long press's Ctrl+click",
                      "document.activeElement && document.activeElement.id === 'foldlab-keyboard'")
        page.touch("touchEnd", [])
        page.settle()
        focused = page.tools.evaluate("document.activeElement && document.activeElement.id")
        check(problems, focused == "foldlab-keyboard",
              f"after a long press on t the focus is on {focused!r}, not the keyboard's field")
        mode = page.tools.evaluate("document.getElementById('foldlab-keyboard').inputMode")
        check(problems, mode == "decimal",
              f"a slider's typed value asks for the {mode!r} keyboard, not the number keyboard")
        page.tools.send("Input.insertText", text="0.05cm")
        page.settle(6)
        page.tools.send("Input.dispatchKeyEvent", type="rawKeyDown", windowsVirtualKeyCode=13,
                        key="Enter", code="Enter")
        page.tools.send("Input.dispatchKeyEvent", type="keyUp", windowsVirtualKeyCode=13,
                        key="Enter", code="Enter")
        state = page.settle()
        check(problems, abs(state["parameters"]["t_mm"] - 0.5) < 1e-12,
              "typed 0.05cm into t through the keyboard's field: t is "
              f"{state['parameters']['t_mm']}")
        focused = page.tools.evaluate("document.activeElement && document.activeElement.id")
        check(problems, focused != "foldlab-keyboard", "the keyboard's field keeps the focus")
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-touch.png"))
    finally:
        page.close()


def camera_of(state):
    return tuple(state["camera"][key] for key in ("yaw_rad", "pitch_rad", "distance_mm"))


def check_touch_first(args, root, problems):
    """A touch starts where the finger is: the explorer sees the pointer there a frame before the
    press, so no view turns or pans by the way from the last touch to this one."""
    page = Page(args, os.path.join(root, "touch_first"), QUERY, touch=True)
    try:
        state = ready(page)
        check(problems, state["appearance"]["coarse_pointer"],
              "with touch emulation the explorer does not take the pointer for a finger")
        cx, cy = panel_centre_css(state, "cloth", 1)
        # A tap on a slider (it takes the focus and leaves the value), then one on the 3D view,
        # far from it: the camera stays. (Sliders a finger's height tall leave t, E and w in
        # sight at this size.)
        state = page.tap(*slider_css(state, "t", 1))
        before = camera_of(state)
        state = page.tap(cx, cy)
        check(problems, camera_of(state) == before,
              f"a tap on the 3D view after one on the t slider moved the camera from "
              f"(yaw, pitch, distance) {before} to {camera_of(state)}")
        # A tap on a slider, then one on the fold plot: its ranges stay, still following the data.
        state = page.tap(*slider_css(state, "E", 1))
        plot_before = state["fold_plot"]
        px, py = panel_centre_css(state, "fold_plot", 1)
        state = page.tap(px, py)
        plot_after = state["fold_plot"]
        check(problems, plot_after["x_auto"] and plot_after["y_auto"] and all(
            abs(a - b) <= 1e-9 * max(1.0, abs(b))
            for key in ("x_mm", "y_mm") for a, b in zip(plot_after[key], plot_before[key])),
              f"a tap on the fold plot after one on the E slider moved its ranges from "
              f"{plot_before} to {plot_after}")
        # Two equal swipes of 24 px from one spot turn the cloth equally (the second used to
        # jump back to its start first and turn nothing).
        turns = []
        for _ in range(2):
            yaw_before = state["camera"]["yaw_rad"]
            state = page.swipe([(cx, cy), (cx + 12, cy), (cx + 24, cy)])
            turns.append(state["camera"]["yaw_rad"] - yaw_before)
        check(problems, abs(turns[0]) > 0.05 and abs(turns[1] - turns[0]) <= 1e-3 * abs(turns[0]),
              f"two equal 24 px swipes turned the cloth by {turns[0]:.5f} and {turns[1]:.5f} rad")
        # A pinch after another touch, its fingers landing one after the other and spreading from
        # 60 to 120 px apart about their midpoint: the view comes twice as close and does not turn.
        state = page.tap(*slider_css(state, "w", 1))
        before = camera_of(state)
        down_s = page.touch("touchStart", [(cx - 30, cy)])
        page.touch("touchStart", [(cx - 30, cy), (cx + 30, cy)], down_s + 0.02)
        for step in range(1, 7):
            page.touch("touchMove", [(cx - 30 - 5 * step, cy), (cx + 30 + 5 * step, cy)],
                       down_s + 0.02 + 0.03 * step)
            page.settle(1)
        page.touch("touchEnd", [], down_s + 0.25)
        state = page.settle()
        after = camera_of(state)
        check(problems, after[:2] == before[:2],
              f"a pinch turned the view: (yaw, pitch) {before[:2]} became {after[:2]}")
        check(problems, abs(after[2] / before[2] - 0.5) < 0.02,
              f"a pinch from 60 to 120 px left the distance at {after[2] / before[2]:.3f} of "
              "what it was, not 0.5")
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-touch-first.png"))
    finally:
        page.close()


def check_fingers(args, root, problems):
    """On a touch screen: the hints speak of fingers, every slider is a finger's target tall, a
    drag away from a slider makes finer changes, and two fingers scroll a panel."""
    here = os.path.dirname(os.path.abspath(__file__))
    # The words as drawn, read by a played script (its `visible` and `absent` steps).
    # The default preset (eq. 7 calibrated): with the paper's own eq. 7 in use the panel says so
    # where it otherwise says how to type a value.
    page = Page(args, os.path.join(root, "words"), "?play=play/touch_words.json&report=1",
                play_dir=here, touch=True)
    try:
        page.wait_for("the played script's report", REPORT_TEXT, timeout_s=240)
        result = json.loads(page.tools.evaluate(REPORT_TEXT))
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-fingers-words.png"))
    finally:
        page.close()
    check(problems, result.get("exit_status") == 0,
          f"the words for fingers: {result.get('stderr')}")
    report = result.get("report") or {}
    for key, slider in (report.get("sliders") or {}).items():
        height = slider["bottom"] - slider["top"]
        check(problems, height >= TOUCH_TARGET_PX - 0.5,
              f"the {key} slider is {height} CSS px tall, less than a finger's {TOUCH_TARGET_PX}")
    check(problems, len(report.get("sliders") or {}) >= 6,
          f"the report shows {len(report.get('sliders') or {})} sliders, not the six")

    page = Page(args, os.path.join(root, "fingers"), QUERY, touch=True)
    try:
        state = ready(page)
        # The same 36 px to the right, once along the w slider and once with the finger four
        # slider heights below (or above) it: the second moves the handle a quarter as far.
        slider = state["sliders"]["w"]
        height = slider["bottom"] - slider["top"]
        x, y = slider_css(state, "w", 1)
        room_below = state["display"][1] - (y + 4 * height)
        away = 4 * height if room_below > height else -4 * height
        moved = []
        for offset in (0.0, away):
            start = state["sliders"]["w"]["fraction"]
            x, y = slider_css(state, "w", 1)
            path = [(x, y)] + [(x, y + offset * k / 4) for k in range(1, 5)] if offset else [(x, y)]
            path += [(x + 12 * k, y + offset) for k in range(1, 4)]
            state = page.swipe(path)
            moved.append(state["sliders"]["w"]["fraction"] - start)
        check(problems, moved[0] > 0.05 and abs(moved[1] / moved[0] - 0.25) < 0.05,
              f"36 px along the w slider moved it {moved[0]:.4f} of its width, and four slider "
              f"heights away {moved[1]:.4f}, not a quarter of that")
        # Two fingers moving up 90 px together over the Parameters panel scroll it by as much: the
        # t slider (its top) comes 90 px higher, and the 3D view does not zoom.
        top_before = state["sliders"]["t"]["top"]
        distance_before = state["camera"]["distance_mm"]
        px, py = panel_centre_css(state, "parameters", 1)
        down_s = page.touch("touchStart", [(px - 30, py), (px + 30, py)])
        for step in range(1, 4):
            page.touch("touchMove", [(px - 30, py - 30 * step), (px + 30, py - 30 * step)],
                       down_s + 0.03 * step)
            page.settle(1)
        page.touch("touchEnd", [], down_s + 0.12)
        state = page.settle()
        scrolled = top_before - state["sliders"]["t"]["top"]
        check(problems, abs(scrolled - 90) <= 9,
              f"two fingers moving 90 px up over the Parameters panel scrolled it {scrolled} px")
        check(problems, state["camera"]["distance_mm"] == distance_before,
              "two fingers over the Parameters panel zoomed the 3D view")
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-fingers.png"))
    finally:
        page.close()


def check_phone(args, root, problems):
    """A phone (390 x 844 CSS px, ratio 3, touch): one view at a time under the read-out, switched
    by its row of views (a played script taps them and reads what is presented), no tiles to go
    back to."""
    here = os.path.dirname(os.path.abspath(__file__))
    page = Page(args, os.path.join(root, "phone"), "?play=play/phone_views.json&report=1",
                play_dir=here, touch=True, metrics=(390, 844, 3))
    try:
        page.wait_for("the played script's report", REPORT_TEXT, timeout_s=240)
        result = json.loads(page.tools.evaluate(REPORT_TEXT))
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-phone.png"))
    finally:
        page.close()
    check(problems, result.get("exit_status") == 0, f"one view at a time: {result.get('stderr')}")
    report = result.get("report") or {}
    check(problems, report.get("display") == [1170, 2532],
          f"the phone's canvas is {report.get('display')}, not 1170 x 2532")
    # The view shown is the phone's, not the fabric's: a link sent from it opens the tiles. (The
    # fabric is the preset's, so the link may be empty; it must be reported.)
    check(problems, "link" in report and "present=" not in report["link"],
          f"the phone's link carries its view: {report.get('link')}")


# WCAG 2.5.5's target size, Apple's 44 pt (docs/web.md, "The screen").
TOUCH_TARGET_PX = 44


def rect_centre_css(rect, ratio):
    return (rect["x"] + rect["w"] / 2) / ratio, (rect["y"] + rect["h"] / 2) / ratio


def check_readable(problems, state, where):
    """Nothing cut at an edge or wrapped inside a word, and every target a finger's height."""
    clipped = state["layout"]["clipped_text"]
    check(problems, clipped == [], f"{where}: text cut or wrapped inside a word: {clipped}")
    smallest = state["layout"]["smallest_target"]
    check(problems, smallest["height_css_px"] >= TOUCH_TARGET_PX - 0.5,
          f"{where}: the smallest target ({smallest['what']}) is {smallest['height_css_px']} "
          f"CSS px tall, less than a finger's {TOUCH_TARGET_PX}")


def drag_slider_by_touch(page, state, key, ratio, problems, where):
    """A finger's drag 60 CSS px to the right along a slider: its value grows and the toast says
    so (a finger hides the value it moves)."""
    field = {"w": "w_N_per_mm2", "h": "h_mm", "t": "t_mm"}[key]
    before = state["parameters"][field]
    x, y = slider_css(state, key, ratio)
    down_s = page.touch("touchStart", [(x, y)])
    for step in range(1, 6):
        page.touch("touchMove", [(x + 12 * step, y)], down_s + 0.03 * step)
        page.settle(1)
    page.touch("touchEnd", [], down_s + 0.18)
    state = page.settle()
    check(problems, state["parameters"][field] > before,
          f"{where}: a drag to the right on the {key} slider left it at "
          f"{state['parameters'][field]} (was {before})")
    check(problems, "(was " in state["toast"],
          f"{where}: the drag on {key} is not said in the toast: {state['toast']!r}")
    return state


def long_press_and_type(page, state, key, ratio, text, problems, where):
    """Holding a finger on a slider opens its typed value with the keyboard's field focused; the
    keyboard's text and Enter set it."""
    x, y = slider_css(state, key, ratio)
    page.touch("touchStart", [(x, y)])
    page.wait_for(f"{where}: the long press on {key}",
                  "document.activeElement && document.activeElement.id === 'foldlab-keyboard'")
    page.touch("touchEnd", [])
    page.settle()
    page.tools.send("Input.insertText", text=text)
    page.settle(6)
    page.tools.send("Input.dispatchKeyEvent", type="rawKeyDown", windowsVirtualKeyCode=13,
                    key="Enter", code="Enter")
    page.tools.send("Input.dispatchKeyEvent", type="keyUp", windowsVirtualKeyCode=13,
                    key="Enter", code="Enter")
    return page.settle()


def orbit_and_pinch(page, state, ratio, problems, where):
    """One finger across the 3D view's picture turns it; two spreading from 60 to 120 CSS px
    apart bring it twice as close."""
    cx, cy = rect_centre_css(state["layout"]["drawing_areas"]["cloth"], ratio)
    yaw_before = state["camera"]["yaw_rad"]
    state = page.swipe([(cx + 12 * step, cy) for step in range(6)])
    check(problems, abs(state["camera"]["yaw_rad"] - yaw_before) > 0.05,
          f"{where}: a one-finger drag on the 3D view left its yaw at {state['camera']['yaw_rad']}")
    distance_before = state["camera"]["distance_mm"]
    down_s = page.touch("touchStart", [(cx - 30, cy), (cx + 30, cy)])
    for step in range(1, 7):
        page.touch("touchMove", [(cx - 30 - 5 * step, cy), (cx + 30 + 5 * step, cy)],
                   down_s + 0.03 * step)
        page.settle(1)
    page.touch("touchEnd", [], down_s + 0.21)
    state = page.settle()
    zoomed = state["camera"]["distance_mm"] / distance_before
    check(problems, abs(zoomed - 0.5) < 0.02,
          f"{where}: a pinch from 60 to 120 px left the distance at {zoomed:.3f}, not 0.5")
    return state


# A link as a teacher sends it: a shipped preset and one input changed.
LINK_QUERY = "?preset=paper-table1-h1400#h=2000"


def check_phone_flows(args, root, problems):
    """A class's phone (390 x 844 CSS px, ratio 3, touch) opened from a link: the link's fabric,
    the 3D view orbited and pinched, each view switched to by its button under the read-out, a
    slider dragged and one typed with a long press; at every step no text cut or wrapped inside
    a word and no target below a finger's height. Then the same phone held sideways."""
    ratio = 3
    page = Page(args, os.path.join(root, "phone_flows"), LINK_QUERY, touch=True,
                metrics=(390, 844, ratio))
    try:
        state = ready(page)
        check(problems, state["parameters"]["h_mm"] == 2000,
              f"phone: the link's h = 2000 mm opened as {state['parameters']['h_mm']}")
        check(problems, state["layout"]["presented"] == "cloth",
              f"phone: it starts on {state['layout']['presented']}, not the 3D view")
        check_readable(problems, state, "phone, 3D view")
        state = orbit_and_pinch(page, state, ratio, problems, "phone")
        for key in ("fold_plot", "results", "presets", "analysis", "parameters"):
            state = page.tap(*rect_centre_css(state["layout"]["view_buttons"][key], ratio))
            check(problems, state["layout"]["presented"] == key,
                  f"phone: a tap on {key}'s button shows {state['layout']['presented']}")
            check_readable(problems, state, f"phone, {key}")
        state = drag_slider_by_touch(page, state, "w", ratio, problems, "phone")
        state = long_press_and_type(page, state, "t", ratio, "0.05cm", problems, "phone")
        check(problems, abs(state["parameters"]["t_mm"] - 0.5) < 1e-12,
              f"phone: 0.05cm typed into t after a long press: t is {state['parameters']['t_mm']}")
        check_readable(problems, state, "phone, after typing")
        state = page.tap(*rect_centre_css(state["layout"]["view_buttons"]["cloth"], ratio))
        check(problems, state["layout"]["presented"] == "cloth",
              f"phone: back to the 3D view shows {state['layout']['presented']}")
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-phone-flows.png"))
    finally:
        page.close()
    page = Page(args, os.path.join(root, "phone_sideways"), LINK_QUERY, touch=True,
                metrics=(844, 390, ratio))
    try:
        state = ready(page)
        check(problems, state["layout"]["presented"] == "cloth",
              f"phone sideways: {state['layout']['presented']} is shown, not the 3D view alone")
        check_readable(problems, state, "phone sideways, 3D view")
        state = page.tap(*rect_centre_css(state["layout"]["view_buttons"]["parameters"], ratio))
        check(problems, state["layout"]["presented"] == "parameters",
              f"phone sideways: a tap on Inputs shows {state['layout']['presented']}")
        check_readable(problems, state, "phone sideways, inputs")
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-phone-sideways.png"))
    finally:
        page.close()


def check_tablet(args, root, problems):
    """A class's tablet (1024 x 768 CSS px, ratio 2, touch) opened from a link: its tiles, a
    slider dragged and one typed with a long press, the 3D view orbited and pinched, the fold plot
    presented by its title's button and back by the menu bar's; nothing cut, every target a
    finger's height."""
    ratio = 2
    page = Page(args, os.path.join(root, "tablet"), LINK_QUERY, touch=True,
                metrics=(1024, 768, ratio))
    try:
        state = ready(page)
        check(problems, state["parameters"]["h_mm"] == 2000,
              f"tablet: the link's h = 2000 mm opened as {state['parameters']['h_mm']}")
        check(problems, state["layout"]["presented"] is None,
              f"tablet: {state['layout']['presented']} is presented rather than the tiles")
        check(problems, not state["layout"]["cramped"], "tablet: the tiles are cramped")
        check_readable(problems, state, "tablet, tiles")
        state = drag_slider_by_touch(page, state, "w", ratio, problems, "tablet")
        state = long_press_and_type(page, state, "t", ratio, "0.05cm", problems, "tablet")
        check(problems, abs(state["parameters"]["t_mm"] - 0.5) < 1e-12,
              f"tablet: 0.05cm typed into t after a long press: t is {state['parameters']['t_mm']}")
        state = orbit_and_pinch(page, state, ratio, problems, "tablet")
        # The present button: a square as tall as the title bar (a finger's target) at the
        # title's right end. Presented, the view has no title bar: the way back is the menu
        # bar's item.
        rect = state["layout"]["panels"]["fold_plot"]
        state = page.tap((rect["x"] + rect["w"]) / ratio - TOUCH_TARGET_PX / 2,
                         rect["y"] / ratio + TOUCH_TARGET_PX / 2)
        check(problems, state["layout"]["presented"] == "fold_plot",
              f"tablet: a tap on the fold plot's present button left "
              f"{state['layout']['presented']} presented, not the fold plot")
        check_readable(problems, state, "tablet, presented fold_plot")
        back = [r for name, r in state["layout"]["menu_bar_items"].items()
                if name.startswith("Back to the tiles") or name.startswith("Tiles")]
        check(problems, len(back) == 1 and back[0]["h"] / ratio >= TOUCH_TARGET_PX - 0.5,
              f"tablet, presented: the menu bar's way back is {back}, not one finger's target")
        if back:
            state = page.tap(*rect_centre_css(back[0], ratio))
            check(problems, state["layout"]["presented"] is None,
                  f"tablet: a tap on the menu bar's way back left "
                  f"{state['layout']['presented']} presented")
            check_readable(problems, state, "tablet, back to the tiles")
        if args.keep_screenshots:
            page.screenshot(os.path.join(args.keep_screenshots, "page-tablet.png"))
    finally:
        page.close()


def check_scheme(args, root, problems):
    # Chromium has no --force-prefers-color-scheme; Blink's settings set the scheme (0 dark,
    # 1 light; headless Chromium prefers light by itself) and the default font size.
    cases = [
        ("dark", ["--blink-settings=preferredColorScheme=0"], False, 100),
        ("light", ["--blink-settings=preferredColorScheme=1"], True, 100),
        ("large text", ["--blink-settings=preferredColorScheme=0,defaultFontSize=24"], False, 150),
    ]
    for name, flags, light, percent in cases:
        page = Page(args, os.path.join(root, name.replace(" ", "_")), QUERY, flags)
        try:
            state = ready(page)
            seen = page.tools.evaluate("matchMedia('(prefers-color-scheme: light)').matches")
            check(problems, seen == light,
                  f"{name}: flags {flags} give prefers-color-scheme light = {seen}")
            check(problems, state["appearance"]["light_theme"] == light,
                  f"{name}: the explorer's light theme is {state['appearance']['light_theme']}")
            check(problems, state["appearance"]["scale_percent"] == percent,
                  f"{name}: the text size is {state['appearance']['scale_percent']} %, not "
                  f"{percent} %")
            if args.keep_screenshots:
                page.screenshot(os.path.join(args.keep_screenshots,
                                             f"page-{name.replace(' ', '-')}.png"))
        finally:
            page.close()


def check_layout(args, root, problems):
    # A person's page: nothing in the address, so the reload restores the session, as the
    # desktop's next start does.
    page = Page(args, os.path.join(root, "layout"), "")
    try:
        state = ready(page)
        fresh = state["layout"]["panels"]
        # The resize grip in the fold plot's lower right corner, dragged 80 px left and 40 px
        # down with the mouse, as a person resizes the tiles: the edges it shares with the 3D
        # view and the panels below move with it. 8 px inside the corner: the neighbours' edges
        # take the 4 px either side of theirs (the page's GLFW has mouse cursors, so edges
        # resize).
        rect = fresh["fold_plot"]
        x, y = rect["x"] + rect["w"] - 8, rect["y"] + rect["h"] - 8
        page.mouse("mouseMoved", x, y)
        page.settle()
        page.mouse("mousePressed", x, y, 1)
        page.settle(1)
        for step in range(1, 5):
            page.mouse("mouseMoved", x - 20 * step, y + 10 * step, 1)
            page.settle(1)
        page.mouse("mouseReleased", x - 80, y + 40)
        dragged = page.settle()
        now = dragged["layout"]["panels"]["fold_plot"]
        check(problems, abs(now["w"] - (rect["w"] - 80)) <= 1 and
              abs(now["h"] - (rect["h"] + 40)) <= 1,
              f"dragging the fold plot's corner 80 px left and 40 px down made it {now['w']} x "
              f"{now['h']} px, from {rect['w']} x {rect['h']}")
        check(problems, dragged["layout"]["automatic"] and dragged["layout"]["fills_window"],
              f"after the drag the tiles are {dragged['layout']}")
        # Reloaded as soon as the drag is drawn: the session is saved a second after the last
        # change, so a fast page is left before that save and keeps the drag as it goes.
        print("layout: at the reload the session was "
              + ("not yet saved (kept as the page went)" if dragged["session_unsaved"]
                 else "already saved"))
        back = page.reload_by("the reloaded page's first frames", "location.reload()")
        check(problems, back["message"] == "Restored the last session.",
              f"after the reload the status says {back['message']!r}")
        for key, was in dragged["layout"]["panels"].items():
            now = back["layout"]["panels"].get(key)
            check(problems, now is not None and
                  all(abs(now[side] - was[side]) <= 1 for side in ("x", "y", "w", "h")),
                  f"after the reload {key} is {now}, before it {was}")
        check(problems, back["layout"]["automatic"] == dragged["layout"]["automatic"],
              f"after the reload the layout is automatic = {back['layout']['automatic']}")
    finally:
        page.close()


def check_address(args, root, problems):
    # A link's value edited in the address bar (Enter fires hashchange, no reload of its own):
    # the page opens the edited link, as a new tab would, and its address stays that link.
    page = Page(args, os.path.join(root, "address"), "#h=2000&w=200gsm")
    try:
        state = ready(page)
        check(problems, abs(state["parameters"]["h_mm"] - 2000) < 1e-9,
              f"the link's h = 2000 mm opened as {state['parameters']['h_mm']}")
        back = page.reload_by("the edited address's first frames",
                              "location.hash = '#h=1500&w=300gsm'")
        # 300 g/m^2 as N/mm^2 at the presets' g = 9.81 m/s^2: 0.3 kg/m^2 * 9.81 / 1e6 mm^2/m^2.
        check(problems, abs(back["parameters"]["h_mm"] - 1500) < 1e-9 and
              abs(back["parameters"]["w_N_per_mm2"] - 0.3 * 9.81e-6) < 1e-15,
              f"after the address was edited the inputs are {back['parameters']}")
        address = page.tools.evaluate("location.hash")
        check(problems, "h=1500" in address and "w=300gsm" in address,
              f"after the address was edited it reads {address!r}")
    finally:
        page.close()


def check_clipboard(args, root, problems):
    # Copy and paste between the page's typed values and the browser's clipboard, through the
    # keys a person presses (the clipboard written by the page itself, as another tab would).
    page = Page(args, os.path.join(root, "clipboard"), "")
    try:
        origin = page.tools.evaluate("location.origin")
        page.tools.send("Browser.grantPermissions", origin=origin,
                        permissions=["clipboardReadWrite", "clipboardSanitizedWrite"])
        # A headless window never has the focus, which the clipboard asks of a page.
        page.tools.send("Emulation.setFocusEmulationEnabled", enabled=True)
        state = ready(page)
        page.tools.evaluate("navigator.clipboard.writeText('1.5 m')")
        page.open_typed_value(state, "h")
        page.key("v", "KeyV", 86, modifiers=2, commands=["paste"])
        page.settle(3)
        page.key("Enter", "Enter", 13)
        state = page.settle()
        check(problems, state["parameters"]["h_mm"] == 1500 and state["refused"] is None,
              f"'1.5 m' pasted with Ctrl+V over h's typed value: h is "
              f"{state['parameters']['h_mm']} mm, refused {state['refused']!r}")
        page.open_typed_value(state, "L")
        page.key("c", "KeyC", 67, modifiers=2)
        state = page.settle(3)
        page.key("Escape", "Escape", 27)
        page.settle()
        copied = page.tools.evaluate("navigator.clipboard.readText()")
        check(problems, copied == "1400" or copied.startswith("1400"),
              f"Ctrl+C on L's typed value (1400 mm) left {copied!r} on the browser's clipboard")
        check(problems, state["clipboard"] == copied,
              f"the explorer's clipboard reads {state['clipboard']!r}, the browser's {copied!r}")
    finally:
        page.close()


# The picture's preset and link, the same in the page and on the desktop: dark, as the desktop
# starts (the headless browser prefers light).
PICTURE_PRESET = "paper-table1-h1400"
PICTURE_LINK = "#L=4000&theme=dark"


def check_picture(args, root, problems):
    """The page's picture beside the desktop's (`render`) of the same preset and link at the page's
    canvas size and pixel ratio 1, three frames each from a fresh start: how many pixels differ
    and by how much (png_compare.py)."""
    from png_compare import compare
    page = Page(args, os.path.join(root, "picture"),
                f"?frames=3&preset={PICTURE_PRESET}{PICTURE_LINK}")
    try:
        page.wait_for("the page's three frames", REPORT_TEXT)
        width, height = page.tools.evaluate(
            "[document.getElementById('canvas').width, document.getElementById('canvas').height]")
        mine = os.path.join(page.root, "page.png")
        page.screenshot(mine)
    finally:
        page.close()
    theirs = os.path.join(root, "desktop.png")
    with tempfile.TemporaryDirectory(prefix="foldlab_native_") as home:
        run = subprocess.run(
            [os.path.abspath(args.native), "render", "--out", theirs, "--size",
             f"{width}x{height}", "--preset",
             os.path.join(os.path.abspath(args.presets), PICTURE_PRESET + ".json"),
             "--link", PICTURE_LINK],
            capture_output=True, text=True, timeout=600, cwd=home,
            env={**os.environ, "XDG_CONFIG_HOME": home, "HOME": home})
    if run.returncode != 0:
        problems.append(f"the desktop program's render failed ({run.returncode}): {run.stderr}")
        return
    if args.keep_screenshots:
        shutil.copy(mine, os.path.join(args.keep_screenshots, "picture-page.png"))
        shutil.copy(theirs, os.path.join(args.keep_screenshots, "picture-desktop.png"))
    result = compare(mine, theirs, PICTURE_THRESHOLD)
    print(f"picture: {json.dumps(result)}")
    if "error" in result:
        problems.append(result["error"])
        return
    check(problems, result["over_threshold"] <= PICTURE_MAX_OVER,
          f"{result['over_threshold']} pixels differ by more than {PICTURE_THRESHOLD} (at most "
          f"{PICTURE_MAX_OVER}), in {result['over_threshold_box']}")


# SwiftShader (the page) and llvmpipe (the desktop) round blending and antialiased edges
# differently: on 2026-11-27, 69 402 of the 840 960 pixels differed, by 8 or less in every
# channel (51 023 by 1 or 2), in flat translucent fills and along every glyph's and line's edge.
# By more than 8: 715 pixels, 579 of them along the 3D view's triangles and lines. Twice that
# leaves room for other versions of either rasteriser, while a line of text moved, another font
# or size, or another colour differs in thousands of pixels by far more.
PICTURE_THRESHOLD = 8
PICTURE_MAX_OVER = 1500


def check_regime_map(args, root, problems):
    here = os.path.dirname(os.path.abspath(__file__))
    page = Page(args, os.path.join(root, "map"),
                "?play=play/regime_map_slices.json&report=1&preset=paper-table1-h1400#L=4000",
                play_dir=here)
    try:
        deadline = time.monotonic() + 240
        text = ""
        while not text and time.monotonic() < deadline:
            time.sleep(0.2)
            text = page.tools.evaluate(REPORT_TEXT)
        if not text:
            problems.append("the played script did not end within 240 s")
            return
        result = json.loads(text)
    finally:
        page.close()
    if result.get("exit_status") != 0:
        problems.append(f"the played script failed: {result.get('stderr')}")
        return
    if not args.native:
        return
    with tempfile.TemporaryDirectory(prefix="foldlab_native_") as home:
        run = subprocess.run(
            [os.path.abspath(args.native), "render", "--play",
             os.path.join(here, "regime_map_done.json"),
             "--report", "--preset",
             os.path.join(os.path.abspath(args.presets), "paper-table1-h1400.json"),
             "--set", "L=4000"],
            capture_output=True, text=True, timeout=600, cwd=home,
            env={**os.environ, "XDG_CONFIG_HOME": home, "HOME": home})
    if run.returncode != 0:
        problems.append(f"the desktop program's run failed ({run.returncode}): {run.stderr}")
        return
    native = json.loads(run.stdout[run.stdout.index("{"):])
    mine = result["report"].get("regime_map") or {}
    theirs = native.get("regime_map") or {}
    for key in ("x", "y", "cells", "rows_done", "digest", "n_sum"):
        check(problems, mine.get(key) == theirs.get(key),
              f"regime_map.{key}: the page's {mine.get(key)!r}, the desktop's {theirs.get(key)!r}")
    z_mine, z_theirs = mine.get("z_max_sum_mm"), theirs.get("z_max_sum_mm")
    check(problems, z_mine is not None and z_theirs is not None and
          abs(z_mine - z_theirs) <= 1e-9 * abs(z_theirs),
          f"regime_map.z_max_sum_mm: the page's {z_mine}, the desktop's {z_theirs}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--check", required=True,
                        choices=["dpr", "touch", "touch_first", "fingers", "phone", "phone_flows",
                                 "tablet", "scheme",
                                 "layout", "address", "clipboard", "picture", "regime_map"])
    parser.add_argument("--native", help="the desktop program (regime_map, picture)")
    parser.add_argument("--presets", help="the presets folder (regime_map, picture)")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--keep-screenshots", help="a folder to copy the screenshots into")
    args = parser.parse_args()
    problems = []
    started = time.monotonic()
    with browser_folder("foldlab_drive_") as root:
        {"dpr": check_dpr, "touch": check_touch, "touch_first": check_touch_first,
         "fingers": check_fingers, "phone": check_phone, "phone_flows": check_phone_flows,
         "tablet": check_tablet, "scheme": check_scheme,
         "layout": check_layout, "address": check_address, "clipboard": check_clipboard,
         "picture": check_picture,
         "regime_map": check_regime_map}[args.check](
            args, root, problems)
    for problem in problems:
        print(f"{args.check}: {problem}", file=sys.stderr)
    print(f"{args.check}: {'ok' if not problems else 'FAILED'} in "
          f"{time.monotonic() - started:.1f} s")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
