(Exported by FreeCAD)
(Post Processor: linuxcnc_post)
(Output Time:2026-11-21 10:15:02.123456)
(begin preamble)
G17 G54 G40 G49 G80 G90
G21
(begin operation: TC: Default Tool)
(machine units: mm/min)
M5
M6 T1
G43 H1
M3 S1000
(finish operation: TC: Default Tool)
(begin operation: Fixture)
(machine units: mm/min)
G54
(finish operation: Fixture)
(begin operation: Profile)
(machine units: mm/min)
(Profile)
(Compensated Tool Path. Diameter: 5.0)
G0 Z15.000
G0 X10.000 Y7.500 Z15.000
G0 X10.000 Y7.500 Z13.000
G1 X10.000 Y7.500 Z-1.000 F100.000
G2 X7.500 Y10.000 Z-1.000 I0.000 J2.500 F200.000
G1 X7.500 Y40.000 Z-1.000 F200.000
G2 X10.000 Y42.500 Z-1.000 I2.500 J0.000 F200.000
G1 X40.000 Y42.500 Z-1.000 F200.000
G2 X42.500 Y40.000 Z-1.000 I0.000 J-2.500 F200.000
G1 X42.500 Y10.000 Z-1.000 F200.000
G2 X40.000 Y7.500 Z-1.000 I-2.500 J0.000 F200.000
G1 X10.000 Y7.500 Z-1.000 F200.000
G0 Z15.000
(finish operation: Profile)
(begin operation: Drilling)
(machine units: mm/min)
(Drilling)
G0 Z15.000
G90
G98
G0 X25.000 Y25.000
G0 Z15.000
G83 X25.000 Y25.000 Z-6.000 F100.000 Q2.000 R3.000
G81 X30.000 Y25.000 Z-3.000 F100.000 R3.000
G80
G0 Z15.000
(finish operation: Drilling)
(begin postamble)
M05
G17 G54 G90 G80 G40
M2
