g20 g64 g17
g0x-.2y-.2z0
f30
g40
g1x0y0
g1y1
g3r.25x-.25y1.25
g1x-.5
g2r.25x-.75y1.5
g1y1.75
g0x-.2y-.2z0
g42 d1
g1x0y0
g1y1
g3r.25x-.25y1.25
g1x-.5
g2r.25x-.75y1.5
g1y1.75
g40
g0x.2y-.2z0
g41 d1
g1x0y0
g1y1
g3r.25x-.25y1.25
g1x-.5
g2r.25x-.75y1.5
g1y1.75
g40

g20 g64 g18
g0x-.2z-.2y0
g40
g1x0z0
g1z1
g2r.25x-.25z1.25
g1x-.5
g3r.25x-.75z1.5
g1z1.75
g0x-.2z-.2y0
g42 d1
g1x0z0
g1z1
g2r.25x-.25z1.25
g1x-.5
g3r.25x-.75z1.5
g1z1.75
g40
g0x.2z-.2y0
g41 d1
g1x0z0
g1z1
g2r.25x-.25z1.25
g1x-.5
g3r.25x-.75z1.5
g1z1.75
g40
g0x.2z-.2y0

m2


