// The built-in vector functions: vlength, vdot, vcross, vnormalize, vrotate (x, then y, then z, in
// degrees), vaxis_rotate (any axis, not necessarily of unit length), with floats promoted to vectors.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro ShowF(Label, Value)
  #debug concat(Label, " = ", str(Value, 0, 6), "\n")
#end
#macro ShowV(Label, Value)
  #debug concat(Label, " = <", vstr(3, Value, ", ", 0, 6), ">\n")
#end

ShowF("vlength(<3,4,0>)", vlength(<3,4,0>))
ShowF("vlength(<1,-2,2>)", vlength(<1,-2,2>))
ShowF("vlength(2)", vlength(2))
ShowF("vlength(0)", vlength(0))
ShowF("vdot(<1,2,3>,<4,-5,6>)", vdot(<1,2,3>,<4,-5,6>))
ShowF("vdot(x,y)", vdot(x,y))
ShowF("vdot(<1,2,3>,2)", vdot(<1,2,3>,2))
ShowV("vcross(x,y)", vcross(x,y))
ShowV("vcross(y,x)", vcross(y,x))
ShowV("vcross(<1,2,3>,<4,5,6>)", vcross(<1,2,3>,<4,5,6>))
ShowV("vnormalize(<1,2,2>)", vnormalize(<1,2,2>))
ShowV("vnormalize(<0,-3,0>)", vnormalize(<0,-3,0>))
ShowV("vnormalize(1)", vnormalize(1))
ShowV("vrotate(<1,2,3>,<30,45,60>)", vrotate(<1,2,3>,<30,45,60>))
ShowV("vrotate(<2,1,1>,<0,0,90>)", vrotate(<2,1,1>,<0,0,90>))
ShowV("vrotate(<1,1,2>,<0,90,0>)", vrotate(<1,1,2>,<0,90,0>))
ShowV("vrotate(<1,2,1>,<90,0,0>)", vrotate(<1,2,1>,<90,0,0>))
ShowV("vrotate(<1,2,3>,-20*y)", vrotate(<1,2,3>,-20*y))
ShowV("vaxis_rotate(<1,2,3>,x,30)", vaxis_rotate(<1,2,3>,x,30))
ShowV("vaxis_rotate(<2,1,1>,y,90)", vaxis_rotate(<2,1,1>,y,90))
ShowV("vaxis_rotate(<1,2,3>,<1,1,1>,120)", vaxis_rotate(<1,2,3>,<1,1,1>,120))
ShowV("vaxis_rotate(<1,2,3>,<0,0,5>,45)", vaxis_rotate(<1,2,3>,<0,0,5>,45))
ShowV("vaxis_rotate(<1,0.5,2>,<1,2,-1>,-70)", vaxis_rotate(<1,0.5,2>,<1,2,-1>,-70))
ShowV("vrotate then back", vrotate(vrotate(<1,2,3>,<10,20,30>),<-10,0,0>))
ShowF("vlength(vcross(x+y,y+z))", vlength(vcross(x+y,y+z)))

camera {}
sphere { 0, 1 }
