// A radiosity block that loads its samples from an absolute path outside the permitted folders.
#version 3.7;
global_settings { radiosity { load_file "/etc/passwd" } }
sphere { 0, 1 pigment { rgb 1 } }
