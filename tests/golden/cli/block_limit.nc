; An endless loop ends at --max-blocks with a diagnostic (exit 1).
N0000 @1=0
N0001 .AGAIN @1=@1+1
N0002 G1 X=@1 F1000
N0003 BRA .AGAIN
