(Frezka sample: five-pointed star, 20 mm across, engraved 0.3 mm deep in two passes)
(Work zero: star centre, 60 mm below Z home, so it runs on a freshly homed GVE64 profile)
G21 G90 G17 G94
G10 L2 P1 X100 Y100 Z-60
G54
M3 S18000
G0 Z3
G0 X10 Y0
G1 Z-0.15 F200
G1 X-8.090 Y5.878 F1200
G1 X3.090 Y-9.511
G1 X3.090 Y9.511
G1 X-8.090 Y-5.878
G1 X10 Y0
G1 Z-0.3 F200
G1 X-8.090 Y5.878 F1200
G1 X3.090 Y-9.511
G1 X3.090 Y9.511
G1 X-8.090 Y-5.878
G1 X10 Y0
G0 Z3
G0 X0 Y0
M5
M30
