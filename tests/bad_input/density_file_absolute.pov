// A media density_file by an absolute path outside the permitted folders.
#version 3.7;
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { emission 1 density { density_file df3 "/etc/passwd" } } } }
