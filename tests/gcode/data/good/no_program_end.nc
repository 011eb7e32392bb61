( in the style of jscut and FlatCAM: no M2/M30 at the end; Frezka ends the program there with a warning )
G21 G90
G0 Z5
G0 X0 Y0
M3 S10000
G1 Z-0.5 F200
G1 X20 F600
G1 Y20
G3 X0 Y20 R10
G1 Y0
G0 Z5
