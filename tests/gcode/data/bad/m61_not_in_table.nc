; expect: ToolNotInTable 4:5
; rs274: error
G21 G90
M61 Q8
M2
