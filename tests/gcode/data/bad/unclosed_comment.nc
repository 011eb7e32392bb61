; expect: UnclosedComment 4:7
; rs274: error
G21
G0 X1 (never closed
M2
