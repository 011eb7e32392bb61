; expect: NumberExpected 4:4
; rs274: error
G21
G0 X Y2
M2
