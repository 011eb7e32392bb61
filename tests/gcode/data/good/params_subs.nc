( hand-written: parameters, expressions, subroutines with arguments and return values )
#<_depth> = -1.5
#<_safe> = 5
#1 = 10
#2 = [#1 * 2] #3 = #2 (#3 gets the old #2: assignments happen after the line is read)
#3 = #2
G21 G90 G17 F[300 + 100]
o<square> sub
  ( #1 = x, #2 = y, #3 = size )
  G0 X#1 Y#2
  G0 Z#<_safe>
  G1 Z#<_depth>
  G1 X[#1 + #3]
  G1 Y[#2 + #3]
  G1 X#1
  G1 Y#2
  G0 Z#<_safe>
o<square> endsub [#3 * #3]
o100 sub
  o100 return [#1 + 1]
o100 endsub
o<square> call [0] [0] [10]
G0 X#<_value> Y0
o<square> call [#1] [#2] [5]
G0 X[sqrt[#<_value>]]
o100 call [41]
G0 Y#<_value>
#4 = [sin[30] + cos[60] + tan[45]]
G0 X#4 Y[atan[1]/[1]]
G0 X[abs[-3] + fix[2.7] + fup[2.1] + round[2.5]] Y[exp[0] + ln[1] + asin[1] - acos[0]]
G0 X[2 ** 3 ** 2 / 32] Y[7 mod 3 + [-7] mod 3]
G0 X[1 eq 1] Y[[2 gt 1] + [2 ge 2] + [1 lt 2] + [1 le 1] + [1 ne 2]]
G0 X[[1 and 0] + [1 or 0] * 2 + [1 xor 1] * 4] Y[exists[#<_depth>] + exists[#<nothere>] * 2]
#5 = 7
#6 = 5
G0 X##6 Y#[2 + 3]
G0 X#5420 Y#<_y> Z#<_z>
G0 X [ 1 + 2 ] Y - 3 . 5
M2
