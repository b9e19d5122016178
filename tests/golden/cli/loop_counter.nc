; Counted loop: the condition of the last arithmetic drives BNE.
N0000 @10=4 ;passes
N0001 @11=0 ;X of the pass
N0002 .NEXT @11=@11+2.5*(5-@10)
N0003 G1 X=@11 Y0 F500
N0004 @10=@10-1 BNE .NEXT
N0005 @12=@11/4 @13=-@12
