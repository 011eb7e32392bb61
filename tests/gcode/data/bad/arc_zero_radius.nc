; expect: ArcZeroRadius 4:1
; rs274: error
G21 F100
G2 X0 Y0 I0.0001 J0
M2
