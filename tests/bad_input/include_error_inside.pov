#include "inc/broken.inc"
sphere { 0, 1 }
