# Regenerates the genome test files (invalid/, valid/); run from tests/data/genome:
#     python3 make-cases.py
# Each invalid file breaks exactly one rule of genome-format.md; GenomeIOTest.cpp holds the
# expected location and message of each.
import json, copy, os
base2 = {
 "format": "marbler-genome", "version": 1, "dimension": 2, "size": [1000, 800],
 "background": "#f3ecdc", "palette": ["#1f3b5a", "#b8412c", "#e0b44c"],
 "initial": [
   {"tool": "drop", "center": [500, 400], "radius": 140, "color": 0},
   {"tool": "spray", "center": [300, 300], "radius": 50, "color": 1}],
 "operations": [
   {"tool": "comb", "origin": [0, 0], "angle": 0, "alpha": 60, "lambda": 12, "spacing": 80},
   {"tool": "wave", "origin": [0, 0], "angle": 90, "amplitude": 25, "wavelength": 300, "phase": 0},
   {"tool": "line", "origin": [0, 500], "angle": 30, "alpha": 40, "lambda": 10},
   {"tool": "circle", "center": [500, 400], "radius": 200, "alpha": 50, "lambda": 20},
   {"tool": "vortex", "center": [500, 400], "alpha": 100, "lambda": 30}],
 "meta": {"name": "base 2D"}}
base3 = {
 "format": "marbler-genome", "version": 1, "dimension": 3, "size": [1000, 1000, 600],
 "background": "#101010", "palette": ["#ff0000", "#00ff00"],
 "initial": [
   {"tool": "drop", "center": [500, 500, 300], "radius": 100, "color": 0},
   {"tool": "cylinder", "center": [200, 200, 300], "axis": [0, 0, 1], "radius": 60, "color": 1}],
 "operations": [
   {"tool": "comb", "origin": [0, 0, 0], "direction": [1, 0, 0], "normal": [0, 1, 0], "alpha": 60, "lambda": 12, "spacing": 80},
   {"tool": "wave", "origin": [0, 0, 0], "direction": [1, 0, 0], "normal": [0, 0, 1], "shape": "eggcrate",
    "amplitude": [20, 10], "wavelength": [300, 200], "phase": [0, 90]},
   {"tool": "wave", "origin": [0, 0, 0], "direction": [0, 1, 0], "normal": [0, 0, 1], "shape": "ripple",
    "amplitude": 15, "wavelength": 250, "phase": 45},
   {"tool": "sphere", "center": [500, 500, 300], "axis": [0, 1, 1], "radius": 200, "alpha": 50, "lambda": 20},
   {"tool": "circle", "center": [500, 500, 300], "axis": [1, 0, 0], "radius": 150, "alpha": 40, "lambda": 20},
   {"tool": "vortex", "center": [500, 500, 300], "axis": [0, 0, 1], "alpha": 100, "lambda": 30},
   {"tool": "line", "origin": [0, 0, 0], "direction": [1, 1, 0], "normal": [0, 1, 1], "alpha": 30, "lambda": 8}]}
cases = {}
def case(name, base, mutate, text=None):
    g = copy.deepcopy(base)
    if mutate: mutate(g)
    cases[name] = text if text is not None else json.dumps(g, indent=1)
def setk(path, value):
    def f(g):
        o = g
        for k in path[:-1]: o = o[k]
        o[path[-1]] = value
    return f
def delk(path):
    def f(g):
        o = g
        for k in path[:-1]: o = o[k]
        del o[path[-1]]
    return f
