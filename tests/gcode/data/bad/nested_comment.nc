; expect: NestedComment 4:10
; rs274: error
G21
G0 X1 (a (b) c)
M2
