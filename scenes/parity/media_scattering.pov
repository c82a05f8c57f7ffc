// Media: scattering in the atmosphere (isotropic) lit by spotlights and a cylinder light with media_attenuation,
// shadows cast through it, and scattering types 2 to 5 (eccentricity, extinction) in interiors.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -12> look_at <0, 2, 0> angle 55 }
media { scattering { 1, rgb 0.02 } intervals 2 samples 6 }
light_source { <0, 10, -10> color rgb 0.3 media_interaction off }
light_source { <-4, 9, 2> color rgb <1, 0.5, 0.3> * 2 spotlight point_at <-3, 0, 1> radius 8 falloff 14 tightness 2
  media_attenuation on }
light_source { <4, 9, 0> color rgb <0.4, 0.7, 1> * 2 spotlight point_at <2, 0, 2> radius 6 falloff 10 }
light_source { <0, 9, 4> color rgb 1.2 cylinder point_at <0, 0, 4> radius 0.6 falloff 1 media_attenuation on }
plane { y, 0 pigment { rgb 0.6 } }
sphere { <-3, 5, 1>, 0.8 pigment { rgb 0.8 } }
box { <1.6, 4, 1.6>, <2.4, 4.4, 2.4> pigment { rgb 0.8 } }
#macro Ball(Type, Position)
  sphere { 0, 1
    pigment { rgbt 1 } hollow
    interior { media { scattering { Type, rgb <0.6, 0.8, 1> extinction 0.5 } } }
    translate Position
  }
#end
Ball(2, <-4.5, 1.2, -2>)
Ball(3, <-1.5, 1.2, -2>)
Ball(4, <1.5, 1.2, -2>)
sphere { 0, 1
  pigment { rgbt 1 } hollow
  interior { media { scattering { 5, rgb <1, 0.8, 0.6> eccentricity 0.6 } absorption 0.2 } }
  translate <4.5, 1.2, -2>
}
