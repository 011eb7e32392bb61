; expect: ToolNotInTable 5:5
; rs274: error
G21 G90
T1 M6
G43 H4
G0 Z1
M2
