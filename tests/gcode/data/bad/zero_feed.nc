; expect: ZeroFeedRate 4:1
; rs274: error
G21
G1 X1
M2
