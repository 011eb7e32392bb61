(MSG**** Inverse Time Motion Test [v1] ****)
g00g17g21g40g49g80g90
g55
g0x0y0
g93
f0.01
g1x10
y10
z10
a10
x0
y0
z0
a0
g1x10y10z-10a10
g0x0y0z0a0
f0.1
g2x10y-10z-20i10
g0x0y0z0
g3x10y-10z-20i10
g0x0y0z0
g2x20y0z-20i10
g0x0y0z0
g3x20y0i10
g0x0y0z0
g2x0y0z-30i10
g3x0y0z0i10
g0x0y0z0
g2x0y0i20 (CW 360 degrees)
g3x0y0i20 (CCW 360 degrees)
g94
g54
g0x0y0
m30
