; expect: NamedParameterUndefined 4:5
; rs274: error
G21
G0 X#<nothing>
M2
