// A photon map saved to an absolute path outside the permitted folders.
#version 3.7;
global_settings { photons { count 100 save_file "/etc/wardray-photons.ph" } }
sphere { 0, 1 pigment { rgb 1 } }
