; expect: ModalGroupConflict 4:5
; G80 beside G0..G3 is ignored as in LinuxCNC; beside a cycle it is refused (rs274 drills).
G21 G90 F100
G81 G80 X1 Y1 Z-1 R1
M2
