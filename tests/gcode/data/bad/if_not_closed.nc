; expect: OwordNotClosed 3:1
G21
o5 if [0]
G0 X1
M2
