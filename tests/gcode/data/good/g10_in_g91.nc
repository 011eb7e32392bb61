( hand-written: G10 L2/L20 values are absolute also in G91 )
G21 G91
G0 X1
G10 L2 P1 X5
G0 X1
G10 L20 P1 X2
G0 X1
G90 G0 X0
M2
