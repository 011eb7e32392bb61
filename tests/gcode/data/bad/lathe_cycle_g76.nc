; expect: UnsupportedGCode 3:1
G21 G90
G76 P1 Z-10 I-1 J0.1 K1
M2
