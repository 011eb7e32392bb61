( hand-written: subroutines defined after M2 and called before, recursion, numbered labels )
G21 G90 F600
o<hole> call [10] [10]
o<hole> call [20] [10]
o200 call [3]
G0 X0 Y0 Z5
M2
o<hole> sub
  G0 X#1 Y#2 Z2
  G1 Z-1
  G0 Z2
o<hole> endsub
o200 sub
  ( recursion: draws #1 steps, then returns )
  o201 if [#1 gt 0]
    G1 X[#1 * 5] Y-5
    o200 call [#1 - 1]
  o201 endif
o200 endsub
