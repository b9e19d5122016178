; Mill: Bxx.058..061 = No, nothing reaches the SPS.
N0001 T3 S1200 M3 M108 Q7
N0002 E2 M62
N0003 @1=1 ;target
N0004 M30
