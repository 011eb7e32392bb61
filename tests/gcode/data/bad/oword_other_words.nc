; expect: OwordWithOtherWords 5:10
; rs274: error
G21
o1 if [1]
o1 endif G0 X1
M2
