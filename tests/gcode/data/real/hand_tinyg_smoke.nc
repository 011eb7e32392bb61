(MSG**** Smoke Test [v1] ****)
G00 G17 G21 G40 G49 G80 G90
m3g4p1
m5g4p1
m4g4p1
m3g4p1
m5g4p1
m7g4p1
m9g4p1
m8g4p1
m9
g0x0y0z0
g00 x20
x0
y20
y0
z20
z0
a20
a0
G00 x20 y20 z20 a20
G00 x0 y0 z0 a0
G01 f30 x2 y2 z2 a2
x0 y0 z0 a0
g0x1
g0x0
m2
