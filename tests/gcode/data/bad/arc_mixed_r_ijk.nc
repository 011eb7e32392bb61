; expect: ArcMixedRAndIjk 4:17
; rs274: error
G21 F100
G2 X10 Y0 I5 J0 R5
M2
