; expect: UnsupportedMCode 3:1
G21
M100 P1
M2
