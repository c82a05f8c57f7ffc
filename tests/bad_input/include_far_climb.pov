// A name that climbs far above the scene folder.
#version 3.7;
#include "../../../../../../../../../../etc/hostname"
