#declare V = vnormalize(<0, 0, 0>);
sphere { V, 1 }
