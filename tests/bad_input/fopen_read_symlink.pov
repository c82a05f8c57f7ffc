// #fopen read through a symbolic link that leads out of the scene folder.
#version 3.7;
#fopen F "inc/escape.inc" read
#read (F, S)
