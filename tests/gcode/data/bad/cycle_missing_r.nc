; expect: CycleMissingR 4:1
; rs274: error
G21 F100
G81 X1 Y1 Z-1
M2
