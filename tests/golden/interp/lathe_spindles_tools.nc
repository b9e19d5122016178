; Spindle words per spindle (S = reference spindle S1, "S2 3000" is spindle 2
; while "S2800" is S = 2800), G92 speed limit, T from the tools list, E, D,
; and their reads.
; process: 1
; options: continue-after-error
; expect-error: TOOL_UNKNOWN
; expect-error: WORD_TWICE
N0001 T3 E1 D2
N0002 S2800 M3
N0003 S2 3000 M203
N0004 S3 1500 M303
N0005 G92 S2500 S2 2000
N0006 @100=S @101=S2 @102=S3 @103=T @104=E @105=SPC @106=S1
N0007 T13
N0008 S1200 S1 1300
N0009 T0 M5 M205 M305
N0010 @107=M(2) @108=M(3) @109=M(4)
N0011 M30
