#version 3.7;
// CRLF line ends: the error is on line 3
sphere { 0, 1 pigment { rgb q } }
