// A radiosity block that saves its samples to an absolute path outside the permitted folders.
#version 3.7;
global_settings { radiosity { save_file "/etc/wardray-radiosity.rad" } }
sphere { 0, 1 pigment { rgb 1 } }
