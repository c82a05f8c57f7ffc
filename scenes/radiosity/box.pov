// A Cornell-like box lit by one point light: the indirect light on the walls, colour bleeding from the red and
// green walls, and the shadowed corners are what the irradiance cache must get right.
// The radiosity block is a moderate setting; tests and tools override it for references.
#version 3.7;
#ifndef (Count) #declare Count = 200; #end
#ifndef (ErrorBound) #declare ErrorBound = 0.5; #end
#ifndef (PretraceEnd) #declare PretraceEnd = 0.02; #end
#ifndef (NearestCount) #declare NearestCount = 10; #end
global_settings {
  assumed_gamma 1.0
  max_trace_level 5
  radiosity {
    count Count
    error_bound ErrorBound
    pretrace_start 0.08
    pretrace_end PretraceEnd
    nearest_count NearestCount
    recursion_limit 2
  }
}
camera { location <0, 1, -3.2> look_at <0, 1, 0> angle 50 }
light_source { <0, 1.9, 0> color rgb 1.5 }
#declare Wall = finish { diffuse 0.8 ambient 0 }
// Floor, ceiling, back wall and the coloured side walls; the front is open.
box { <-1.02, -0.02, -1>, <1.02, 0, 1.02> pigment { rgb 0.8 } finish { Wall } }
box { <-1.02, 2, -1>, <1.02, 2.02, 1.02> pigment { rgb 0.8 } finish { Wall } }
box { <-1.02, 0, 1>, <1.02, 2, 1.02> pigment { rgb 0.8 } finish { Wall } }
box { <-1.02, 0, -1>, <-1, 2, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { Wall } }
box { <1, 0, -1>, <1.02, 2, 1> pigment { rgb <0.1, 0.8, 0.1> } finish { Wall } }
// Two blocks that cast shadows and make concave corners.
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y*20 translate <0.35, 0, -0.2> pigment { rgb 0.8 } finish { Wall } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate -y*15 translate <-0.4, 0, 0.4> pigment { rgb 0.8 } finish { Wall } }
