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
shot() { # language png
    xvfb-run -a -s "-screen 0 1366x768x24" \
        "$build/app/frezka" --language "$1" --screenshot "$out/$2" \
        resources/programs/frezka-demo.nc
    echo "wrote $out/$2"
}
shot en main-window.png
shot cs main-window-cs.png
