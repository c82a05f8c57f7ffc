// A closed room lit only by an emissive ceiling panel (no light_source): all light in the picture arrives through
// the cache, as in POV-Ray with `emission` (in a 3.7 radiosity scene `ambient` is not light).
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
camera { location <0, 1.2, -1.9> look_at <0, 0.9, 0> angle 70 }
#declare Matte = finish { diffuse 0.75 ambient 0.2 }
box { <-1.5, 0, -2>, <1.5, 2.2, 1.5> inverse pigment { rgb 0.8 } finish { Matte } }
box { <-1.1, 2.19, -1.2>, <1.1, 2.2, 0.9> pigment { rgb 1 } finish { emission 2 diffuse 0 ambient 0 } }
box { <-1.2, 0, 0.6>, <-0.3, 0.9, 1.3> pigment { rgb <0.2, 0.6, 0.3> } finish { Matte } }
sphere { <0.6, 0.45, 0.3>, 0.45 pigment { rgb <0.85, 0.3, 0.2> } finish { Matte } }
