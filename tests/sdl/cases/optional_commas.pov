// POV-Ray takes the commas between the arguments of most built-in functions as optional: fixed
// argument lists (atan2, pow, select, vdot, vaxis_rotate, str, vstr, substr, strcmp) and concat's
// list parse without them. (min and max need their commas, and so does the optional fourth
// argument of select.)
#version 3.7;
global_settings { assumed_gamma 1 }

#debug concat("atan2(1 2) = ", str(atan2(1 2), 0, 6), "\n")
#debug concat("pow(2 10) = ", str(pow(2 10), 0, 6), "\n")
#debug concat("select(-1 2 3) = ", str(select(-1 2 3), 0, 6), "\n")
#debug concat("select(0 2 3, 4) = ", str(select(0 2 3, 4), 0, 6), "\n")
#debug concat("mod(7 3) = ", str(mod(7 3), 0, 6), "\n")
#debug concat("vdot(x y) = ", str(vdot(x y), 0, 6), "\n")
#debug concat("vaxis_rotate(x y 90) = ", vstr(3, vaxis_rotate(x y 90), ",", 0, 3), "\n")
#debug concat("vrotate(x <0,0,90>) = ", vstr(3, vrotate(x <0,0,90>), ",", 0, 3), "\n")
#debug concat("str(1/3 0 3) = ", str(1/3 0 3), "\n")
#debug concat("vstr(3 <1,2,3> \",\" 0 1) = ", vstr(3 <1,2,3> "," 0 1), "\n")
#debug concat("substr(\"abcdef\" 2 3) = ", substr("abcdef" 2 3), "\n")
#debug concat("strcmp(\"a\" \"a\") = ", str(strcmp("a" "a"), 0, 0), "\n")
#debug concat("concat without commas: " "a" "b" chr(67) "\n")

camera {}
sphere { 0, 1 }
