; expect: UnsupportedAxis 3:7
G21
G0 X1 B2
M2
