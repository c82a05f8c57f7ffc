// image_map: POV-Ray's test.png (a 16-colour palette PNG) planar with once, spherical, cylindrical and torus,
// without interpolation, bilinear and by normalized distance, with gamma 2.2, filter all and transmit all.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 1.2, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.4 } }
box { <0, 0, 0>, <1, 1, 0.1>
      pigment { image_map { png "test.png" map_type 0 once } }
      scale <2.4, 1.5, 1> translate <-3.6, 1.8, 0.5> }
sphere { <0, 0, 0>, 1
         pigment { image_map { png "test.png" gamma 2.2 map_type 1 interpolate 2 } }
         rotate y*30 translate <-2.2, 1, -1> }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.8
           pigment { image_map { png "test.png" map_type 2 interpolate 4 } }
           scale <1, 2, 1> rotate y*-40 translate <0.3, 0, 0.5> }
torus { 1, 0.4
        pigment { image_map { png "test.png" map_type 5 interpolate 2 } }
        rotate x*-60 translate <2.6, 1.3, 0> }
sphere { <0, 0, 0>, 0.7
         pigment { image_map { png "test.png" map_type 1 filter all 0.6 transmit all 0.2 } }
         translate <1.4, 0.7, -2.5> }
