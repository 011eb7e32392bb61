g0 x0 y0 z1
s1000
m3
g33.1 z-1.2 k0.1
m2
