; expect: ArcMissingCentre 4:1
; rs274: error
G21 F100
G3 X10 Y0
M2
