// Tests the density_file df3 pattern as a pigment, a texture pattern and a normal (files written by
// pattern_density_file.py). Rows: top pattern_density_file_8.df3 (5x6x7 voxels of 8 bits, hashed values), bottom
// pattern_density_file_16.df3 (6x5x4 voxels of 16 bits, a smooth wave with a cold and a hot voxel). Columns:
// interpolate 0 (nearest voxel), 1 (trilinear), 2 (tricubic). Each box spans 0.02 … 0.98 of the unit cube the file
// covers (faces exactly on the cube's faces would show POV-Ray's rounding of the hit point: inside or 0), turned so
// that three faces show: its low faces lie in the first voxels, where POV-Ray's tricubic wraps around the grid. The
// colour map makes the value readable; tricubic values above 1 wrap to near 0 in the wave step.
// Behind, a plane: a texture_map chosen by the 8-bit file (interpolate 1), one of its textures with a normal from the
// 16-bit file (interpolate 2), both stretched over the view by the texture's transform (the map's textures move
// with it) so that the outside of the unit cube (value 0) shows too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -8> look_at <0, 0, 0> angle 48 }
light_source { <-4, 6, -9> color rgb 1 }

#declare ValueMap = color_map {
  [0.0 rgb <0.02, 0.02, 0.25>]
  [0.35 rgb <0.1, 0.6, 0.9>]
  [0.7 rgb <0.95, 0.9, 0.2>]
  [1.0 rgb <0.9, 0.15, 0.05>]
}

#macro DF3Box(File, Interpolation, Position)
  box { 0.02, 0.98
    pigment { density_file df3 File interpolate Interpolation color_map { ValueMap } }
    finish { ambient 1 diffuse 0 }
    translate -0.5 rotate <-30, 40, 0> scale 1.2 translate Position }
#end

DF3Box("pattern_density_file_8.df3", 0, <-2.2, 1.05, 0>)
DF3Box("pattern_density_file_8.df3", 1, <0, 1.05, 0>)
DF3Box("pattern_density_file_8.df3", 2, <2.2, 1.05, 0>)
DF3Box("pattern_density_file_16.df3", 0, <-2.2, -1.05, 0>)
DF3Box("pattern_density_file_16.df3", 1, <0, -1.05, 0>)
DF3Box("pattern_density_file_16.df3", 2, <2.2, -1.05, 0>)

plane { z, 2
  texture {
    density_file df3 "pattern_density_file_8.df3" interpolate 1
    texture_map {
      [0.45 pigment { rgb <0.35, 0.3, 0.25> } finish { ambient 0.2 diffuse 0.7 }]
      [0.45 pigment { rgb <0.3, 0.4, 0.5> }
            normal { density_file df3 "pattern_density_file_16.df3" 6 interpolate 2 }
            finish { ambient 0.2 diffuse 0.7 }]
    }
    scale <8, 6, 1> translate <-4.5, -3.2, 1.5>
  }
}
