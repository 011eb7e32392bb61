; expect: CycleRBelowDepth 4:15
; rs274: error
G21 F100
G81 X1 Y1 Z-1 R-2
M2
