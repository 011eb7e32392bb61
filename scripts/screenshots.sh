#!/usr/bin/env bash
# Makes the README screenshots under Xvfb: the main window with the demo program, in English
# and in Czech. Uses a throw-away settings directory, so the user's settings stay untouched.
#   scripts/screenshots.sh [build-dir]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
cmake --build "$build" --target frezka
out=docs/screenshots
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export XDG_CONFIG_HOME="$tmp/config" XDG_RUNTIME_DIR="$tmp/run"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
shot() { # language png [extra options]; $program: the program (default: the demo)
    local lang=$1 png=$2
    shift 2
    xvfb-run -a -s "-screen 0 1366x768x24" \
        "$build/app/frezka" --language "$lang" --screenshot "$out/$png" "$@" \
        "${program:-resources/programs/frezka-demo.nc}"
    echo "wrote $out/$png"
}
shot en main-window.png
shot cs main-window-cs.png
# Half-way through the demo on the built-in emulator: cut part, tool, DRO, progress, speed.
shot en running.png --screenshot-running 40
# Two GVE114 units on one line (docs/gui.md "Several units on one line"): the mill runs the demo,
# the Units panel shows both units; profiles in a settings directory of their own.
units="$tmp/units/Frezka/frezka"
mkdir -p "$units"
cat > "$units/engraver.json" <<'JSON'
{"name": "Engraver", "unit": {"variant": "gve114"}}
JSON
cat > "$units/machine.json" <<'JSON'
{"name": "Mill", "unit": {"variant": "gve114"}, "motion": {"runBeforeHoming": true},
 "line": {"units": [
     {"address": 0, "variant": "gve114", "name": "Mill", "role": "machine"},
     {"address": 1, "variant": "gve114", "name": "Engraver", "role": "auxiliary",
      "profile": "engraver.json"}]}}
JSON
XDG_CONFIG_HOME="$tmp/units" shot en units-line.png --screenshot-running 15 \
    --screenshot-dock unitsDock
# A height map applied to a PCB-style program (docs/height-map.md "In the 3D view"): the mesh
# over the cuts, its heights exaggerated 100x (View › Height map Z scale) to show the warp.
board="$tmp/board"
mkdir -p "$board/Frezka"
printf '[view]\nheightMapZScale=100\n' > "$board/Frezka/frezka.conf"
awk 'BEGIN {
    print "G21 G90 G94\nG10 L2 P1 X20 Y20 Z-10\nG54\nM3 S10000\nG0 Z2"
    for (k = 0; k < 5; ++k) {
        y = 5 + k * 12
        printf "G0 X5 Y%d\nG1 Z-0.1 F100\nG1 X75 F900\nG1 Y%d\nG1 X5\nG1 Y%d\nG0 Z2\n", y, y + 4, y
    }
    print "G0 X26 Y30\nG1 Z-0.1 F100\nG2 X26 Y30 I-6 J0 F900\nG0 Z2\nM5\nM2"
}' > "$board/board.nc"
awk 'BEGIN {
    print "# frezka-height-map 1\n# origin_x_mm: 20\n# origin_y_mm: 20"
    print "# spacing_x_mm: 10\n# spacing_y_mm: 10\n# count_x: 9\n# count_y: 7"
    print "# reference_z_mm: -10\nx_mm,y_mm,z_mm"
    pi = 3.14159265358979
    for (j = 0; j < 7; ++j)
        for (i = 0; i < 9; ++i) {
            x = 10 * i; y = 10 * j
            z = 0.002 * x + 0.001 * y + 0.05 * sin(x / 100 * 2 * pi) * sin(y / 100 * 2 * pi + 0.5)
            printf "%d,%d,%.4f\n", 20 + x, 20 + y, z
        }
}' > "$board/board-map.csv"
XDG_CONFIG_HOME="$board" xvfb-run -a -s "-screen 0 1366x768x24" "$build/app/frezka" \
    --language en --height-map "$board/board-map.csv" --screenshot "$out/height-map-view.png" \
    "$board/board.nc"
echo "wrote $out/height-map-view.png"
# A program that probes for itself (docs/probing.md "Programs that probe for themselves"), in
# pcb2gcode's autolevel shape: a touch-off, a 3 x 3 grid into #500..#508, the tracks' Z from
# them; everything after the first probe is provisional (dim, dashed) until the probes have run.
auto="$tmp/autolevel"
mkdir -p "$auto"
awk 'BEGIN {
    print "G21 G90 G94\nG10 L2 P1 X20 Y20 Z-10\nG54\nG0 Z5\nG0 X0 Y0\nG38.2 Z-10 F60\nG10 L20 P1 Z0\nG0 Z2"
    for (j = 0; j < 3; ++j)
        for (i = 0; i < 3; ++i)
            printf "G0 X%d Y%d\nG38.2 Z-3 F60\n#%d=#5063\nG0 Z2\n", 30 * i, 30 * j, 500 + 3 * j + i
    print "M3 S10000"
    for (k = 0; k < 5; ++k) {
        y = 5 + k * 12; r = (y < 30) ? 0 : 3
        printf "#1=[[#%d+#%d+#%d]/3-0.1]\nG0 X5 Y%d\nG1 Z#1 F100\nG1 X55 F600\nG1 Y%d\nG1 X5\n", \
            500 + r, 501 + r, 502 + r, y, y + 4
        printf "G1 Y%d\nG0 Z2\n", y
    }
    print "M5\nM2"
}' > "$auto/autolevel.nc"
program="$auto/autolevel.nc" shot en probing-provisional.png
