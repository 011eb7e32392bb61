; expect: SlashComment 3:3
; A "//" comment line (indented); rs274 reads it as block delete and then refuses the second /.
  // roughing pass
G21 G90
G0 X1
M2
