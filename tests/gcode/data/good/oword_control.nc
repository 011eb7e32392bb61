( hand-written: if/elseif/else, while, do-while, repeat, break, continue )
G21 G90 F500
#1 = 0
o10 while [#1 lt 5]
  #1 = [#1 + 1]
  o11 if [#1 eq 2]
    o10 continue
  o11 elseif [#1 eq 4]
    G1 X[#1 * 10] Y-1
  o11 else
    G1 X[#1 * 10] Y0
  o11 endif
o10 endwhile
#2 = 0
o20 do
  #2 = [#2 + 1]
  G0 Y[#2]
  o21 if [#2 ge 3]
    o20 break
  o21 endif
o20 while [1]
o30 repeat [3]
  G91 G1 X1
  G90
o30 endrepeat
o40 repeat [0]
  G0 X999
o40 endrepeat
#3 = 0
o50 do
  #3 = [#3 + 1]
o50 while [#3 lt 4]
G0 X#3
o<outer> sub
  o<inner> call [#1 * 2]
  G0 Z#<_value>
o<outer> endsub
o<inner> sub
  o<inner> return [#1 + 0.5]
o<inner> endsub
o<outer> call [3]
o60 if [0]
  G0 X1000
o60 endif
o70 if [1]
  G0 X-1
o70 else
  G0 X1000
o70 endif
M30
