; expect: BreakOutsideLoop 4:1
; rs274: error
G21
o1 break
M2
