;Cannot do g1 with zero feed rate
g1x1
