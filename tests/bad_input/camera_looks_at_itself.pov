camera { location <1, 2, 3> look_at <1, 2, 3> }
sphere { 0, 1 pigment { rgb 1 } }
