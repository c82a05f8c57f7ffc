// Parity scene: the tiling pattern, tilings 15 to 27 seen from above (the Penrose tilings 25 to 27 about their
// centres), one panel each, then tiling 26 as a normal and tiling 17 choosing textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 10, 0> direction <0, -1, 0> up <0, 0, 16.5> right <22, 0, 0> }
light_source { <-10, 30, 12> color rgb 1 }
background { rgb <0.1, 0.1, 0.12> }

// The patterns are moved off the pixel grid: a pixel centre exactly on a tile edge takes either side by rounding.
#declare Bands = color_map {
    [0.00 rgb <0.10, 0.20, 0.80>] [0.30 rgb <0.90, 0.90, 0.20>] [0.34 rgb <0.95, 0.35, 0.10>]
    [0.64 rgb <0.20, 0.80, 0.30>] [0.68 rgb <0.80, 0.30, 0.80>] [1.00 rgb <0.05, 0.05, 0.05>] }

#macro Centre(I) <mod(I, 5) * 4.25 - 8.5, 0, 4.25 - div(I, 5) * 4.25> #end
#macro Panel(I) box { Centre(I) - <2, 1, 2>, Centre(I) + <2, 0, 2> #end

#declare T = 15;
#while (T <= 27)
    Panel(T - 15)
        pigment { tiling T color_map { Bands } scale 0.8 translate Centre(T - 15) + <0.013, 0, 0.029> }
        finish { ambient 0.25 diffuse 0.75 } }
    #declare T = T + 1;
#end

Panel(13)
    pigment { rgb <0.85, 0.8, 0.7> }
    normal { tiling 26 bump_size 0.6 translate Centre(13) + <0.013, 0, 0.029> }
    finish { ambient 0.1 diffuse 0.9 } }

Panel(14)
    texture { tiling 17
        texture_map {
            [0.0 pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 0.3 diffuse 0.7 }]
            [0.5 pigment { rgb <0.9, 0.9, 0.9> } finish { ambient 0.3 diffuse 0.7 }]
            [1.0 pigment { rgb <0.1, 0.3, 0.9> } finish { ambient 0.3 diffuse 0.7 }] }
        scale 0.7 translate Centre(14) + <0.013, 0, 0.029> } }
