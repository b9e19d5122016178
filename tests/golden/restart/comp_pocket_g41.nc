; A pocket 50 x 40 milled with T2 (radius 5) under G41, restarted at the
; second wall (N0006) with ADJUST and REPOS of the test library
; (docs/decisions/compensation.md TC-013). G54 is X-150 Y-80 Z-120, so the
; programmed corner X60 Y10 is machine X-90 Y-70, and the tool centre at the
; inside corner (55, 15) is machine X-95 Y-65: REPOS goes there, not to the
; programmed corner; the final programmed position stays X-90 Y-70.
N0001 T2 S2000 M3
N0002 G0 G17 G90 G54 X30 Y30 Z5
N0003 G1 Z-2 F300
N0004 G41 X30 Y10 ;start-up: centre (30, 15)
N0005 X60 ;centre from (30, 15) to the inside corner (55, 15)
N0006 Y50 ;target
N0007 X10
N0008 Y10
N0009 X30
N0010 G40 X30 Y30
N0011 G0 Z5
N0012 M30
