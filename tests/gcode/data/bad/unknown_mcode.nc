; expect: UnknownMCode 4:7
; rs274: error
G21 G90
G0 X1 M47
M2
