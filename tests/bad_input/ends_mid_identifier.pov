camera { location <0, 0, -3> look_at 0 }
sphe