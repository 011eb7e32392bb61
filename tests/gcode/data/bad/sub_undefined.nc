; expect: SubroutineUndefined 3:1
G21
o<nowhere> call
M2
