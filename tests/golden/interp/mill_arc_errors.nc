; Circles that cannot be executed: the block is rejected, nothing changes.
; process: 0
; options: continue-after-error
; expect-error: FEED_MISSING
; expect-error: ARC_RADIUS_MISMATCH
; expect-error: ARC_CENTER_MISSING
; expect-error: ARC_CENTER_NOT_IN_PLANE
; expect-error: ARC_RADIUS_ZERO
N0001 G0 X10 Y0 Z0
N0002 G2 X0 Y10 I0 J0
N0003 G1 F800 X10 Y0
N0004 G2 X0 Y-10.1 I0 J0
N0005 G3 X0 Y10
N0006 G3 X0 Y10 I0 K0
N0007 G3 X0 Y10 I10 J0
N0008 G3 X0 Y10 I0 J0
N0009 M30
