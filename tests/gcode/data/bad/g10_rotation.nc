; expect: UnsupportedRotation 3:17
G21
G10 L2 P1 X1 Y1 R30
M2
