; expect: DivisionByZero 4:7
; rs274: error
G21
G0 X[1/0]
M2
