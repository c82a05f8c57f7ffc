// Parity scene: the pavement pattern with squares, triangles and hexagons, its pavings and corner forms.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 10, 0> sky z look_at <0, 0, 0> right x * 12 up z * 9 }
light_source { <-20, 40, -10> color rgb 1 }
light_source { <10, 30, 20> color rgb 0.4 }

#declare Fin = finish { ambient 0.15 diffuse 0.8 }
#declare Map = color_map { [0 rgb <0.85, 0.75, 0.6>] [0.6 rgb <0.7, 0.5, 0.35>] [1 rgb <0.15, 0.1, 0.1>] }

// One panel per paving, three across (x), four down (z).
#macro Panel(I, J, Pig)
  box { <-1.9, -1, -1.4>, <1.9, 0, 1.4> translate <(I - 1) * 4, 0, (1.5 - J) * 3>
    texture { pigment { Pig } finish { Fin } } }
#end

Panel(0, 0, pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 35 form 2 interior 1 exterior 2
                      color_map { Map } scale 0.22 })
Panel(1, 0, pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 8 form 1 interior 2 exterior 1
                      color_map { Map } scale 0.25 rotate y * 20 })
Panel(2, 0, pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 16 form 3 exterior 2 color_map { Map }
                      scale 0.2 })
Panel(0, 1, pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 3 form 0 color_map { Map }
                      scale 0.3 translate <0.1, 0, 0.05> })
Panel(1, 1, pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 2 exterior 2
                      color_map { Map } scale 0.3 })
Panel(2, 1, pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 4 form 1 exterior 1 interior 1
                      color_map { Map } scale 0.3 })
Panel(0, 2, pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 7 color_map { Map } scale 0.3
                      rotate y * 15 })
Panel(1, 2, pigment { pavement number_of_sides 3 number_of_tiles 2 form 2 color_map { Map } scale 0.4 })
Panel(2, 2, pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 22 form 2 interior 1 color_map { Map }
                      scale 0.2 })
Panel(0, 3, pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 8 form 1 interior 2 color_map { Map }
                      scale 0.15 })
Panel(1, 3, pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 2 interior 2 color_map { Map }
                      scale 0.2 })
// The default grey map on hexagons, and a pavement normal.
box { <-1.9, -1, -1.4>, <1.9, 0, 1.4> translate <4, 0, -4.5>
  texture { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 2 scale 0.25 }
            normal { pavement number_of_sides 4 number_of_tiles 2 form 2 bump_size 0.6 scale 0.4 } finish { Fin } } }
