; expect: WordNotUsed 4:4
; rs274: error
G21 G90 F100
G1 D1 X20 Y0
M2
