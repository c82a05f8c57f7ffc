// Parity scene: material (declared, with texture layers, interior_texture and interior), interior_texture seen
// through an open and a clipped object, double_illuminate on a thin translucent sheet, and light groups with and
// without global_lights.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera { location <0, 3, -9> look_at <0, 0.9, 0> angle 52 }
light_source { <-12, 14, -10> color rgb 0.9 }

plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } }

#declare Glass = material {
  texture { pigment { rgbf <0.9, 1, 0.9, 0.8> } finish { phong 0.6 reflection 0.08 } }
  interior { ior 1.45 fade_distance 1 fade_power 2 fade_color <0.3, 0.8, 0.5> }
}
#declare Painted = material {
  texture { pigment { rgb <0.8, 0.4, 0.2> } }
  texture { pigment { gradient y color_map { [0.5 rgbt 1] [0.5 rgb <0.2, 0.3, 0.8>] } scale 0.4 } }
  interior_texture { pigment { rgb <0.1, 0.9, 0.2> } }
  scale 1.2
}

sphere { <-2.6, 1, 0>, 1 material { Glass } }
// An open cylinder shows its inside surface through the opening.
cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.9 open material { Painted } rotate x*-35 translate <0, 0.3, 0> }
// A clipped sphere: its inside shows the interior texture.
sphere { <2.6, 1, 0>, 1
  texture { pigment { rgb <0.9, 0.8, 0.3> } }
  interior_texture { pigment { rgb <0.5, 0.1, 0.6> } finish { ambient 0.3 } }
  clipped_by { plane { -z, 0.2 } }
}
// Light from behind reaches the near face of the left sheet only (double_illuminate).
box { <-4.6, 0, 2>, <-0.2, 3, 2.05> pigment { rgb 1 filter 0.6 } double_illuminate }
box { <0.2, 0, 2>, <4.6, 3, 2.05> pigment { rgb 1 filter 0.6 } }
light_source { <0, 2, 8> color rgb 0.8 }

// Light groups: a red light for the small spheres only; the left one keeps the global lights.
light_group {
  sphere { <-1, 0.35, -2.5>, 0.35 pigment { rgb 1 } }
  light_source { <0, 3, -4> color rgb <1, 0.2, 0.2> }
  global_lights on
}
light_group {
  sphere { <1, 0.35, -2.5>, 0.35 pigment { rgb 1 } }
  light_source { <0, 3, -4> color rgb <1, 0.2, 0.2> }
}
