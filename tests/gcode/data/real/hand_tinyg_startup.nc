G00 G17 G21 G40 G49 G80 G90 (initialize model)
G92 X0 Y0 Z0 (zero system)
G00 x20
y20
z20
a20
G00 x0 y0 z0 a0
G01 f100 x7
y7
z7
a7
G00 x0 y0 z0 a0
G92 x0 y0
