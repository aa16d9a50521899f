// The square-cup reference scene's blank holder (a choice the scene leaves
// open, prm/square-cup-reference.prm): its opening ends where the die
// radius ends, 90.47 x 90.47 mm with corner radius 20.24, sharp edge; face on
// the sheet's top surface (t0 = 0.81 mm); a block reaching 90 mm.
shape = 1; length = 90.47; width = 90.47; rc = 20.24; rh = 0; z0 = 0.81; reach = 90;
Include "../holder.geo";
