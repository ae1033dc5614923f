#!/usr/bin/env python3
"""Makes docs/families.png: one design of every pattern family, in the order `marbler random
--families` lists them (the k-th, from 0, is seed 21 + k, so the palettes differ), in a grid of
240-pixel cells on cream (a solid family as its z = 500 section).

    python3 docs/families-gallery.py build/app/marbler docs/families.png

Only the standard library: the cells are rendered by `marbler` and read back with zlib.
"""

import os
import struct
import subprocess
import sys
import tempfile
import zlib

CELL, GAP, COLUMNS, SEED = 240, 10, 5, 21


def read_png(path):
    """(width, height, rows of RGB bytes) of an 8-bit RGB or RGBA PNG, not interlaced."""
    data = open(path, "rb").read()
    pos, idat, width, height, channels = 8, b"", 0, 0, 3
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                raise SystemExit(f"{path}: only 8-bit RGB or RGBA")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        previous = line
        rows.append(bytes(line) if channels == 3 else bytes(v for i, v in enumerate(line) if i % 4 != 3))
    return width, height, rows


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + row for row in rows)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    marbler, target = sys.argv[1], sys.argv[2]
    listing = subprocess.run([marbler, "random", "--families"], capture_output=True, text=True, check=True).stdout
    families = [line.split()[:2] for line in listing.splitlines() if line.strip()]
    cells = []
    with tempfile.TemporaryDirectory() as work:
        for k, (family, kind) in enumerate(families):
            genome, image = os.path.join(work, family + ".marble.json"), os.path.join(work, family + ".png")
            subprocess.run([marbler, "random", "--family", family, "--seed", str(SEED + k), "-o", genome], check=True)
            solid = ["--slice", "z=500"] if kind == "solid" else []
            subprocess.run([marbler, "render", genome, "-o", image, "--width", str(CELL)] + solid, check=True)
            cells.append(read_png(image))
            print(family, file=sys.stderr)
    rows_of_cells = (len(cells) + COLUMNS - 1) // COLUMNS
    width = COLUMNS * CELL + (COLUMNS + 1) * GAP
    height = rows_of_cells * CELL + (rows_of_cells + 1) * GAP
    sheet = [bytearray(b"\xf3\xef\xe6" * width) for _ in range(height)]
    for k, (w, h, rows) in enumerate(cells):
        x0, y0 = GAP + (k % COLUMNS) * (CELL + GAP), GAP + (k // COLUMNS) * (CELL + GAP)
        for y in range(min(h, CELL)):
            sheet[y0 + y][3 * x0:3 * (x0 + min(w, CELL))] = rows[y][:3 * min(w, CELL)]
    write_png(target, width, height, [bytes(r) for r in sheet])


if __name__ == "__main__":
    main()
