; Target behind a JMP: the computing process starts at the beginning of
; this program, so what it set before the JMP is there (seed 000, 2.4).
N0001 T3 G54 S1200 M3 M108
N0002 @40=7
N0003 JMP 5
N0004 M30
