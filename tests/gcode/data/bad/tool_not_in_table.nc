; expect: ToolNotInTable 4:4
; rs274: error
G21 G90
G0 T9 X1
M6
M2
