; expect: UnclosedBracket 4:5
; rs274: error
G21
G0 X[1+2
M2
