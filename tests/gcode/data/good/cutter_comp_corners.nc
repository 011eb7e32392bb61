(Cutter radius compensation: outside and inside corners between lines and arcs, a Z-only)
(move in an inside corner, rapids, G42, G41.1/G42.1 with D, incremental moves, the XZ plane,)
(M1 in the middle, a negative diameter: the other side; tools from cutter_comp_corners.tbl)
G21 G17 G90 G94 F300
T1 M6 G43
S12000 M3
(pocket with G41: inside corners line-line, line-arc, arc-line, arc-arc)
G0 X5 Y5 Z5
G41 D1 G1 X10 Y10
G1 Z-1
G1 X40
G1 Z-2
G1 Y30
G2 X30 Y40 I-10 J0
G1 X15
G3 X10 Y35 I0 J-5
G3 X10 Y20 I25 J-7.5
G1 X10 Y10
G40 G1 X20 Y20
(outside profile with G42, rapids inside the compensation, a dwell queued)
G0 X-20 Y0
G42 G0 X0 Y0
G1 X30 Y0
G4 P0.5
G1 X30 Y20
G3 X10 Y20 R10
G1 X0 Y20
G91 G1 Y-20
G90
M1
G40 G0 X-20 Y-20
(G41.1 with a diameter given, G42.1 with a negative one, G41 with tool 2)
G41.1 D3 G1 X0 Y0
G1 X20 Y5
G2 X30 Y-5 R10
G1 X40 Y-5
G40 G1 X50 Y-20
G42.1 D-1 G1 X0 Y0
G1 X20
G1 Y20
G40 G0 X-10 Y30
G41 D2 G1 X0 Y0
G1 X20
G1 Y20
G40 G0 X-10 Y30
(XZ plane: compensation in Z and X)
G18 G0 X0 Y0 Z0
G42.1 D2 G1 X10 Z0
G1 X10 Z-10
G2 X20 Z-20 I10 K0
G1 X30 Z-20
G40 G1 X40 Z-30
G17
M2
