// The square-cup reference scene's punch (doc/reference-scenes.md, section 3):
// 70 x 70 mm, corner radius 10, nose radius 8, face on the sheet's top
// surface (t0 = 0.81 mm). Tools/Punch/Mesh file takes this file directly.
shape = 1; length = 70; width = 70; rc = 10; rp = 8; z0 = 0.81; h = 50;
Include "../punch.geo";
