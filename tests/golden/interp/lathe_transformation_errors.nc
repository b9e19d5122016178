; Rules of G30/G31/G32: RI mandatory and > 0, unchangeable while active, a
; rotary axis in the plane, G30 before another transformation or a plane
; change, designation 2 names only while active, the rotary axis only by
; its designation 2.
; process: 1
; options: continue-after-error
; expect-error: AXIS_DESIGNATION2_INACTIVE
; expect-error: G32_NO_ROTARY_AXIS
; expect-error: G31_PLANE
; expect-error: ARC_ROTARY_AXIS
; expect-error: G32_RI_MISSING
; expect-error: G32_RI_NOT_POSITIVE
; expect-error: G32_RI_NOT_POSITIVE
; expect-error: RI_WITHOUT_G32
; expect-error: G32_RI_CHANGE
; expect-error: TRANSFORMATION_SWITCH
; expect-error: PLANE_CHANGE_IN_TRANSFORMATION
; expect-error: AXIS_TRANSFORMED
; expect-warning: AXIS_DESIGNATION1_IN_TRANSFORMATION
N0001 G0 X40 Z50 C0
N0002 Y1 10
N0003 G32 RI 30
N0004 G31
N0005 G20 Z0 C0 X0
N0006 G2 Z60 C10 I55 J0 F100
N0007 G32
N0008 G32 RI 0
N0009 G32 RI=-5
N0010 RI 30
N0011 G32 RI=30
N0012 G32 RI 30
N0013 G32 RI 31
N0014 G31
N0015 G18
N0016 C10
N0017 G0 Z60 Y1 5
N0018 G30 G18
N0019 M30
