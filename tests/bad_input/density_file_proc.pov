// A /proc file as a density_file (it reads as an empty file, then as whatever the process holds).
#version 3.7;
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { emission 1 density { density_file df3 "/proc/self/environ" } } } }
