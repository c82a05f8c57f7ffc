// image_map of a picture above the scene folder.
#version 3.7;
plane { z, 1 pigment { image_map { png "../../docs/reports/gi_comparison/box.png" } } }
