(MSG**** Coordinate offsets test [v1] ****)
g00g17g21g40g49g80g90
g54
g92x0y0z0
f600
(MSG**** test G92 offsets****)
(msgStep 1: Move from 0,0 to 30,0 mm in positive X direction)
(msgStep 2: Reset origin to 0.0 using G92)
(msgStep 3: Move to 20,0. Should move 20 mm in positive X direction and status report should start from 0,0)
(msgStep 4: Move to 0.0   Should move 20 mm in negative X direction and status report should start from 20,0)
g1x30
g92x0
g1x20
g1x0y0
$sr
g92x0
g4p0.5
(MSG**** test G55 offsets****)
(msgStep 1: Set Coordinate system 2 [g55] to offset of 50,50)
(msgStep 2: Select G55 coordinate system)
(msgStep 3: Move to 0,0. Head should move diagonally in +X and +Y and status report should start from 0,0)
g10L2p2x50y50
g55
g0x0y0
g4p0.5
(MSG**** test G53 absolute overrides ****)
(msgStep 1: Run a square in G55 system)
(msgStep 2: Run a square w/G53 override)
g0x0y0
g0x20y0
g0x20y20
g0x0y20
g0x0y0
g4p0.5
g53g0x0y0
g53g0x20y0
g53g0x20y20
g53g0x0y20
g53g0x0y0
g0x0y0
g4p0.5
(MSG**** test Return to home ****)
(msgStep 1: Return to home using G28)
(msgStep 2: Reset to G54 coord system)
g28
g54
m30
