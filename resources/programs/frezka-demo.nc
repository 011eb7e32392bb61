(Frezka demo: contour, circle pocket ring and a helix, 3 passes of 1 mm)
(Work zero: part corner, 60 mm below Z home, so it runs on a freshly homed GVE64 profile)
G21 G90 G17 G94
G10 L2 P1 X50 Y50 Z-60
G54
M3 S12000
M8
G0 Z5
G0 X0 Y0
(contour 80 x 50)
G1 Z-1 F300
G1 X80 F900
G1 Y50
G1 X0
G1 Y0
G1 Z-2 F300
G1 X80 F900
G1 Y50
G1 X0
G1 Y0
G1 Z-3 F300
G1 X80 F900
G1 Y50
G1 X0
G1 Y0
G0 Z5
(circle R15 around 40,25)
G0 X55 Y25
G1 Z-1 F300
G3 X55 Y25 I-15 J0 F700
G1 Z-2 F300
G3 X55 Y25 I-15 J0 F700
G0 Z5
(helix R5 down 3 mm)
G0 X45 Y25
G1 Z0 F300
G2 X45 Y25 Z-1.5 I-5 J0 F500
G2 X45 Y25 Z-3 I-5 J0
G0 Z5
G0 X0 Y0
M9
M5
M30
