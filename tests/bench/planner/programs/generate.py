#!/usr/bin/env python3
"""Generates the planner benchmark programs (deterministic; the .nc files are committed).

Machine coordinates of the shipped GVE64 profile: X 0..400, Y 0..300, Z -120..0 (mm).
    python3 generate.py   # rewrites the .nc files next to this script
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, lines):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("\n".join(lines) + "\n")


def fmt(v):
    return ("%.4f" % v).rstrip("0").rstrip(".") if abs(v) > 5e-5 else "0"


def header(title, spindle=12000):
    return ["(%s)" % title, "G21 G90 G17 G94 G64", "M3 S%d" % spindle, "G0 Z-1"]


def footer():
    return ["G0 Z-1", "M5", "M2"]


def pocket():
    """2.5D zig-zag pocket, 3 depths: long lines, 90-degree corners, step-overs."""
    out = header("pocket: zig-zag 120 x 80 mm, 3 passes")
    out.append("G0 X20 Y20")
    for depth in (-3, -6, -9):
        out.append("G1 Z%s F300" % fmt(depth))
        y, forward = 20.0, True
        out.append("F1800")
        while y <= 100.0 + 1e-9:
            out.append("G1 X%s Y%s" % ("140" if forward else "20", fmt(y)))
            y += 2.5
            if y <= 100.0 + 1e-9:
                out.append("G1 Y%s" % fmt(y))
            forward = not forward
        out.append("G0 Z-1")
        out.append("G0 X20 Y20")
    return out + footer()


def contour():
    """Profile with arcs of many radii (G2/G3), chorded by the planner."""
    out = header("contour: rounded rectangle, slot and circles")
    out += ["G0 X50 Y40", "G1 Z-4 F300", "F2400"]
    for r in (2, 5, 10):
        x0, y0, x1, y1 = 50, 40, 250, 200
        out += [
            "G1 X%s Y%s" % (fmt(x1 - r), fmt(y0)),
            "G3 X%s Y%s R%s" % (fmt(x1), fmt(y0 + r), fmt(r)),
            "G1 Y%s" % fmt(y1 - r),
            "G3 X%s Y%s R%s" % (fmt(x1 - r), fmt(y1), fmt(r)),
            "G1 X%s" % fmt(x0 + r),
            "G3 X%s Y%s R%s" % (fmt(x0), fmt(y1 - r), fmt(r)),
            "G1 Y%s" % fmt(y0 + r),
            "G3 X%s Y%s R%s" % (fmt(x0 + r), fmt(y0), fmt(r)),
            "G1 X50 Y40",
        ]
    for i, r in enumerate((1, 3, 8, 20)):
        cx, cy = 300, 60 + 55 * i
        out += ["G0 Z-1", "G0 X%s Y%s" % (fmt(cx + r), fmt(cy)), "G1 Z-4 F300", "F2400",
                "G2 X%s Y%s I%s J0 P2" % (fmt(cx + r), fmt(cy), fmt(-r))]
    return out + footer()


def surface():
    """3D finishing raster over a wavy surface: dense XZ segments of 0.04 mm (CAM style)."""
    out = header("surface: 3D finishing raster, 0.04 mm segments, F3500")
    out += ["G0 X30 Y30", "G1 Z-5 F300", "F3500"]
    forward = True
    for row in range(12):
        y = 30 + row * 1.0
        xs = [30 + 0.04 * i for i in range(2001)]
        if not forward:
            xs.reverse()
        for x in xs:
            z = -5 + 1.5 * math.sin(x / 6.0) * math.cos(y / 9.0)
            out.append("G1 X%s Y%s Z%s" % (fmt(x), fmt(y), fmt(z)))
        forward = not forward
    return out + footer()


def engrave():
    """Engraving-style spiral and lettering curves from tiny segments (0.02-0.05 mm)."""
    out = header("engrave: spiral and curves, 0.02-0.05 mm segments", 18000)
    out += ["G0 X200 Y150", "G1 Z-0.5 F200", "F1500"]
    t = 0.0
    while t < 16 * math.pi:
        r = 0.4 * t
        out.append("G1 X%s Y%s" % (fmt(200 + r * math.cos(t)), fmt(150 + r * math.sin(t))))
        t += 0.04 / max(r, 0.4)
    out += ["G0 Z-1", "G0 X60 Y250", "G1 Z-0.5 F200", "F1500"]
    s = 0.0
    while s < 240:
        x = 60 + s
        y = 250 + 6 * math.sin(s / 2.0) + 2 * math.sin(s * 1.7)
        out.append("G1 X%s Y%s" % (fmt(x), fmt(y)))
        s += 0.03
    return out + footer()


def adaptive():
    """Adaptive clearing: trochoidal loops (small circles advancing), chorded 0.05-0.2 mm."""
    out = header("adaptive: trochoidal slot, 200 loops")
    out += ["G0 X40 Y120", "G1 Z-6 F300", "F3000"]
    cx, cy, r = 40.0, 120.0, 4.0
    for loop in range(200):
        n = 180
        for k in range(1, n + 1):
            a = 2 * math.pi * k / n
            out.append("G1 X%s Y%s" % (fmt(cx + 0.6 * k / n + r * math.cos(a) - r),
                                      fmt(cy + r * math.sin(a))))
        cx += 0.6
    return out + footer()


def main():
    write("pocket.nc", pocket())
    write("contour.nc", contour())
    write("surface.nc", surface())
    write("engrave.nc", engrave())
    write("adaptive.nc", adaptive())


if __name__ == "__main__":
    main()
