; expect: WordNotUsed 4:10
; rs274: error
G21 F100
G1 X2 Y1 P1
M2
