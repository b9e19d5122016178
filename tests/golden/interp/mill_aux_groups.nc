; M function groups of the mill (MACHINES.md): last M per group, group 16,
; Q functions, M(n) reads, M=expr and Q=expr, two M of one group rejected,
; and the resets at program end (read back after M30 in the state).
; process: 0
; options: continue-after-error
; expect-error: M_GROUP_CONFLICT
N0001 M3 S1200 M41 M108 M207 M10 M917
N0002 M68 M69 Q9500 Q17
N0003 @100=M(1) @101=M(2) @102=M(3) @103=M(5) @104=M(6) @105=M(7) @106=M(15) @107=M(16)
N0004 @108=M(4) @109=M(14)
N0005 @110=M(2)+1 M=@110
N0006 Q=@110+9000
N0007 M3 M4
N0008 M0
N0009 M1
N0010 @111=M(1) @112=M(16)
N0011 M30
