// #fopen write to an absolute path that climbs out of a permitted folder with ..
#version 3.7;
#fopen Log "/tmp/../etc/wardray.txt" write
