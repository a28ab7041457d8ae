#!/usr/bin/env python3
"""Writes ui_WxH.json: every button, tab, menu item and dialog of the explorer clicked at one
window size, each followed by a check of what it should have done (a tab's content is there to
be clicked, a dialog opens and Escape closes it, the layout fills the window). The exports are
saved with the save dialog, which opens in the working folder: the CTest command makes that a
fresh temporary one and then checks the files.

Run from this folder after changing a label; the CTest command line gives the base state:
Table 1's h = 1400 mm preset with L = 4000 mm.
"""
import json

SIZES = ["1024x640", "1280x800", "1920x1080"]
# After the run the window is resized to the next size, so that every size is also reached by a
# resize rather than only at start.
NEXT = {"1024x640": "1920x1080", "1280x800": "1024x640", "1920x1080": "1280x800"}
UNSAVED = "Unsaved changes"
SAVE_AS = "Save as"
# Each Export item opens the save dialog with the fabric's name, what the file holds and its
# extension as the name ("cotton-jersey-knit-cloth.obj"); None keeps that name (Enter), a text is
# typed over it (the extension is added).
EXPORTS = [("OBJ mesh (.obj)...", None), ("glTF mesh (.glb)...", None),
           ("Fold lines (.svg)...", None), ("Fold lines (.csv)...", None),
           ("Window picture (.png)...", None), ("3D view picture (.png)...", "view"),
           ("Fold plot picture (.png)...", "fold-plot")]
# The "any size" pictures first ask for a size, background and caption in a small dialog, then
# where (the dialog's defaults: 1920 x 1080, white, no caption).
ANY_SIZE = [("3D view picture, any size (.png)...", "any-view"),
            ("Fold plot picture, any size (.png)...", "any-plot")]


def click(label, frames=2):
    return [{"click": label}, {"frames": frames}]


def menu(name, item):
    return click(name, 1) + click(item)


def script(size):
    tiled = {"layout.automatic": True, "layout.fills_window": True}
    steps = [{"expect": dict(tiled, modal=None, dirty=False)}]
    # Analysis tabs: each tab's own content is there to be clicked.
    steps += click("Equations") + click("eq. 7: critical stress gives Q7")
    steps += click("Sweep") + click("Table 1 (h)") + [{"expect": {"modal": None}}]
    steps += click("Regime map")
    # In the smallest window the map's settings fold behind one button, which opens them.
    folded = size == "1024x640"
    steps += [{"expect": {"regime_map.settings_folded": folded}}]
    if folded:
        steps += click("map settings...")
    steps += click("show z_max instead of n") + [{"expect": {"regime_map.shows": "z_max"}}]
    steps += click("show z_max instead of n") + [{"expect": {"regime_map.shows": "n"}}]
    if folded:
        steps += [{"key": "escape"}, {"frames": 2}]
    steps += click("Equations")
    # The 3D view's toggles, twice each so that the view ends as it began; in the smallest window
    # they fold behind one button too.
    if folded:
        steps += click("view settings...")
    for label in ["wireframe", "fold lines", "ground", "breeze"]:
        steps += click(label) + click(label)
    steps += click("reset camera")
    if folded:
        steps += [{"key": "escape"}, {"frames": 2}]
    steps += click("autoscale")
    # The unsaved-edits dialog: Escape keeps the edits, Discard loads the preset clicked.
    steps += [{"drag": "h", "dx": 40}, {"expect": {"dirty": True, "modal": None}}]
    steps += click("Cotton jersey knit") + [{"expect": {"modal": UNSAVED}}]
    steps += [{"key": "escape"}, {"frames": 2}, {"expect": {"modal": None, "dirty": True}}]
    steps += click("Cotton jersey knit") + [{"expect": {"modal": UNSAVED}}]
    steps += click("Discard") + [{"expect": {"modal": None, "dirty": False,
                                             "parameters.h_mm": 1400}}]
    steps += [{"drag": "d", "dx": 30}, {"expect": {"dirty": True}}]
    steps += click("Reset to preset") + [{"expect": {"dirty": False}}]
    # Save as: Ctrl+S on a shipped preset asks for a name; Escape closes the dialog unsaved.
    steps += [{"key": "ctrl+s"}, {"frames": 2}, {"expect": {"modal": SAVE_AS}}]
    steps += [{"key": "escape"}, {"frames": 2}, {"expect": {"modal": None}}]
    steps += click("Save as...") + [{"expect": {"modal": None}}]  # no name: refused, no file
    # The View menu.
    steps += menu("View", "Light theme") + [{"expect": {"appearance.light_theme": True}}]
    steps += menu("View", "Larger text") + [{"expect": {"appearance.scale_percent": 110}}]
    steps += [{"expect": tiled}]
    steps += menu("View", "Default size") + [{"expect": {"appearance.scale_percent": 100}}]
    steps += menu("View", "Pipeline stats") + menu("View", "Pipeline stats")
    steps += menu("View", "Light theme") + [{"expect": {"appearance.light_theme": False}}]
    # The Compare menu: B pinned, swapped (A and B the same fabric: A is unchanged), cleared.
    steps += menu("Compare", "Pin as B") + [{"expect": {"compare.parameters.h_mm": 1400}}]
    steps += menu("Compare", "Swap A and B") + [{"expect": {"parameters.h_mm": 1400,
                                                           "compare.parameters.h_mm": 1400}}]
    steps += menu("Compare", "Clear B") + [{"expect": {"compare": None}}]
    # Presenting one panel from the View menu, Escape back to the tiles.
    steps += click("View", 1) + click("Present (fill the window)", 1) + click("Cloth (3D)")
    steps += [{"expect": {"layout.presented": "cloth"}}]
    steps += [{"key": "escape"}, {"frames": 2}, {"expect": dict(tiled, **{"layout.presented": None})}]
    # The introduction: from the menu bar, closed by Escape.
    steps += click("What am I looking at?") + [{"expect": {"intro_open": True}}]
    steps += [{"key": "escape"}, {"frames": 2}, {"expect": {"intro_open": False}}]
    # The Export menu: the files are checked by the CTest command.
    for item, name in EXPORTS:
        steps += menu("Export", item)
        steps += [{"type": name}] if name else []
        steps += [{"key": "enter"}, {"frames": 2}, {"expect": {"modal": None}}]
    for item, name in ANY_SIZE:
        steps += menu("Export", item) + [{"expect": {"popup_open": True}}]
        steps += click("Save as...") + [{"type": name}]
        steps += [{"key": "enter"}, {"frames": 2}, {"expect": {"modal": None}}]
    steps += [{"frames": 2}, {"expect": dict(tiled, modal=None)}]
    # Another window size: the panels refit it.
    steps += [{"resize": NEXT[size]}, {"frames": 3}, {"expect": tiled}]
    # The calibration window (last but one: it floats over the panels).
    steps += click("Fit to measurements...", 3) + click("Measurements")
    # The fabric as a link, on the clipboard (play_copy_link checks its text and the message);
    # last, since what the status line says of it takes lines of the Presets panel, above the
    # calibration's button.
    steps += menu("Export", "Copy link") + [{"expect": {"popup_open": False}}]
    return {"steps": steps}


for size in SIZES:
    with open(f"ui_{size}.json", "w") as out:
        json.dump(script(size), out, indent=1)
        out.write("\n")
