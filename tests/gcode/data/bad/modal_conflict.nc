; expect: ModalGroupConflict 4:4
; rs274: error
G21
G0 G1 X1 F100
M2
