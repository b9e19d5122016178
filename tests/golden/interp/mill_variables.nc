; Variables and arithmetic: precedence, parentheses, negation, division,
; assignments seen by later words of the same block, condition code of the
; last arithmetic tested in the same block and in a later block.
; process: 0
N0001 @1=2+3*4 @2=(2+3)*4 @3=-@1+@2/4 @4=7/2 @5=@4*2-7
N0002 @6=1 @7=@6+1 @8=@7*@7
N0003 @10=5-5 BEQ .ZERO
N0004 @90=1
N0005 .ZERO @11=3-5 BMI .NEG
N0006 @91=1
N0007 .NEG @12=4-4
N0008 BPL .PLUS
N0009 @92=1
N0010 .PLUS @13=1 BNE .NOTZ
N0011 @93=1
N0012 .NOTZ @14=0 BNE .NEVER
N0013 @20=0
N0014 .LOOP @20=@20+1 @21=@20-5 BMI .LOOP
N0015 G0 X=@1 Y=@2*2 Z=-@4
N0016 M30
N0017 .NEVER @99=1
N0018 M30
