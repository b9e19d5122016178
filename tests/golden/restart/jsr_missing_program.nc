; JSR to a program that is not in the program memory.
N0001 @1=1
N0002 JSR 42
N0003 @2=2
N0004 M30
