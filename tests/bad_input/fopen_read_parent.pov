// #fopen read of a file above the scene folder.
// Run with --strict-reads: the source tree may lie below $HOME or /tmp, which Debian's povray.conf lets a scene read.
#version 3.7;
#fopen F "../../README.md" read
#read (F, S)
