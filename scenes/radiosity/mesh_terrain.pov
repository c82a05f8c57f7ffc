// A rippled terrain of 100,352 triangles (one mesh2 made at parse time) in a box lit by one point light: the
// cache on a large mesh, where every gather ray and lookup meets triangles rather than analytic shapes (issue 18's
// comparison scene with a mesh of at least 100k triangles).
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
camera { location <0, 2.4, -3.3> look_at <0, 0.3, 0.2> angle 55 }
light_source { <-0.5, 1.85, -0.3> color rgb 0.7 }
#declare Wall = finish { diffuse 0.8 ambient 0 }
// Ceiling, back wall and the coloured side walls; the front is open and the terrain is the floor.
box { <-1.52, 2, -1.5>, <1.52, 2.02, 1.52> pigment { rgb 0.8 } finish { Wall } }
box { <-1.52, -0.2, 1.5>, <1.52, 2, 1.52> pigment { rgb 0.8 } finish { Wall } }
box { <-1.52, -0.2, -1.5>, <-1.5, 2, 1.5> pigment { rgb <0.8, 0.15, 0.1> } finish { Wall } }
box { <1.5, -0.2, -1.5>, <1.52, 2, 1.5> pigment { rgb <0.1, 0.7, 0.2> } finish { Wall } }

// The terrain: a grid of N x N cells over [-1.5, 1.5]², two triangles a cell, heights from a few ripples.
#declare N = 224;
#declare Height = function(u, v) { 0.12 * sin(11 * u) * cos(8 * v) + 0.05 * sin(27 * (u + 0.6 * v)) }
mesh2 {
  vertex_vectors { (N + 1) * (N + 1)
    #for (J, 0, N)
      #for (I, 0, N)
        #declare U = 3 * I / N - 1.5;
        #declare V = 3 * J / N - 1.5;
        #if (I + J > 0) , #end <U, Height(U, V), V>
      #end
    #end
  }
  face_indices { 2 * N * N
    #for (J, 0, N - 1)
      #for (I, 0, N - 1)
        #declare A = J * (N + 1) + I;
        #if (I + J > 0) , #end <A, A + 1, A + N + 2>, <A, A + N + 2, A + N + 1>
      #end
    #end
  }
  pigment { rgb <0.75, 0.7, 0.6> }
  finish { Wall }
}
// A sphere on the terrain: a shadow and a concave corner with the mesh.
sphere { <0.4, 0.35, 0.2>, 0.3 pigment { rgb 0.8 } finish { Wall } }
