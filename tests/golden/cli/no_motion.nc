; --no-motion: the final state without the motion list.
N0000 G0 G90 X5 Y5 Z5
N0001 G1 X15 F400 M108
N0002 @100=G(1) @101=M(5)
