; expect: RepeatedWord 5:10
; rs274: error
G21 F100
G1 X1
G1 X2 Y3 X4
M2
