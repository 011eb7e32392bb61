(A slower job for the pause-and-resume trace: long feeds so that a pause falls mid-move)
G21 G90 G17
M3 S6000
G1 X20 Y10 Z-1 F300
G1 X30 Y0 F300
G0 Z0
M5
G0 X0 Y0
M2
