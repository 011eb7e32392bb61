; expect: BadCharacter 4:7
; rs274: error
G21
G0 X1 $ Y2
M2
