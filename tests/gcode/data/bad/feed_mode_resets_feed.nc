; expect: ZeroFeedRate 5:5
; rs274: error
G21 F100
G1 X1
G94 G1 X2 (G93/G94 reset the feed rate)
M2
