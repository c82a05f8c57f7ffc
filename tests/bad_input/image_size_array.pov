// Run with an absurd +W/+H (image_size_array.args): the scene sizes an array by the image.
#declare Pixels = array[image_width][image_height][4];
