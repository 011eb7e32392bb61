; expect: ToolNumberMissing 4:1
; rs274: error
G21 G90
M61
M2
