; Contours a tool cannot follow, and compensation used the wrong way: every
; case is a diagnostic at its block, never a silent wrong path. Check mode
; (continue-after-error): each rejected block is skipped. Tool T2, radius 5.
; process: 0
; options: continue-after-error
; expect-error: COMP_STARTUP_ARC
; expect-error: COMP_ARC_TOO_SMALL
; expect-error: COMP_ELEMENT_TOO_SHORT
; expect-error: COMP_PLANE_CHANGE
; expect-error: COMP_TOOL_CHANGE
; expect-error: COMP_CANCEL_ARC
; expect-error: COMP_BOTTLENECK
N0001 T2 G17 G90 G54 G0 X0 Y0 Z2 F400
N0002 G41 G2 X20 Y0 I10 J0 F400
N0003 G41 G1 X10 Y0
N0004 X30
N0005 G3 X34 Y4 I30 J4
N0006 G1 Y3
N0007 X33 Y20
N0008 G18 X20
N0009 T3 Y30
N0010 G40 G2 X23 Y30 I33 J30
N0011 G1 X10 Y30
N0012 Y10
N0013 X33
N0014 M30
