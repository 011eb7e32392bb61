(Tool table: M6 and G43 with lengths from the table, H of another tool, H0, G43.2 H,)
(G43.1 with axis words, G10 L1/L10/L11 changing the table, #5400 = tool in the spindle,)
(G43.1 words shared with a motion, inches, and an arc under an X offset;)
(run with tool_table.tbl.)
G21 G17 G90 G94 F500
T1 M6
G43
G0 X0 Y0 Z10
G1 Z-1
G43 H2
G1 X10 Y5 Z2
G2 X20 Y5 I5 J0
G43 H0
G0 Z5
G43.2 H3
G1 X25 Z-2
G49
G0 Z20
T2 M6 G43
G0 X30 Y10 Z5
G10 L1 P2 Z80 R2
G0 X31
G43
G0 X32 Z4
G0 X[#5400] Y5
G10 L10 P3 Z1
G43 H3
G0 Z0
G10 L11 P7 Z2
G43 H7
G0 X40 Z3 A10
G43.1 Z10 X-2
G1 X45 Z1
G43.1 Z12
G1 G43.1 Z11 X46
G0 Z7 G43.1 X1
G20
G43 H1
G1 X2 Y1 Z0.5 F20
G3 X2.5 Y1.5 R0.5
G21
G49 T3 M6
G43 H0
G0 X0 Y0 Z30
M2
