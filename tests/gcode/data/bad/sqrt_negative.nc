; expect: DomainError 4:6
; rs274: error
G21
G0 X[sqrt[-1]]
M2
