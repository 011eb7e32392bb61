; expect: G53NeedsG0OrG1 4:1
; rs274: error
G21 F100
G53 G2 X1 Y1 I1
M2
