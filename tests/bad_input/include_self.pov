// Includes itself forever.
#include "include_self.pov"
