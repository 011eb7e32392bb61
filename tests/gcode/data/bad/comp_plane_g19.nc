; expect: CompPlane 4:5
; rs274: error
G21 G90 F100
G19 G41 D1 G1 Y20
M2
