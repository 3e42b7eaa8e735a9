// #declare deprecated: the identifier keeps working (POV-Ray only adds warnings, which neither
// capture shows), with and without "once" and a message, for floats, vectors, strings and
// colours, as #local, and redeclared.
#version 3.7;
global_settings { assumed_gamma 1 }

#declare deprecated Old_Float = 2.5;
#declare deprecated once Old_Vector = <1,2,3>;
#declare deprecated "use New_String instead" Old_String = "legacy";
#declare deprecated once "use rgb 1" Old_Colour = rgb <1,0.5,0>;

#debug concat("Old_Float*2 = ", str(Old_Float * 2, 0, 3), "\n")
#debug concat("Old_Float again = ", str(Old_Float, 0, 3), "\n")
#debug concat("Old_Vector = ", vstr(3, Old_Vector, ",", 0, 1), "\n")
#debug concat("Old_Vector.y = ", str(Old_Vector.y, 0, 1), "\n")
#debug concat("Old_String = ", Old_String, "\n")
#debug concat("Old_Colour.green = ", str(Old_Colour.green, 0, 3), "\n")
#ifdef (Old_Float) #debug "Old_Float is defined\n" #end

#macro UsesOld() Old_Float + 1 #end
#debug concat("UsesOld() = ", str(UsesOld(), 0, 3), "\n")

#macro LocalDeprecated()
  #local deprecated Inner = 7;
  #debug concat("Inner = ", str(Inner, 0, 0), "\n")
#end
LocalDeprecated()

#declare Old_Float = 4;
#debug concat("Old_Float after #declare = ", str(Old_Float, 0, 3), "\n")

camera {}
sphere { 0, 1 }
