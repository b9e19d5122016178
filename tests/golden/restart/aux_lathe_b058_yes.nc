; Lathe: Bxx.058 = Yes, the M functions reach the SPS (S, T, E, Q not).
N0001 T3 S1 1200 M3 M8 Q7
N0002 E2 M68 M19
N0003 @1=1 ;target
N0004 M30
