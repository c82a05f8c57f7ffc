#version 3.7;
sphere { 0, 1
