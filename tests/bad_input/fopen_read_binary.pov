// #fopen read of an image: not a data file, reported without echoing it.
#version 3.7;
#fopen F "Mount2.png" read
#read (F, S)
