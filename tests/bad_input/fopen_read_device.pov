// A device is outside the permitted folders (and would never end).
#version 3.7;
#fopen F "/dev/urandom" read
#read (F, S)
