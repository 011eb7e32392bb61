; expect: ProgramAborted 10:3
; rs274: error
G21 G90 F100
#1 = 0
o1 if [#1 eq 1]
  (abort, not reached: the branch is skipped)
o1 endif
G1 X10
o2 if [#1 eq 0]
  (ABORT, fixture not clamped)
  G1 X20
o2 endif
M2
