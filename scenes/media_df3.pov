// Tests a media density from a DF3 density file (media_df3.df3, 8×8×8 voxels of 8 bits, written by media_df3.py:
// a ramp along x, a dense ring in the middle z layers, an empty column, a bright corner voxel). density_file maps the
// file onto the unit cube <0,0,0>-<1,1,1> (value = voxel / 255, 0 outside the cube); each box is scaled and moved
// after its interior, carrying the density along. The boxes stop 0.001 short of the cube's faces: on a face itself
// the media's first and last samples fall inside or outside the cube (the boundary voxel or 0) by the last bit of
// the hit point, so an image of boxes on the faces records POV-Ray's rounding (shrinking them by 1e-9 changes 19 %
// of POV-Ray's pixels by more than 1/255). Left: interpolate 0 (nearest voxel: blocky); middle: interpolate 1
// (trilinear); right: interpolate 2 (tricubic). Turned so that all three axes show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 1.3, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 10, -6> color rgb 0.8 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
#macro DF3Box(Interpolation, Colour, Position)
  box { 0.001, 0.999 pigment { color rgbt <1, 1, 1, 1> } hollow
    interior { media {
      emission Colour absorption 1.5
      density { density_file df3 "media_df3.df3" interpolate Interpolation }
    } }
    translate -0.5 rotate <-30, 35, 0> scale 1.7 translate Position }
#end
DF3Box(0, <2.4, 1.6, 0.6>, <-2.2, 1.4, 0>)
DF3Box(1, <0.6, 2.0, 2.4>, <0, 1.4, 0>)
DF3Box(2, <2.4, 0.8, 1.8>, <2.2, 1.4, 0>)
