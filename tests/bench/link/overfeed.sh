#!/usr/bin/env bash
# The dense raster at three times the machine's maximum feed (issue 12): 12 000 segments of
# 0.1 mm over a wavy surface (Z varying), planned and run by frezka-cli on the in-process emulator
# on a virtual clock, for the GVE64 and GVE84 profiles at 1, 8 and 16 ms adapter latency.
# Prints one row per run: job time, the plan's estimate, brake violations, starvation stops,
# vectors per second against the wire's byte limit (the bytes alone, back to back: no round
# trips, no queue), the planner's lower bound with the link's pace (docs/planner.md §7: the
# motion, each packet's round trip and bytes, the unit's queue) and the share of that bound the
# job reached (bound / job: 100 % = as fast as this link and queue allow).
#
#   tests/bench/link/overfeed.sh [BUILD_DIR (default build)] [FEED (default 12000)]
#   FREZKA_CLI=path/to/frezka-cli runs another build's CLI (the table's "before" column).
set -euo pipefail
cd "$(dirname "$0")/../../.."
build="${1:-build}"
feed="${2:-12000}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$feed" > "$work/raster.nc" <<'PY'
import math, sys
feed = int(sys.argv[1])
out = ["(dense raster: 12 rows x 1000 segments of 0.1 mm, Z varying)", "G21 G90 G17 G94 G64",
       "G0 X30 Y30", "G1 Z-5 F300", "F%d" % feed]
for row in range(12):
    y = 30 + row * 0.5
    for j in range(1000):
        t = j if row % 2 == 0 else 1000 - j
        x = 30 + 0.1 * t
        z = -5 + 0.3 * math.sin(x * 0.7) * math.cos(y * 0.3)
        out.append("G1 X%.4f Y%.4f Z%.4f" % (x, y, z))
out += ["G0 Z-1", "M2"]
print("\n".join(out))
PY
printf '%-6s %-8s %9s %9s %7s %6s %6s %10s %10s %6s %9s %7s\n' unit latency job_s est_s job/est brake starve vectors/s wire_lim wire% bound_s bound%
for unit in gve64 gve84; do
    for ms in 1 8 16; do
        json=$("${FREZKA_CLI:-$build/app/frezka-cli}" run "$work/raster.nc" --machine "resources/machines/$unit.json" \
            --port sim --clock virtual --latency-ms "$ms" 2>/dev/null | tail -1)
        python3 - "$unit" "$ms" "$json" <<'PY'
import json, sys
unit, ms, j = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
j.setdefault("estimated_s", float("nan"))  # a frezka-cli from before estimated_s was reported
j.setdefault("bound_s", float("nan"))
print("%-6s %-8s %9.2f %9.2f %7.4f %6d %6d %10.1f %10.1f %5.1f%% %9.2f %6.1f%%" % (
    unit, ms + " ms", j["job_s"], j["estimated_s"], j["job_s"] / j["estimated_s"],
    j["brake_violations"], j["starvation_stops"], j["vectors_per_s"],
    j["wire_limit_vectors_per_s"], 100 * j["vectors_per_s"] / j["wire_limit_vectors_per_s"],
    j["bound_s"], 100 * j["bound_s"] / j["job_s"]))
PY
    done
done
