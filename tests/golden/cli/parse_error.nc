; A program with parse errors is not started.
N0000 G0 X10
N0001 G1 X20 Y F100
N0002 M30
