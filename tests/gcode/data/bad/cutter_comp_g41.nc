; expect: CutterCompensation 4:4
; Cutter radius compensation is refused, never skipped.
G21 G90 F100
G0 G41 D1 X10
M2
