( hand-written: feeds across units changes, spindle speeds and dwells, compared with rs274 )
( LinuxCNC executes F before G20/G21 and keeps the physical feed across a units change )
G21 G90 G17 G94
F6
G20
G1 X1
G21
G1 X30
G20 F6
G1 X2
F6
G1 X3
G21 F100
G1 X100
S1000
M3
G1 X110
S1500
G2 X120 Y0 I5 J0
M4 S800
G4 P2.5
M5
S2000
G1 X130
M3
G82 X130 Y10 Z-2 R1 P0.75
G80
G0 Z5
G20
G38.3 Z0 F4
M5 M9
M2
