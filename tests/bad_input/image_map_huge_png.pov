// An image_map PNG whose header claims 60000 x 60000 pixels (10 GB decoded) in a 254-byte file.
#version 3.7;
plane { z, 1 pigment { image_map { png "inc/huge.png" } } }