case("syntax-error", base2, None, '{\n  "format": "marbler-genome",\n  "version": 1,,\n}\n')
case("not-an-object", base2, None, '[1, 2, 3]\n')
case("format-wrong", base2, setk(["format"], "marbler-genom"))
case("format-missing", base2, delk(["format"]))
case("version-newer", base2, setk(["version"], 3))
case("version-fraction", base2, setk(["version"], 1.5))
case("dimension-four", base2, setk(["dimension"], 4))
case("size-negative", base2, setk(["size", 1], -800))
case("size-count", base2, setk(["size"], [1000, 800, 600]))
case("background-malformed", base2, setk(["background"], "#12345g"))
case("palette-empty", base2, setk(["palette"], []))
case("palette-seventeen", base2, setk(["palette"], ["#000000"] * 17))
case("palette-malformed", base2, setk(["palette", 2], "red"))
case("initial-not-array", base2, setk(["initial"], {"tool": "drop"}))
case("operations-missing", base2, delk(["operations"]))
case("initial-stroke", base2, lambda g: g["initial"].append({"tool": "comb", "origin": [0, 0], "angle": 0, "alpha": 60, "lambda": 12, "spacing": 80}))
case("tool-unknown", base2, setk(["operations", 0, "tool"], "rake"))
case("tool-missing", base2, delk(["operations", 1, "tool"]))
case("tool-3d-only", base2, setk(["operations", 3, "tool"], "sphere"))
case("cylinder-in-2d", base2, setk(["initial", 0], {"tool": "cylinder", "center": [1, 2], "radius": 3, "color": 0}))
case("entry-not-object", base2, setk(["operations", 1], "comb"))
case("param-missing", base2, delk(["operations", 0, "lambda"]))
case("vector-count", base2, setk(["initial", 0, "center"], [1, 2, 3]))
case("number-as-string", base2, setk(["initial", 0, "center", 1], "400"))
case("scalar-as-array", base2, setk(["operations", 2, "angle"], [30]))
case("radius-negative", base2, setk(["operations", 3, "radius"], -2))
case("lambda-zero", base2, setk(["operations", 4, "lambda"], 0))
case("spacing-negative", base2, setk(["operations", 0, "spacing"], -80))
case("wavelength-zero", base2, setk(["operations", 1, "wavelength"], 0))
case("color-fraction", base2, setk(["initial", 1, "color"], 1.5))
case("color-out-of-range", base2, setk(["initial", 0, "color"], 3))
case("color-negative", base2, setk(["initial", 0, "color"], -1))
case("source-in-3d", base3, setk(["source"], {"image": "a.png"}))
case("source-not-object", base2, setk(["source"], "a.png"))
case("source-image-missing", base2, setk(["source"], {"file": "a.png"}))
case("meta-not-object", base2, setk(["meta"], "Blue stone"))
case("direction-zero", base3, setk(["operations", 0, "direction"], [0, 0, 0]))
case("normal-zero", base3, setk(["operations", 6, "normal"], [0, 0, 0]))
case("axis-zero", base3, setk(["initial", 1, "axis"], [0, 0, 0]))
case("normal-parallel", base3, setk(["operations", 0, "normal"], [-2, 0, 0]))
case("eggcrate-single", base3, setk(["operations", 1, "amplitude"], 20))
case("ripple-pair", base3, setk(["operations", 2, "wavelength"], [250, 250]))
case("shape-unknown", base3, setk(["operations", 1, "shape"], "egg"))
case("vector-2d-in-3d", base3, setk(["operations", 3, "center"], [500, 500]))
case("nested-too-deep", base2, None, json.dumps(base2)[:-1] + ', "meta": ' + '[' * 100 + ']' * 100 + '}\n')
case("number-overflow", base2, None, json.dumps(base2, indent=1).replace('"alpha": 60', '"alpha": 1e999', 1))
# Version 2: a 2D design with every version-2 feature (cored swirls, stretch, both flows,
# bleed) and a solid one with cored swirls and bleed.
base2v2 = copy.deepcopy(base2)
base2v2["version"] = 2
base2v2["operations"][3]["core"] = 25
base2v2["operations"][4]["core"] = 40
base2v2["operations"] += [
  {"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": [0, 100, 250, 400, 600, 800], "shift": 40, "power": 0.5},
  {"tool": "flow", "field": "cells", "origin": [0, 0], "angle": 0, "size": [250, 200], "speed": 40, "time": 2, "steps": 64},
  {"tool": "flow", "field": "cavity", "origin": [100, 100], "angle": 10, "size": [600, 500], "speed": -30, "time": 1.5, "steps": 8}]
