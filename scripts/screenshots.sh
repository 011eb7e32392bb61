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
shot() { # language png [extra options]
    local lang=$1 png=$2
    shift 2
    xvfb-run -a -s "-screen 0 1366x768x24" \
        "$build/app/frezka" --language "$lang" --screenshot "$out/$png" "$@" \
        resources/programs/frezka-demo.nc
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
