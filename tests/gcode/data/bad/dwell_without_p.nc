; expect: DwellMissingP 4:1
; rs274: error
G21
G4
M2
