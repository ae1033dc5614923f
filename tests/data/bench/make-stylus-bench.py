#!/usr/bin/env python3
"""Writes the stylus benchmark designs (docs/performance.md, "Stylus"): 200 drops, then 10
stylus strokes (single styluses and rakes, 300 to 2,000 integration steps each), and the same
design with each stroke replaced by a `line` of the same alpha and lambda from the stroke's
first point towards its last. Deterministic: run it again to get the same files."""
import json
import math
import random
from pathlib import Path

rng = random.Random(24)
here = Path(__file__).resolve().parent


def minimum_steps(stroke):
    pts = stroke["path"]
    length = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
    reach, lam, k = stroke["reach"], stroke["lambda"], stroke.get("tines", 1)
    c_max = 15 * abs(stroke["alpha"]) * max(stroke.get("pressure", [1.0])) / (16 * reach)
    need = max(4 * length / reach, 2 * length * k * c_max * (3.1 / reach + 0.65 / lam + 6.3 * lam / reach**2))
    return math.ceil(need - 1e-9)


drops = []
for i in range(200):
    drops.append({"tool": "drop", "center": [round(rng.uniform(40, 960), 1), round(rng.uniform(40, 960), 1)],
                  "radius": round(rng.uniform(25, 70), 1), "color": i % 5})

strokes = []
tines = [1, 1, 1, 1, 1, 2, 2, 3, 3, 4]
while len(strokes) < 10:
    k = tines[len(strokes)]
    start = [rng.uniform(80, 920), rng.uniform(80, 920)]
    heading = rng.uniform(0, 2 * math.pi)
    points = [start]
    for _ in range(rng.randint(2, 8)):
        heading += rng.uniform(-0.9, 0.9)
        step = rng.uniform(90, 220)
        nxt = [points[-1][0] + step * math.cos(heading), points[-1][1] + step * math.sin(heading)]
        if not (20 < nxt[0] < 980 and 20 < nxt[1] < 980):
            heading += math.pi / 2  # turn away from the edge
            continue
        points.append(nxt)
    if len(points) < 2:
        continue
    stroke = {"tool": "stylus", "path": [[round(x, 1), round(y, 1)] for x, y in points],
              "alpha": round(rng.uniform(20, 45) * rng.choice([1, -1]), 1), "lambda": round(rng.uniform(8, 18), 1),
              "reach": round(rng.uniform(40, 80), 1)}
    if k > 1:
        stroke["tines"] = k
        stroke["spacing"] = round(rng.uniform(25, 45), 1)
    if len(strokes) % 3 == 1:
        stroke["pressure"] = [round(rng.uniform(0.4, 1.0), 2) for _ in stroke["path"]]
    need = minimum_steps(stroke)
    if need > 2000:
        continue
    # The steps a user might give: from 300 to 2,000 (never fewer than the rule asks).
    stroke["steps"] = max(need, [300, 2000, 450, 1200, 600, 900, 350, 1500, 700, 1000][len(strokes)])
    strokes.append(stroke)


def line_of(stroke):
    (ax, ay), (bx, by) = stroke["path"][0], stroke["path"][-1]
    angle = math.degrees(math.atan2(by - ay, bx - ax))
    return {"tool": "line", "origin": [ax, ay], "angle": round(angle, 2), "alpha": stroke["alpha"],
            "lambda": stroke["lambda"]}


def design(name, note, operations):
    return {"format": "marbler-genome", "version": 3, "dimension": 2, "size": [1000, 1000],
            "background": "#f1e9d8", "palette": ["#1f3b5a", "#b8412c", "#e0b44c", "#2e6e5e", "#7a4e8c"],
            "meta": {"name": name, "note": note}, "initial": drops, "operations": operations}


(here / "stylus-10x200.marble.json").write_text(json.dumps(design(
    "Stylus, 10 strokes over 200 drops (benchmark)",
    "200 drops, then 10 stylus strokes (5 single, 5 rakes of 2 to 4 tines, 300 to 2,000 steps); "
    "written by make-stylus-bench.py", strokes), indent=2) + "\n")
(here / "stylus-as-lines-10x200.marble.json").write_text(json.dumps(design(
    "Stylus benchmark with lines (benchmark)",
    "stylus-10x200 with each stroke replaced by a line of the same alpha and lambda from its first "
    "point towards its last; written by make-stylus-bench.py", [line_of(s) for s in strokes]), indent=2) + "\n")
for s in strokes:
    print(len(s["path"]), s.get("tines", 1), s["steps"], minimum_steps(s))
