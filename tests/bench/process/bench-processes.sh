#!/usr/bin/env bash
# Whole-process timings, as a user meets them: start-up of the headless verbs, a 2048x2048
# drop+comb render against the straightforward per-pixel loop (perpixel_render), ten stylus
# strokes against ten lines (issue 24), and the time
# from launching the window to its first population shown sharp. Medians of whole processes
# (hyperfine), on a quiet machine. Needs hyperfine and xvfb-run (apt-get install hyperfine xvfb).
#   tests/bench/process/bench-processes.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../../.."
BUILD=${1:-build}
M=$BUILD/app/marbler
PERPIXEL=$BUILD/tests/bench/cpu/perpixel_render
EXAMPLE=tests/data/examples/flame-comb-vortex.marble.json
DROPCOMB=tests/data/bench/drop-comb-50x50.marble.json
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
command -v hyperfine >/dev/null || { echo "needs hyperfine (apt-get install hyperfine)" >&2; exit 2; }

median() { # hyperfine's median (seconds) from its JSON export
    python3 -c 'import json,sys; print("%.3f" % json.load(open(sys.argv[1]))["results"][0]["median"])' "$1"
}
time_cmd() { # NAME COMMAND...: 5 runs after a warm-up, prints the median
    local name=$1
    shift
    hyperfine -N -w 1 -r 5 --export-json "$OUT/t.json" "$*" >/dev/null 2>&1
    printf '%-44s %s s\n' "$name" "$(median "$OUT/t.json")"
}

echo "== start-up (median of 5 whole processes)"
time_cmd "marbler --help" "$M" --help
time_cmd "marbler info" "$M" info "$EXAMPLE"
time_cmd "marbler render, 64 px PNG" "$M" render "$EXAMPLE" -o "$OUT/a.png" --width 64 --quiet

echo "== drop+comb (50 drops, 50 combs) at 2048x2048, uncompressed PPM, 2 threads"
time_cmd "perpixel_render (per-pixel scalar loop)" "$PERPIXEL" "$DROPCOMB" "$OUT/p.ppm" 2048
time_cmd "marbler render" "$M" render "$DROPCOMB" -o "$OUT/m.ppm" --width 2048 --quiet
time_cmd "marbler render, PNG" "$M" render "$DROPCOMB" -o "$OUT/m.png" --width 2048 --quiet
time_cmd "marbler render flame-comb-vortex, PNG" "$M" render "$EXAMPLE" -o "$OUT/f.png" --width 2048 --quiet

# Issue 24: ten stylus strokes over 200 drops, against the same design with lines. The strokes
# take tens of seconds on two cores: the median of 3 runs, no warm-up.
STYLUS=tests/data/bench/stylus-10x200.marble.json
STYLUS_LINES=tests/data/bench/stylus-as-lines-10x200.marble.json
echo "== stylus: 200 drops + 10 strokes at 1024x1024, PNG, every core"
time_cmd "marbler render stylus-as-lines-10x200" "$M" render "$STYLUS_LINES" -o "$OUT/sl.png" --width 1024 --quiet
hyperfine -N -r 3 --export-json "$OUT/t.json" "$M render $STYLUS -o $OUT/s.png --width 1024 --quiet" >/dev/null 2>&1
printf '%-44s %s s\n' "marbler render stylus-10x200" "$(median "$OUT/t.json")"

echo "== the window: launch to the first population shown sharp (median of 5)"
# A fresh home each time: no saved session to resume, no remembered choices.
cat >"$OUT/window.sh" <<SCRIPT
#!/usr/bin/env bash
export HOME=\$(mktemp -d) XDG_CONFIG_HOME= XDG_DATA_HOME=
MARBLER_EXIT_WHEN_SHOWN=1 "$PWD/$M" --flat --seed 7 2>/dev/null | sed -n 's/^first population shown \([0-9.]*\) s.*/\1/p'
rm -rf "\$HOME"
SCRIPT
chmod +x "$OUT/window.sh"
run_window() {
    local times=()
    for _ in 1 2 3 4 5 6; do times+=("$(xvfb-run -a -s "-screen 0 1280x1024x24" "$OUT/window.sh")"); done
    # the first run warms the caches
    printf '%s\n' "${times[@]:1}" | sort -n | sed -n 3p
}
printf '%-44s %s s\n' "window, renderer chosen automatically" "$(run_window)"
printf '%-44s %s s\n' "window, MARBLER_RENDERER=gpu (llvmpipe here)" "$(MARBLER_RENDERER=gpu run_window)"
