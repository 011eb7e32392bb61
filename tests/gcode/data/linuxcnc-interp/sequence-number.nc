





(debug,main: line=#<_line> - expect 7)
o<rm400>call
(debug,main: line=#<_line> - expect 9)
M2
