(Polar coordinates: @ radius and ^ angle in G90 and G91, alone and together, in G0/G1/G2,)
(in canned cycles with L repeats, and under a work offset)
G21 G17 G90 F200
G10 L2 P1 X5 Y-3
G0 @10 ^30
G1 ^60
G1 @15
G91 G1 ^15
G1 @-5
G1 @2 ^-45
G90 G2 @10 ^0 R10
G0 Z5
G91 G81 ^45 R1 Z-4 L4
G90 G81 @20 ^10 R6 Z-2
G80
G90 G0 X0 Y0
M2
