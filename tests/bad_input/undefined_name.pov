camera { location <0, 1, -4> look_at 0 }
sphere { Centre, 1 pigment { rgb 1 } }
