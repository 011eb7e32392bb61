; expect: AxisWordsWithoutMotion 4:1
; rs274: error
G21
X1 Y2
M2
