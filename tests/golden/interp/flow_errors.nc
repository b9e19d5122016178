; Bad program flow and arithmetic: a missing label, a missing program, RTS
; without a call, a division by zero, an unknown variable, an axis the
; process does not have, a spindle it does not have, a word the language
; does not know. The run goes on after each rejected block (check mode).
; process: 0
; options: continue-after-error
; expect-error: LABEL_NOT_FOUND
; expect-error: PROGRAM_NOT_FOUND
; expect-error: RTS_WITHOUT_CALL
; expect-error: DIVISION_BY_ZERO
; expect-error: VARIABLE_RANGE
; expect-error: AXIS_UNKNOWN
; expect-error: AXIS_UNKNOWN
; expect-error: AXIS_UNKNOWN
; expect-error: BLOCK_SYNTAX
; expect-error: EVENT_INVALID
N0001 BRA .NOWHERE
N0002 JSR 77
N0003 RTS
N0004 @1=5 @2=@1/(@1-5)
N0005 @1000=1
N0006 G0 A10
N0007 G0 Z2 10
N0008 S2 100
N0009 H5
N0010 BES .ANY 9:3
N0011 M30
