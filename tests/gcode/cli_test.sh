#!/bin/sh
# frezka-cli check / toolpath end to end: exit codes, JSON Lines, FILE:LINE:COL errors.
# usage: cli_test.sh FREZKA_CLI DATA_DIR
cli=$1
data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
    echo "FAIL: $*"
    exit 1
}

# toolpath on a good program: one JSON object per motion, nothing on stderr.
"$cli" toolpath "$data/good/estlcam.nc" >"$tmp/out" 2>"$tmp/err" || fail "toolpath exit $?"
[ -s "$tmp/err" ] && fail "toolpath wrote to stderr: $(cat "$tmp/err")"
[ "$(wc -l <"$tmp/out")" -eq 19 ] || fail "expected 19 motions, got $(wc -l <"$tmp/out")"
head -1 "$tmp/out" | grep -qx '{"line":9,"type":"rapid","x":0.0000,"y":0.0000,"z":5.0000,"a":0.0000,"f":600.0000}' ||
    fail "first motion: $(head -1 "$tmp/out")"
grep -q '"type":"arc",.*"cx":25.0000,"cy":10.0000,"cz":-0.5000,"plane":"XY","turns":-1}' "$tmp/out" ||
    fail "arc fields"
"$cli" toolpath "$data/good/estlcam.nc" --events >"$tmp/out" || fail "toolpath --events"
grep -q '"type":"event","event":"m3","value":20000.0000' "$tmp/out" || fail "events"

# toolpath on a bad program: exit 1, nothing on stdout, the error on stderr.
"$cli" toolpath "$data/bad/zero_feed.nc" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 1 ] || fail "toolpath on a bad program must exit 1"
[ -s "$tmp/out" ] && fail "toolpath on a bad program wrote moves"
grep -q "zero_feed.nc:4:1: G1 with zero feed rate" "$tmp/err" || fail "toolpath error: $(cat "$tmp/err")"

# check: every error as FILE:LINE:COL: message, exit 1.
"$cli" check "$data/bad/arc_radius_mismatch.nc" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 1 ] || fail "check on a bad program must exit 1"
grep -q "arc_radius_mismatch.nc:5:1: Arc end point is not on the circle" "$tmp/err" ||
    fail "check error: $(cat "$tmp/err")"

# check with more errors than it keeps: the rest are counted.
i=0
: >"$tmp/many.nc"
while [ $i -lt 1005 ]; do echo "G1 X1 Q2" >>"$tmp/many.nc"; i=$((i + 1)); done
echo "M2" >>"$tmp/many.nc"
"$cli" check "$tmp/many.nc" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 1 ] || fail "check on many errors must exit 1"
grep -q "many.nc: 5 more error" "$tmp/err" || fail "errors not shown: $(tail -2 "$tmp/err")"
grep -q "many.nc: 1005 error" "$tmp/err" || fail "error count: $(tail -1 "$tmp/err")"

# check on a good program: the summary.
"$cli" check "$data/good/estlcam.nc" >"$tmp/out" 2>"$tmp/err" || fail "check good exit $?"
grep -q "moves: 19 (rapid 5, feed 10, arc 4, probe 0), dwells: 0" "$tmp/out" || fail "summary"
grep -q "bounds (machine, mm): X 0.0000 .. 30.0000, Y 0.0000 .. 25.0000, Z -1.0000 .. 5.0000" \
    "$tmp/out" || fail "bounds: $(cat "$tmp/out")"

# warnings go to stderr as FILE:LINE:COL: warning: ..., and the program still checks OK (check
# plans for the machine too, so the program is one the default GVE64 can run: no M4).
printf 'G21 G90 G17 G94\nG0 X10 Y10\nF6\nG20\nG1 X1\nM2\n' >"$tmp/units.nc"
"$cli" check "$tmp/units.nc" >"$tmp/out" 2>"$tmp/err" || fail "check warnings exit $?: $(cat "$tmp/err")"
grep -q "units.nc:4:1: warning: F6 was read in mm/min (line 3) before this change of units" \
    "$tmp/err" || fail "units warning: $(cat "$tmp/err")"
grep -q "units.nc: OK" "$tmp/out" || fail "check with warnings: $(cat "$tmp/out")"

# splines (butterfly.nc: G5.2/G5.3) are cut as chords within the profile's
# motion.chordToleranceMm: a coarser profile gives fewer feed moves over the same curve.
feeds() { sed -n 's/^moves: .* feed \([0-9]*\),.*/\1/p' "$1"; }
"$cli" check "$data/spline/butterfly.nc" --offset G54:40,35,-31 >"$tmp/out" 2>"$tmp/err" ||
    fail "check butterfly exit $?: $(cat "$tmp/err")"
fine=$(feeds "$tmp/out")
sed 's/"chordToleranceMm": 0.002/"chordToleranceMm": 0.5/' "$data/../../../resources/machines/gve64.json" \
    >"$tmp/coarse.json"
grep -q '"chordToleranceMm": 0.5' "$tmp/coarse.json" || fail "coarse profile"
"$cli" check "$data/spline/butterfly.nc" --machine "$tmp/coarse.json" --offset G54:40,35,-31 \
    >"$tmp/out" 2>"$tmp/err" || fail "check butterfly coarse exit $?: $(cat "$tmp/err")"
coarse=$(feeds "$tmp/out")
[ "$fine" -gt 1000 ] && [ "$coarse" -lt 300 ] || fail "spline feeds: $fine at 0.002 mm, $coarse at 0.5 mm"

# a missing file and a usage error
"$cli" check "$tmp/missing.nc" 2>"$tmp/err"
[ $? -eq 1 ] || fail "missing file must exit 1"
grep -q "missing.nc: Cannot read the file" "$tmp/err" || fail "missing file message"
"$cli" toolpath 2>/dev/null
[ $? -eq 2 ] || fail "usage error must exit 2"
echo OK
