; Nested loops: the 7th arrival at N0004 is in pass 3 of the outer loop.
N0001 @1=0 @2=0
N0002 .OUTER @1=@1+1 @3=0
N0003 .INNER @3=@3+1
N0004 @2=@2+1 ;target
N0005 @4=@3-3 BMI .INNER
N0006 @4=@1-4 BMI .OUTER
N0007 M30
