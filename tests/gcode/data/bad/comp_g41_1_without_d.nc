; expect: CompMissingD 4:1
; rs274: error
G21 G90 F100
G41.1 G1 X20 Y0
M2
