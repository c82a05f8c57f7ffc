// A sphere almost touching a wall and the floor, in a corner: the contact shadows and the narrow gaps, where
// hit distances go to zero, are where irradiance caches leak or blotch.
#version 3.7;
#ifndef (Count) #declare Count = 200; #end
#ifndef (ErrorBound) #declare ErrorBound = 0.5; #end
#ifndef (PretraceEnd) #declare PretraceEnd = 0.02; #end
#ifndef (NearestCount) #declare NearestCount = 10; #end
global_settings {
  assumed_gamma 1.0
  radiosity {
    count Count
    error_bound ErrorBound
    pretrace_start 0.08
    pretrace_end PretraceEnd
    nearest_count NearestCount
    recursion_limit 2
  }
}
camera { location <1.6, 1.4, -2.6> look_at <-0.3, 0.5, 0.3> angle 55 }
light_source { <1.5, 2.6, -1.5> color rgb 1.2 }
#declare Matte = finish { diffuse 0.75 ambient 0 }
plane { y, 0 pigment { rgb 0.75 } finish { Matte } }
plane { -x, 1 pigment { rgb <0.75, 0.55, 0.3> } finish { Matte } }  // the wall at x = -1
plane { -z, -1 pigment { rgb <0.3, 0.45, 0.75> } finish { Matte } }  // the wall at z = 1
sphere { <-0.48, 0.5, 0.2>, 0.5 pigment { rgb 0.85 } finish { Matte } }  // 2 % of its radius from the wall
box { <-0.2, 0, 0.55>, <0.4, 0.8, 0.999> pigment { rgb <0.8, 0.2, 0.2> } finish { Matte } }
