; expect: WordNotUsed 5:7
; rs274: error
G21 F100
G1 X1
G1 X2 I1
M2
