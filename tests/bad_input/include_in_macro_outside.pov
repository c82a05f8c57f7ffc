// An #include built from strings inside a macro is checked like any other.
#version 3.7;
#macro Load(Dir) #include concat(Dir, "/hostname") #end
Load("/etc")
