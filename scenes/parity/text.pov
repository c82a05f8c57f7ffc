// Parity scene: TrueType text from POV-Ray's fonts (straight and curved outlines, holes, kerning, offsets,
// a rotated extrusion seen from the side) and text in CSG, on a floor under two point lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }

light_source { <-6, 10, -8> color rgb 1 }
light_source { <7, 5, -4> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// Serif outlines with holes (e, o, a, B) and a pair kerned by the font.
text { ttf "timrom.ttf" "WardRay AV", 0.4, 0
  scale 1.2 translate <-3.4, 1.6, 0>
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }

// A sans-serif font with extra spacing from the offset vector, turned so its walls show.
text { ttf "cyrvetic.ttf" "Bezier 8", 0.6, <0.1, 0, 0>
  rotate <0, -35, 0> translate <-3.6, 0.05, -0.5>
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.4 phong_size 30 } }

// Text cut out of a box: the glyph's inside decides what the difference keeps.
difference {
  box { <-0.1, -0.1, 0.01>, <2.3, 0.9, 0.3> }
  text { ttf "crystal.ttf" "Oq", 1, 0 translate <0.2, 0.05, -0.2> }
  rotate <0, 25, 0> translate <1.4, 0.01, -1.2>
  pigment { rgb <0.3, 0.8, 0.3> }
}

// Text lying on its back, seen from above, and a povlogo glyph.
text { ttf "timrom" "g&?", 0.25, 0 rotate <90, 0, 0> scale 1.1 translate <-1.2, 0.26, -2.4>
  pigment { rgb <0.9, 0.8, 0.2> } }
text { ttf "povlogo.ttf" "P", 0.3, 0 scale 1.3 translate <2.6, 0.4, 1>
  pigment { rgb <0.7, 0.4, 0.9> } }
