#!/usr/bin/env python3
"""Writes slider_KEY.json: drags of +-40 px from the handle, clicks at 0, 0.5 and 1 of each
parameter slider (which take the focus and leave the value), and drags past both ends, with the
ranges a correct slider must land in.

The ranges come from the input table's slider range and scale (copied here by hand, so that a
change of the table shows up as a failing test): a fresh start is a beginner's, whose t, E and w
sliders run over the rows' beginner range (the fabrics one buys), the others over the typical one and from ImGui 1.86's slider geometry: a float
slider's handle is GrabMinSize = 10 px wide inside 2 px of padding, so 40 px move the handle by
40 / (W - 14) of the range for a slider W px wide. The layout may give the slider anything from
100 to 600 px, so a drag must move between 40/586 and 40/86 of the range (clamped at the ends).

The L and d sliders stop where validation starts refusing, d < L/2: with the other inputs fixed, L's
slider runs from 2d (just above) and d's to L/2 (just below). nu and K are expert settings: their
scripts first tick "Expert settings" (a fresh start shows the cloth's inputs only).

Run from this folder after changing the table or the base state; the CTest command line gives
the base state: Table 1's h = 1400 mm preset with L = 4000 mm (so that d has room to move).
"""
import json
import math

BASE = {"t": 0.25, "E": 165.0, "w": 1.5e-6, "nu": 0.3, "h": 1400.0, "L": 4000.0, "d": 100.0}
# K is eq. 7's constant from c and nu: K = c / (1 - nu^2) with the preset's c = 26.9.
G_PER_M2 = 9.81e-9  # N/mm² of 1 g/m²
TABLE = {  # key: (report field, slider lo, slider hi, logarithmic)
    "t": ("t_mm", 0.05, 3.0, True),
    "E": ("E_MPa", 3.0, 1000.0, True),
    "w": ("w_N_per_mm2", 1e-7, 1000 * G_PER_M2, True),
    "nu": ("nu", 0.0, 0.49, False),
    "h": ("h_mm", 100.0, 5000.0, False),
    "L": ("L_mm", 100.0, 5000.0, False),
    "d": ("d_mm", 0.0, 2500.0, False),
    "K": ("K", 0.5, 300.0, True),
}
MOVE_LO = 40.0 / (600 - 14)
MOVE_HI = 40.0 / (100 - 14)


EXPERT = {"nu", "K"}


def ends(key):
    """The slider's ends with the other inputs at BASE: the table's range, cut where d < L/2 stops."""
    _, lo, hi, _ = TABLE[key]
    if key == "L":
        lo = max(lo, 2 * BASE["d"])
    if key == "d":
        hi = min(hi, BASE["L"] / 2)
    return lo, hi


def fraction(key, value):
    _, _, _, log = TABLE[key]
    lo, hi = ends(key)
    if log:
        return (math.log10(value) - math.log10(lo)) / (math.log10(hi) - math.log10(lo))
    return (value - lo) / (hi - lo)


def value(key, f):
    _, _, _, log = TABLE[key]
    lo, hi = ends(key)
    f = min(1.0, max(0.0, f))
    if log:
        return lo * (hi / lo) ** f
    return lo + (hi - lo) * f


def band(key, f_lo, f_hi, slack=1e-9):
    a, b = value(key, f_lo), value(key, f_hi)
    return [min(a, b) * (1 - slack) - slack, max(a, b) * (1 + slack) + slack]


def script(key, base_value):
    field = "parameters." + TABLE[key][0]
    f0 = fraction(key, base_value)
    reset = [{"click": "Reset to preset"}, {"expect": {field: base_value}}]
    steps = [{"click": "Expert settings"}] if key in EXPERT else []
    steps += [{"expect": {field: base_value, "refused": None}}]
    steps += [{"drag": key, "dx": 40},
              {"expect": {field: band(key, f0 + MOVE_LO, f0 + MOVE_HI), "refused": None}}]
    steps += reset
    steps += [{"drag": key, "dx": -40},
              {"expect": {field: band(key, f0 - MOVE_HI, f0 - MOVE_LO), "refused": None}}]
    steps += reset
    # A click only takes the focus (for the arrow keys), wherever it lands: the value stays.
    for at in (0.0, 0.5, 1.0):
        steps += [{"click": key, "at": at}, {"expect": {field: base_value, "dirty": False}}]
    # A drag far past either end reaches it, and every value there is accepted, the ends of L and
    # d included.
    steps += [{"drag": key, "dx": -2000}, {"expect": {field: band(key, 0.0, 0.0)}}]
    steps += [{"drag": key, "dx": 2000}, {"expect": {field: band(key, 1.0, 1.0)}}]
    for step in steps[-3::2]:
        step["expect"]["refused"] = None
    return {"steps": steps}


def main():
    base = dict(BASE)
    base["K"] = 26.9 / (1 - 0.3 ** 2)
    for key in TABLE:
        with open(f"slider_{key}.json", "w") as out:
            json.dump(script(key, base[key]), out, indent=1)
            out.write("\n")


if __name__ == "__main__":
    main()
