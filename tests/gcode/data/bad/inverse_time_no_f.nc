; expect: InverseTimeFeedMissing 5:1
; rs274: error
G21 G93
G1 X1 F2
G1 X2
M2
