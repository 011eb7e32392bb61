; expect: CompEntryTooShort 4:8
; rs274: error
G21 G90 F100
G41 D1 G1 X4 Y0
M2
