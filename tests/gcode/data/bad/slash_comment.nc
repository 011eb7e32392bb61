; expect: SlashComment 4:7
; rs274: error
G21 G90
G0 X1 // to the start
M2
