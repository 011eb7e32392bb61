N1 g00g17g21g40g49g80g90
N10 g0x0y0
N20 f500
N30 g2x10y-10i10 (CW 270 degrees)
N40 g0x0y0
N50 g3x10y-10i10 (CCW 90 degrees)
N60 g0x0y0
N80 g2x20y0i10 (CW 180 degrees)
N70 g0x0y0
N80 g3x20y0i10 (CCW 180 degrees)
N90 g0x0y0
N99 F1200
N100 g2x0y0i20 (CW 360 degrees)
N110 g2x0y0i20 (CW 360 again)
N120 f700 (Change feed rate while in G2 motion mode)
N130 g2x0y0i20 (CW 360 3rd time)
N140 g2x0y0i20 (CW 360 4th time)
N150 f500
N160 g3x0y0z40i20 (CCW 360 degrees with linear travel)
N170 g3x0y0z0i20 (CCW 360 again)
N180 f700 (msg****Change feed rate while in G3 motion mode****)
N190 g3x0y0i20 (CCW 360 3rd time)
N200 g3x0y0i20 (CCW 360 4th time)
N210 (msg****G18 Eval test****)
N220 G1 X30.707 Z50.727 F500
N230 G18 G02 X67.738 Z23.617 R25 F250
N240 g80
N250 g0x0y0z0
N260 m30
