// String comparisons with the comparison operators (byte-wise, as strcmp): = != < <= > >=, in #if
// conditions, in ?:, with identifiers and string expressions, and mixed with & and |.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Cmp(A, B)
  #debug concat("\"", A, "\" vs \"", B, "\":",
    #if (A = B) " =", #end
    #if (A != B) " !=", #end
    #if (A < B) " <", #end
    #if (A <= B) " <=", #end
    #if (A > B) " >", #end
    #if (A >= B) " >=", #end
    "\n")
#end
Cmp("abc", "abc")
Cmp("abc", "abd")
Cmp("abd", "abc")
Cmp("ab", "abc")
Cmp("", "a")
Cmp("Z", "a")
Cmp("10", "9")
Cmp("same ", "same")

#declare S = "povtrace";
#if (S = "povtrace") #debug "S = \"povtrace\"\n" #end
#if (S = concat("pov", "trace")) #debug "S = concat(\"pov\", \"trace\")\n" #end
#if (substr(S, 1, 3) = "pov" & strlen(S) = 8) #debug "substr and strlen agree\n" #end
#if (S < "z" | S > "zz") #debug "S < \"z\"\n" #end
#declare R = (S = "x" ? 1 : 2);
#debug concat("(S = \"x\" ? 1 : 2) = ", str(R, 0, 0), "\n")
#declare Eq = (strupr(S) = "POVTRACE");
#debug concat("strupr(S) = \"POVTRACE\" -> ", str(Eq, 0, 0), "\n")

camera {}
sphere { 0, 1 }
