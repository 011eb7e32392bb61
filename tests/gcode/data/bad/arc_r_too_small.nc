; expect: ArcRadiusTooSmall 4:11
; rs274: error
G21 F100
G2 X10 Y0 R4
M2
