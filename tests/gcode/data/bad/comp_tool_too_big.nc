; expect: CompToolTooBig 6:1
; rs274: error
G21 G90 F100
G0 X-20 Y0
G41 D1 G1 X0 Y0
G3 X8 Y0 R4
M2
