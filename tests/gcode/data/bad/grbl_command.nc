; expect: GrblCommand 4:1
; rs274: error
G21 G90
$X
G0 X1
M2
