; expect: UnsupportedRotation 5:5
G21
G10 L2 P1 X1 Y1 R30
G0 X0 Y0 Z0
G18 G2 X1 Z0 I0.5 K0 F100
M2
