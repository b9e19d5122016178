; BSR searches the label in this program, then in program 99 (the
; demo mill library with the tool change .M6).
N0000 T5 BSR .M6
N0001 G0 G54 X0 Y0 Z10
N0002 BSR .LOCAL
N0003 M30
N0004 .LOCAL G1 Z0 F200
N0005 RTS
