; expect: UnsupportedGCode 3:1
G21 G90 F100 S500 M3
G33 Z-10 K1.5
M2
