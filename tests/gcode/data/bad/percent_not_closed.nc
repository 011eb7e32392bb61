%
; expect: FileEndedWithoutPercent 4:1
G21
G0 X1
