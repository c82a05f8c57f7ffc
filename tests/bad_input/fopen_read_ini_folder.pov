// POV-Ray's ini folder is not on the include path: reading from it is refused.
#version 3.7;
#fopen F "/usr/share/povray-3.7/ini/povray.ini" read
#read (F, S)
