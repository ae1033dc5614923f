#!/usr/bin/env python3
"""Marbled-paper images made outside Marbler, the simulated breeder's image targets (issue 26).

Neither is made with Marbler's maps, so no genome reproduces them exactly:
- turbulent-marble.png: Perlin's marble (Perlin 1985, "An Image Synthesizer"), the stripes of
  sin(x + turbulence) in five paper inks with dark veins, as a combed-and-swirled paper looks;
- stone-battal.png: a battal (stone) paper as Voronoi cells of a jittered grid, their borders
  warped by noise and edged with a thin vein, as drops of ink crowd one another on the bath.

Run with Python 3 and NumPy: `python3 make-images.py` writes both next to this script. The
noise draws from a fixed integer hash, so the images are the same on every machine."""

import os
import struct
import zlib

import numpy as np

SIDE = 384
HERE = os.path.dirname(os.path.abspath(__file__))


def hash01(i, j, salt):
    """A fixed integer hash of lattice points to [0, 1)."""
    with np.errstate(over="ignore"):  # the hash wraps around, as intended
        h = (i.astype(np.uint64) * np.uint64(73856093)) ^ (j.astype(np.uint64) * np.uint64(19349663))
        h = h ^ np.uint64(salt)
        h = (h ^ (h >> np.uint64(13))) * np.uint64(0x5BD1E995)
        h = h ^ (h >> np.uint64(15))
    return (h & np.uint64(0xFFFFFF)).astype(np.float64) / float(0x1000000)


def gradient_noise(x, y, salt):
    """Perlin's gradient noise, about -0.7..0.7."""
    i0, j0 = np.floor(x).astype(np.int64), np.floor(y).astype(np.int64)
    fx, fy = x - i0, y - j0

    def corner(di, dj):
        a = 2.0 * np.pi * hash01(i0 + di + 1000, j0 + dj + 1000, salt)
        return np.cos(a) * (fx - di) + np.sin(a) * (fy - dj)

    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    top = corner(0, 0) * (1 - sx) + corner(1, 0) * sx
    bottom = corner(0, 1) * (1 - sx) + corner(1, 1) * sx
    return top * (1 - sy) + bottom * sy


def turbulence(x, y, salt, octaves=4):
    return sum(np.abs(gradient_noise(x * 2**o, y * 2**o, salt + o)) / 2**o for o in range(octaves))


def inks(hexes):
    return np.array([[int(h[k:k + 2], 16) for k in (1, 3, 5)] for h in hexes], dtype=np.float64)


def turbulent_marble():
    v, u = np.mgrid[0:SIDE, 0:SIDE] / SIDE
    t = 5.0 * np.pi * (u + 0.35 * v) + 4.0 * turbulence(3.0 * u, 3.0 * v, 11)
    s = 0.5 + 0.5 * np.sin(t)
    palette = inks(["#1f3a5f", "#c8a24a", "#8c2f2b", "#e8dcc2", "#2f6b62"])
    band = np.minimum((s * len(palette)).astype(int), len(palette) - 1)
    image = palette[band]
    vein = np.abs(np.sin(t)) > 0.985
    image[vein] = [34, 28, 24]
    return image


def stone_battal():
    v, u = np.mgrid[0:SIDE, 0:SIDE] / SIDE
    cells = 7
    wu = u + 0.035 * gradient_noise(9 * u, 9 * v, 31)
    wv = v + 0.035 * gradient_noise(9 * u, 9 * v, 47)
    best = np.full(u.shape, 1e9)
    second = np.full(u.shape, 1e9)
    owner = np.zeros(u.shape, dtype=np.int64)
    for gi in range(-1, cells + 1):
        for gj in range(-1, cells + 1):
            gi_, gj_ = np.array(gi), np.array(gj)
            cx = (gi + 0.15 + 0.7 * hash01(gi_, gj_, 5)) / cells
            cy = (gj + 0.15 + 0.7 * hash01(gi_, gj_, 6)) / cells
            d = np.hypot(wu - cx, wv - cy)
            closer = d < best
            second = np.where(closer, best, np.minimum(second, d))
            best = np.where(closer, d, best)
            owner = np.where(closer, (gi + 1) * 100 + gj + 1, owner)
    palette = inks(["#b5472f", "#d8b25a", "#2d4f7c", "#6f8f4e", "#e6d9bd", "#7a3b5c"])
    colour = (hash01(owner // 100, owner % 100, 77) * len(palette)).astype(int)
    image = palette[colour]
    # Each stone is paler towards its heart, as a drop spreads its ink thinner.
    shade = np.clip(1.0 - 2.5 * best, 0.0, 1.0)[..., None]
    image = image * (1.0 - 0.25 * shade) + 255.0 * 0.25 * shade
    vein = (second - best) < 0.006
    image[vein] = [40, 32, 30]
    return image


def write_png(path, image):
    rgb = np.clip(np.rint(image), 0, 255).astype(np.uint8)
    height, width, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


if __name__ == "__main__":
    write_png(os.path.join(HERE, "turbulent-marble.png"), turbulent_marble())
    write_png(os.path.join(HERE, "stone-battal.png"), stone_battal())
