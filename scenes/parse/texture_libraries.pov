// The parse-time benchmark of the scene-language issue: five large standard include files, a few of their
// declarations used (tools/parse_time.py times this file with wardray and with POV-Ray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "textures.inc"
#include "stones.inc"
#include "metals.inc"
#include "woods.inc"

camera { location <0, 1.5, -5> look_at <0, 0.5, 0> angle 40 }
light_source { <4, 6, -5> color White }
plane { y, 0 texture { T_Stone1 } }
sphere { <-1.2, 0.7, 0>, 0.7 texture { T_Brass_3A } }
sphere { <0, 0.7, 0>, 0.7 texture { T_Wood10 } }
sphere { <1.2, 0.7, 0>, 0.7 texture { Polished_Chrome } }
