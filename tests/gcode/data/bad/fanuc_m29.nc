; expect: FanucRigidTapping 4:1
; rs274: error
G21 G90 G0 X10 Y10 Z5
M29 S500
G84 Z-10 R2 F625
G80
M30
