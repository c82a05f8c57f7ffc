#version 3.7;
sphere { 0, 1 } //  ÿþ
#error "a line with control bytes is shown escaped"
