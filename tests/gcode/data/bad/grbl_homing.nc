; expect: GrblHoming 3:1
; rs274: error
$H
G21 G90
G0 X1
M2
