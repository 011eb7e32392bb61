; expect: FileEndedWithoutEnd 4:1
; rs274: error
G21
G0 X1
