// #fopen read of a file above the scene folder.
#version 3.7;
#fopen F "../../README.md" read
#read (F, S)
