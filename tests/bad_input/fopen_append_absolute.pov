// #fopen append to a system file.
#version 3.7;
#fopen Log "/etc/passwd" append
#write (Log, "x\n")
