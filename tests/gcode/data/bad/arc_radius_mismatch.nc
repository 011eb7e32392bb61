; expect: ArcRadiusMismatch 5:1
; rs274: error
G21 F100
G0 X0 Y0
G2 X10 Y1 I5 J0
M2
