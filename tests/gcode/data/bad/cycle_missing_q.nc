; expect: CycleMissingQ 4:1
; rs274: error
G21 F100
G83 X1 Y1 Z-1 R2
M2
