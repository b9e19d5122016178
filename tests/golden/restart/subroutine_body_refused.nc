; A block of a subroutine body picked without <Plane+>: refused with the
; call to follow (restart.md R-023).
N0001 G0 G54 X0 Y0 Z5
N0002 BSR .LAP
N0003 M30
N0004 .LAP G1 X10 F500
N0005 Y10 ;target without the call
N0006 X0 RTS
