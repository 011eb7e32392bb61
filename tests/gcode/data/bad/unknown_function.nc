; expect: UnknownFunction 4:6
; rs274: error
G21
G0 X[foo[1]]
M2
