; expect: ArcRadiusMismatch 4:3
; rs274: error
o<s> sub
  G2 X3 Y0 I1 J0 F100
o<s> endsub
G21
o<s> call
M2
