; expect: ArcEndEqualsStart 4:10
; rs274: error
G21 F100
G2 X0 Y0 R4
M2
