// Tests warp { repeat }: a slab of a pattern repeated along x, with offset per slab and flip in odd slabs, and
// transforms written before and after the warp (they apply in written order).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { onion scale 0.6 warp { repeat x*1.5 offset <0, 0, 0.4> flip x } rotate y*10 } }
sphere { <-1.2, 1, 0>, 1 pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }
                                   translate y*0.2 warp { repeat y*0.5 flip y } scale 1.2 } }
box { <0.4, 0, -0.8>, <2.2, 1.6, 0.8> rotate y*-20
      pigment { leopard scale 0.1 warp { repeat z*0.3 offset <0.2, 0.1, 0> } } }
