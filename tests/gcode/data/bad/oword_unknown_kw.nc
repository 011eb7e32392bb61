; expect: OwordUnknownKeyword 4:4
; rs274: error
G21
o1 goto
M2
