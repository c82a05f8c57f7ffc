// Grey PNGs as POV-Ray 3.7 reads them: Mount1.png (8-bit grey, gAMA 0.45455) as an image_map, whose texels are
// decoded by the file's own gamma and kept as 8-bit grey through a colour table (dark values fall to whole levels),
// as a bump_map (its stored values), and as a smooth height field, whose levels the colour table moves too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <-6, 10, -5> color rgb 1 }
light_source { <5, 6, -8> color rgb 0.4 }
plane { y, -0.01 pigment { checker rgb 0.7, rgb 0.35 } }
box { <0, 0, 0>, <1, 1, 0.1>
      pigment { image_map { png "Mount1.png" interpolate 2 } }
      finish { ambient 0.3 diffuse 0.7 }
      scale <3, 2.2, 1> translate <-3.4, 0.1, 1.2> }
box { <0, 0, 0>, <1, 1, 0.1>
      pigment { rgb 0.8 }
      normal { bump_map { png "Mount2.png" bump_size 3 } }
      finish { specular 0.4 }
      scale <2.6, 2.2, 1> translate <0.6, 0.1, 1.2> }
height_field { png "Mount1.png" smooth
               pigment { rgb <0.9, 0.7, 0.5> } finish { phong 0.3 }
               translate <-0.5, 0, -0.5> scale <4, 0.9, 2.4> translate <0, 0, -1.6> }
