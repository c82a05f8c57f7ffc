// An absolute path with .. that leads out of the include folder.
#version 3.7;
#include "/usr/share/povray-3.7/include/../../../../etc/hostname"
