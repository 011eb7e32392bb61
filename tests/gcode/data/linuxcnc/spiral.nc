g20 g64 g90
s3400 m3

g0 z1
g0 x2 y0
g1 z-.1 f24

o100 repeat [800]
g91 g1 @-.0025 ^4.5
o100 endrepeat

g90 g0 z1
m2
