; expect: AxisWordsWithG80 4:1
; rs274: error
G21
G80 X1
M2
