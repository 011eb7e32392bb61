; expect: OwordUnmatched 4:1
; rs274: error
G21
o5 endif
M2
