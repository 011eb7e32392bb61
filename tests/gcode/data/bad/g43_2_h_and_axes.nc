; expect: ToolOffsetWords 4:1
; rs274: error
G21 G90
G43.2 H1 Z3
M2
