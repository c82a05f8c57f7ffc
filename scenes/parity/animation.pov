// Parity scene: the animation values POV-Ray's front end declares (clock, clock_delta, clock_on, frame_number,
// initial_frame, final_frame, initial_clock, final_clock) place the objects; a still has them all 0 but clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -8> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }

plane { y, 0 pigment { checker rgb 0.8 rgb 0.4 } }
// A sphere that moves with the clock, and one placed by the frame number within the frame range.
sphere { <-3 + 2 * clock, 1, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.3> } }
#if (clock_on)
  #declare Along = (frame_number - initial_frame) / max(1, final_frame - initial_frame);
  box { <-0.4, 0, -0.4>, <0.4, 0.8 + 4 * clock_delta, 0.4> translate <-2 + 4 * Along, 0, 2>
    pigment { rgb <0.3, 0.6, 0.9> } }
  cylinder { 0, y * (1 + final_clock - initial_clock), 0.3 translate <2, 0, -1> pigment { rgb <0.9, 0.8, 0.3> } }
#else
  torus { 1, 0.2 translate <1.5, 0.2, 0> pigment { rgb <0.5, 0.9, 0.5> } }
#end
