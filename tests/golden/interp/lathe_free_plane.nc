; Free plane selection G20 on the demo lathe (axis definitions X: X,Z;
; Z: Z,X; C (S1): C,Y; Y: Y; Z2: W) with its boundary conditions, G1 and
; G97 forced on activation, G18 restoring the base coordinate system.
; process: 1
; options: continue-after-error
; expect-error: G20_DEFINITION_NOT_ALLOWED
; expect-error: G20_DEFINITION_NOT_ALLOWED
; expect-error: G20_AXIS_TWICE
; expect-error: G20_AXIS_VALUE
; expect-error: G20_AXIS_COUNT
; expect-error: G20_EXTRA_AXIS
; expect-error: G20_DEFINITION_NOT_ALLOWED
; expect-error: G20_DEFINITION_NOT_ALLOWED
; expect-error: G20_DEFINITION_NOT_ALLOWED
; expect-error: G20_DEFINITION_NOT_ALLOWED
; expect-error: G20_PERPENDICULAR_ROTARY
N0001 G0 G96 X50 Z100
N0002 G20 Z0 C0 X0
N0003 @100=G(2) @101=G(1) @102=G(9)
N0004 G18
N0005 G20 Z0 X0
N0006 G20 Z0 C0 Y0
N0007 G20 Z0 C0 Z0
N0008 G20 Z0 C1 X0
N0009 G20 Z0
N0010 G20 Z0 C0 X0 Y0
N0011 G20 C0 Z0 X0
N0012 G20 Z0 X0 C0
N0013 G20 X0 C0 Z0
N0014 @103=G(2)
N0015 M30
