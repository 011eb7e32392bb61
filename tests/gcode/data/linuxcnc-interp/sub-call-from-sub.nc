(Test: calling a sub from within another sub is valid)
o<caller> call [1] [2] [3]
M2
