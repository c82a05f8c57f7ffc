// A poly of order one million: its coefficient count does not fit anywhere.
#version 3.7;
poly { 1000000, <1, 2, 3> }
