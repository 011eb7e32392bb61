; expect: CompAlreadyOn 5:1
; rs274: error
G21 G90 F100
G41 D1 G1 X20 Y0
G42 G1 X30
M2
