// A df3 file whose header claims 65535^3 voxels over 16 bytes of data.
#version 3.7;
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { emission 1 density { density_file df3 "inc/huge.df3" } } } }
