// The square-cup reference scene's die: opening 74.47 x 74.47 mm, corner
// radius 12.24, entry radius 8, face at z = 0; a block reaching 90 mm.
shape = 1; length = 74.47; width = 74.47; rc = 12.24; rd = 8; reach = 90; h = 50;
Include "../die.geo";
