o<fail>  call
o<fail>  call
M2
