; expect: ArcWrongPlaneWord 4:14
; rs274: error
G21 F100
G2 X10 Y0 I5 K1
M2
