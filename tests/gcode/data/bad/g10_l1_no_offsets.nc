; expect: G10L1NoOffsets 4:1
; rs274: error
G21 G90
G10 L1 P1
M2
