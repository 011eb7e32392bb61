; expect: ParameterOutOfRange 4:1
; rs274: error
G21
#6000=1
M2
