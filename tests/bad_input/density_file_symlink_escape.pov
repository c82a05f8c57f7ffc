// A density_file through a link in the scene folder that leads outside it.
#version 3.7;
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { emission 1 density { density_file df3 "inc/escape.inc" } } } }
