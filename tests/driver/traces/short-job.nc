(A short job for the serial traces: spindle on, a few cuts, spindle off)
G21 G90 G17
M3 S8000
G1 X4 Y2 Z-1 F600
G1 X8 Y0
G2 X10 Y2 I0 J2
G1 X4 Y6 F900
G0 Z0
M5
G0 X0 Y0
M2
