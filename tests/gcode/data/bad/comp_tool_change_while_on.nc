; expect: CompNotAllowed 6:4
; rs274: error
G21 G90 F100
G41 D1 G1 X20 Y0
G1 X30
T2 M6
M2
