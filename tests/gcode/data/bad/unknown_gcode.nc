; expect: UnknownGCode 4:7
; rs274: error
G21 G90
G0 X1 G12.3
M2
