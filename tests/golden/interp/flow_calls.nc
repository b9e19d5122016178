; Subroutines and jumps: BSR/RTS in the same program, a label found in
; program 99, JSR of a program by number and by variable, a label in the
; cycle memory, BRA forward, JMP to another program (which ends this one).
; process: 0
N0001 @1=0
N0002 BSR .SUB1
N0003 BSR .LIB
N0004 JSR 5
N0005 @4=5 JSR @4
N0006 BSR .*CYC
N0007 BRA .SKIP
N0008 @9=99
N0009 .SKIP @2=@1 G19
N0010 JMP 6
N0011 .SUB1 @1=@1+1
N0012 RTS
;== program 99 ==
.LIB @1=@1+10
RTS
;== program 5 ==
N0000 @1=@1+100 @5=G(2)
N0001 RTS
;== cycle *CYCLES ==
.*CYC @1=@1+1000
RTS
;== program 6 ==
N0000 @3=@1 @6=G(2)
N0001 M30
