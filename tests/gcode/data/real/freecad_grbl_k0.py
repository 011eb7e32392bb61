# Writes freecad_grbl_k0.nc (tests/gcode/data/real/README.md): run with FreeCAD 0.20 (Debian
# freecad-python3, no GUI):
#   freecadcmd -c "import sys; sys.argv=['x', 'freecad_grbl_k0.nc']; exec(open('freecad_grbl_k0.py').read())"
# A rounded rectangle in two passes and a clockwise hole, turned into Path commands by FreeCAD's
# own edge conversion (PathGeom.cmdsForEdge, which writes I J K for arcs) and written by its grbl
# post (grbl_post.export). Part of Frezka (its licence).
import sys
import FreeCAD, Part, Path
from PathScripts import PathGeom
from PathScripts.post import grbl_post

# A 40 x 30 mm rectangle with 5 mm corner radii, cut in two 1 mm passes, as FreeCAD turns
# edges into G-code (PathGeom.cmdsForEdge) and its grbl post writes it.
r = 5.0
w, h = 40.0, 30.0
V = FreeCAD.Vector
def arc(c, a0, a1):
    circ = Part.Circle(c, V(0, 0, 1), r)
    import math
    return Part.ArcOfCircle(circ, math.radians(a0), math.radians(a1)).toShape()
edges = [
    Part.LineSegment(V(r, 0, 0), V(w - r, 0, 0)).toShape(),
    arc(V(w - r, r, 0), -90, 0),
    Part.LineSegment(V(w, r, 0), V(w, h - r, 0)).toShape(),
    arc(V(w - r, h - r, 0), 0, 90),
    Part.LineSegment(V(w - r, h, 0), V(r, h, 0)).toShape(),
    arc(V(r, h - r, 0), 90, 180),
    Part.LineSegment(V(0, h - r, 0), V(0, r, 0)).toShape(),
    arc(V(r, r, 0), 180, 270),
]
cmds = [Path.Command("G0", {"Z": 5.0}), Path.Command("G0", {"X": r, "Y": 0.0})]
for z in (-1.0, -2.0):
    cmds.append(Path.Command("G1", {"X": r, "Y": 0.0, "Z": z, "F": 2.0}))
    for e in edges:
        moved = e.copy()
        moved.translate(V(0, 0, z))
        for c in PathGeom.cmdsForEdge(moved, hSpeed=10.0, vSpeed=2.0):
            cmds.append(c)
cmds.append(Path.Command("G0", {"Z": 5.0}))
# A hole of radius 8 around (20, 15), cut clockwise (the circle's axis -Z): two half arcs.
import math
hole = Part.Circle(V(20, 15, -1.0), V(0, 0, -1), 8.0)
halves = [Part.ArcOfCircle(hole, a0, a1).toShape()
          for a0, a1 in ((0.0, math.pi), (math.pi, 2 * math.pi))]
start = halves[0].Vertexes[0].Point
cmds.append(Path.Command("G0", {"X": start.x, "Y": start.y}))
cmds.append(Path.Command("G1", {"X": start.x, "Y": start.y, "Z": -1.0, "F": 2.0}))
for e in halves:
    for c in PathGeom.cmdsForEdge(e, hSpeed=10.0, vSpeed=2.0):
        cmds.append(c)
cmds.append(Path.Command("G0", {"Z": 5.0}))

doc = FreeCAD.newDocument("k0")
obj = doc.addObject("Path::Feature", "Profile")
obj.Path = Path.Path(cmds)
doc.recompute()
grbl_post.export([obj], sys.argv[-1], "--no-show-editor")
