// image_map of a picture above the scene folder.
// Run with --strict-reads: the source tree may lie below $HOME or /tmp, which Debian's povray.conf lets a scene read.
#version 3.7;
plane { z, 1 pigment { image_map { png "../../docs/reports/gi_comparison/box.png" } } }