base2v2["bleed"] = 1.5
base2v2["meta"] = {"name": "base 2D, version 2"}
base3v2 = copy.deepcopy(base3)
base3v2["version"] = 2
base3v2["operations"][3]["core"] = 30
base3v2["operations"][4]["core"] = 12.5
base3v2["operations"][5]["core"] = 60
base3v2["bleed"] = 0.5
stretch = {"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": [0, 500], "shift": 40, "power": 1}
flow = {"tool": "flow", "field": "cells", "origin": [0, 0], "angle": 0, "size": [250, 250], "speed": 10, "time": 1, "steps": 10}
case("teeth-one", base2v2, setk(["operations", 5, "teeth"], [0]))
case("teeth-too-many", base2v2, setk(["operations", 5, "teeth"], list(range(1001))))
case("teeth-not-array", base2v2, setk(["operations", 5, "teeth"], 100))
case("teeth-not-number", base2v2, setk(["operations", 5, "teeth", 1], "100"))
case("teeth-not-increasing", base2v2, setk(["operations", 5, "teeth", 2], 100))
case("teeth-decreasing", base2v2, setk(["operations", 5, "teeth", 5], -800))
case("shift-missing", base2v2, delk(["operations", 5, "shift"]))
case("shift-as-string", base2v2, setk(["operations", 5, "shift"], "40"))
case("power-zero", base2v2, setk(["operations", 5, "power"], 0))
case("power-negative", base2v2, setk(["operations", 5, "power"], -1))
case("field-unknown", base2v2, setk(["operations", 6, "field"], "vortex"))
case("field-missing", base2v2, delk(["operations", 7, "field"]))
case("flow-size-count", base2v2, setk(["operations", 6, "size"], [250]))
case("flow-size-zero", base2v2, setk(["operations", 6, "size", 1], 0))
case("speed-null", base2v2, setk(["operations", 6, "speed"], None))
case("time-zero", base2v2, setk(["operations", 6, "time"], 0))
case("time-negative", base2v2, setk(["operations", 7, "time"], -1.5))
case("steps-fraction", base2v2, setk(["operations", 6, "steps"], 64.5))
case("steps-zero", base2v2, setk(["operations", 6, "steps"], 0))
case("steps-too-many", base2v2, setk(["operations", 6, "steps"], 10001))
case("steps-too-few", base2v2, setk(["operations", 6, "steps"], 15))
case("steps-impossible", base2v2, setk(["operations", 6, "speed"], 40000))
case("core-negative", base2v2, setk(["operations", 4, "core"], -1))
case("core-as-string", base2v2, setk(["operations", 3, "core"], "25"))
case("bleed-negative", base2v2, setk(["bleed"], -0.5))
case("bleed-as-string", base2v2, setk(["bleed"], "1"))
case("stretch-in-3d", base3v2, lambda g: g["operations"].append(dict(stretch, origin=[0, 0, 0])))
case("flow-in-initial", base2v2, lambda g: g["initial"].append(flow))
case("v1-stretch", base2, lambda g: g["operations"].append(stretch))
case("v1-flow", base2, lambda g: g["operations"].append(flow))
case("v1-core", base2, setk(["operations", 4, "core"], 10))
case("v1-core-zero", base2, setk(["operations", 3, "core"], 0))
case("v1-core-3d", base3, setk(["operations", 3, "core"], 30))
case("v1-bleed", base2, setk(["bleed"], 1))
for name, text in cases.items():
    open(f"invalid/{name}.marble.json", "w").write(text if text.endswith("\n") else text + "\n")
open("valid/base-2d.marble.json", "w").write(json.dumps(base2, indent=1) + "\n")
open("valid/base-3d.marble.json", "w").write(json.dumps(base3, indent=1) + "\n")
open("valid/base-2d-v2.marble.json", "w").write(json.dumps(base2v2, indent=1) + "\n")
open("valid/base-3d-v2.marble.json", "w").write(json.dumps(base3v2, indent=1) + "\n")
# unknown keys: warned, loaded
g = copy.deepcopy(base2); g["comment"] = "hi"; g["operations"][0]["speed"] = 3; g["source"] = {"image": "paper.png", "fit": "stretch"}
open("valid/unknown-keys.marble.json", "w").write(json.dumps(g, indent=1) + "\n")
# edge cases: shortest doubles, nearly-unit vectors, large and tiny numbers, 2.0 colour index
g = copy.deepcopy(base3)
g["size"] = [1000.5, 0.1, 1e6]
g["initial"][0]["color"] = 1.0
g["initial"][1]["axis"] = [1e-200, 0, 3e-200]
g["operations"][0]["direction"] = [0.1, 0.2, 0.30000000000000004]
g["operations"][0]["normal"] = [1, 1e-8, 0]
g["operations"][6]["normal"] = [1e300, 1e300, 1e299]
g["operations"][1]["phase"] = [-720.125, 1e-300]
g["meta"] = {"name": "edge", "nested": {"list": [1, 2.5, "x", None, True, {"deep": []}]}, "unicode": "Marmorpapier \u00e9\u00f1 \u2603"}
open("valid/edge-3d.marble.json", "w").write(json.dumps(g, indent=1) + "\n")
print(len(cases))
