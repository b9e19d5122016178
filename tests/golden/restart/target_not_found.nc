; M30 ends the program before the target.
N0001 @1=1
N0002 M30
N0003 @2=2 ;target
