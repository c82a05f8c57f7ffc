// The sphere's block is never closed.
camera { location <0, 1, -4> look_at 0 }
sphere { 0, 1
  pigment { rgb 1 }
