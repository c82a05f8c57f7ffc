// Parity scene: finishes (reflection forms, metallic, conserve_energy, brilliance, albedo, irid), normal patterns,
// layered textures, texture_map, sky_sphere and fog.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera { location <0, 2.2, -10> look_at <0, 0.6, 0> angle 52 }
light_source { <-15, 25, -20> color rgb 1 }
light_source { <10, 8, -12> color rgb <0.3, 0.3, 0.35> }

sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.8, 0.85, 0.9>] [0.5 rgb <0.3, 0.45, 0.8>] [1 rgb <0.1, 0.2, 0.6>] } }
  pigment { bozo turbulence 0.5 color_map { [0.5 rgbt 1] [0.8 rgbt <1, 1, 1, 0.3>] } scale 0.3 }
}
fog { distance 250 color rgb <0.7, 0.75, 0.8> }

plane { y, -0.6
  texture { pigment { checker rgb 0.7, rgb 0.25 } finish { reflection 0.25 } }
  texture { pigment { gradient x color_map { [0 rgbt <0.9, 0.3, 0.1, 0.6>] [0.5 rgbt 1] [1 rgbt 1] } scale 3 } }
}

#macro Ball(X, Z) sphere { <X * 1.45 - 3.6, 0, Z * 1.5>, 0.6 #end

// Front row: reflection forms.
Ball(0, 0) pigment { rgb <0.8, 0.2, 0.2> } finish { reflection 0.4 phong 0.8 phong_size 60 } }
Ball(1, 0) pigment { rgb <0.2, 0.6, 0.3> } finish { reflection { 0.05, 0.9 falloff 2 } specular 0.6 roughness 0.01 } }
Ball(2, 0) pigment { rgb <0.9, 0.7, 0.2> } finish { ambient 0.05 diffuse 0.3 reflection { 0.8 metallic } metallic phong 0.9 } }
Ball(3, 0) pigment { rgb <0.3, 0.4, 0.9> } finish { reflection { 0.1, 1 fresnel } conserve_energy } interior { ior 1.5 } }
Ball(4, 0) pigment { rgb <0.7, 0.7, 0.7> } finish { reflection { 0.6 exponent 2 } diffuse albedo 0.5 brilliance 3 } }
Ball(5, 0) pigment { rgb <0.9, 0.5, 0.7> } finish { diffuse 0.9 brilliance 0.5 specular 0.8 roughness 0.05 metallic 0.7 } }

// Back row: normals.
Ball(0, 1) pigment { rgb 0.8 } normal { bumps 0.6 scale 0.15 } finish { phong 0.6 } }
Ball(1, 1) pigment { rgb <0.6, 0.8, 1> } normal { dents 1.5 scale 0.3 } finish { specular 0.5 } }
Ball(2, 1) pigment { rgb <1, 0.8, 0.6> } normal { wrinkles 0.8 scale 0.3 } finish { phong 0.5 } }
Ball(3, 1) pigment { rgb <0.7, 0.9, 0.7> } normal { ripples 0.8 frequency 3 scale 0.5 } finish { phong 0.7 reflection 0.2 } }
Ball(4, 1) pigment { rgb <0.9, 0.9, 0.6> } normal { waves 0.7 frequency 2 scale 0.4 }
  finish { phong 0.6 irid { 0.4 thickness 0.3 turbulence 0.2 } } }
Ball(5, 1) pigment { rgb <0.8, 0.6, 0.9> } normal { gradient x 0.6 sine_wave scale 0.2 } finish { phong 0.6 } }

// Texture map and normal on a pattern.
box { <-1.2, -0.6, 2.6>, <1.2, 1.4, 3.2>
  texture {
    gradient x
    texture_map {
      [0.3 pigment { rgb <0.9, 0.2, 0.1> } normal { checker 0.4 scale 0.15 } finish { phong 0.8 }]
      [0.7 pigment { granite color_map { [0 rgb 0.9] [1 rgb 0.2] } scale 0.5 } finish { reflection 0.3 }]
    }
    scale 2.4 translate -1.2 * x
  }
  rotate y * 15
}
