// A photon map loaded from an absolute path outside the permitted folders.
#version 3.7;
global_settings { photons { count 100 load_file "/etc/passwd" } }
sphere { 0, 1 pigment { rgb 1 } }
