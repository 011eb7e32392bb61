(MSG**** Squares Motion Test [v1] ****)
g00g17g21g40g49g80g90
g0x0y0
g0x20 (traverse a 20mm square in X and Y)
y20
x0
y0
g1x10f500 (draw a 10mm square in X and Y at F500)
y10
x0
y0
g0z20 (traverse a 20mm square in X and Z)
x20
z0
x0
g1x20y20z20f500 (feed a 20mm diagonal in X, Y and Z)
x0y0z0
x40y40z40 (traverse a 40mm cube in X, Y and Z)
x40y0z0
x0y40z40
x40y40z0
x0y0z40
x0y40z0
x40y0z40
x0y0z0
g80
g0x0y0
g0x1
g0x0
m30
