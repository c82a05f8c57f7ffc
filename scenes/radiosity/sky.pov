// No light source at all: a sky_sphere lights the scene through the cache alone (POV-Ray's sky as a light).
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
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> angle 50 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.85, 0.8>] [0.5 rgb <0.5, 0.7, 1.0>] [1 rgb <0.25, 0.45, 0.9>] } }
}
#declare Matte = finish { diffuse 0.7 ambient 0 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.6 scale 0.5 } finish { Matte } }
sphere { <-1.2, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.5, 0.3> } finish { Matte } }
box { <0.2, 0, -0.6>, <1.6, 1.4, 0.8> rotate y*-20 pigment { rgb 0.85 } finish { Matte } }
// An arch: light reaches under it only after bouncing.
box { <-0.6, 0, 1.5>, <-0.4, 1.2, 2.5> pigment { rgb 0.8 } finish { Matte } }
box { <0.4, 0, 1.5>, <0.6, 1.2, 2.5> pigment { rgb 0.8 } finish { Matte } }
box { <-0.6, 1.2, 1.5>, <0.6, 1.4, 2.5> pigment { rgb 0.8 } finish { Matte } }
