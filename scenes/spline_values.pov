// Tests SDL spline values: one path of entries given unsorted, followed by beads under each of the four
// interpolations (linear, quadratic, cubic = Catmull-Rom, natural) from t before the first entry to after the
// last, where each type holds its end value; a copy that adds an entry; and an isosurface of a spline function.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, -0.2 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
#declare Path = spline { 2, <1, 1.5, 0>, 0, <-1, 0.2, 0> 1, <0, 1, 0>, 3, <2, 0.5, 0>, 4, <3, 1.5, 0> }
#declare Colours = array[4] { rgb <0.9, 0.3, 0.2>, rgb <0.2, 0.8, 0.3>, rgb <0.3, 0.4, 0.9>, rgb <0.9, 0.8, 0.2> }
#for (K, 0, 3)
  #declare Typed = spline { Path }
  #for (T, -0.5, 4.5, 0.125)
    sphere { 0, 0.08
      #switch (K)
        #case (0) translate Typed(T, linear_spline) #break
        #case (1) translate Typed(T, quadratic_spline) #break
        #case (2) translate Typed(T, cubic_spline) #break
        #case (3) translate Typed(T, natural_spline) #break
      #end
      translate <-2, 0, 1.5 * K - 1.5> pigment { color Colours[K] } }
  #end
#end
#declare Longer = spline { Path natural_spline 5, <4, 0, 0> }
#for (T, 0, 5, 0.1) sphere { Longer(T) * <1, 1, 0> + <-2, 2.5, 3>, 0.06 pigment { rgb 1 } } #end
#declare Radius = function { spline { natural_spline -1, 0.3, 0, 0.8, 0.5, 0.4, 1, 0.7 } }
isosurface { function { sqrt(x * x + z * z) - Radius(y).u } contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
  max_gradient 3 pigment { color rgb <0.8, 0.5, 0.9> } translate <3.5, 0.8, -1> }
