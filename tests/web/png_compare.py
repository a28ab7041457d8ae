#!/usr/bin/env python3
"""Two PNG pictures compared pixel by pixel, with Python's standard library alone (zlib and the
PNG filters): how many pixels differ, by how much at most, and where.

  png_compare.py A.png B.png [--threshold N]

Prints one JSON object: width, height, differing (pixels whose red, green or blue differ at
all), over_threshold (by more than N in some channel), max_channel_difference and the bounding
box of the pixels over the threshold. 8-bit RGB or RGBA, not interlaced; alpha is ignored."""
import argparse
import json
import struct
import zlib


def read_png(path):
    """(width, height, rows): rows as bytes of R, G, B per pixel."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos, idat = 8, []
    width = height = channels = None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            channels = {2: 3, 6: 4}.get(colour)
            if depth != 8 or channels is None or interlace:
                raise ValueError(f"{path}: only 8-bit RGB or RGBA, not interlaced")
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 0xFF
        elif kind == 2:
            line = bytearray((a + b) & 0xFF for a, b in zip(line, previous))
        elif kind == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 0xFF
        elif kind == 4:
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b = previous[i]
                c = previous[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 0xFF
        rows.append(bytes(line) if channels == 3 else bytes(
            v for i, v in enumerate(line) if i % 4 != 3))
        previous = line
    return width, height, rows


def compare(a_path, b_path, threshold):
    aw, ah, a = read_png(a_path)
    bw, bh, b = read_png(b_path)
    if (aw, ah) != (bw, bh):
        return {"error": f"sizes differ: {aw}x{ah} and {bw}x{bh}"}
    differing = over = worst = 0
    box = None
    for y in range(ah):
        ra, rb = a[y], b[y]
        if ra == rb:
            continue
        for x in range(aw):
            d = max(abs(ra[3 * x + k] - rb[3 * x + k]) for k in range(3))
            if d:
                differing += 1
                worst = max(worst, d)
                if d > threshold:
                    over += 1
                    box = ([x, y, x, y] if box is None else
                           [min(box[0], x), min(box[1], y), max(box[2], x), max(box[3], y)])
    return {"width": aw, "height": ah, "pixels": aw * ah, "differing": differing,
            "threshold": threshold, "over_threshold": over, "max_channel_difference": worst,
            "over_threshold_box": box}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--threshold", type=int, default=0)
    args = parser.parse_args()
    print(json.dumps(compare(args.a, args.b, args.threshold)))


if __name__ == "__main__":
    main()
