; expect: CompArcAfterExit 7:1
; rs274: error
G21 G90 F100
G41 D1 G1 X20 Y0
G1 X30
G40
G2 X40 Y0 R5
M2
