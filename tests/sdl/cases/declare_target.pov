// #declare and #local choose their target table before the value is read: a macro whose body ends the value
// (its last statement is `Q;`) still assigns the caller's table, not its own.
#version 3.7;
#macro Twice(A)
  #local Q = A * 2;
  #if (1)
    Q;
  #else
    0;
  #end
#end
#macro Caller()
  #local R = Twice(3)
  #debug concat("local in macro: ", str(R, 0, 3), "\n")
  #local Q = 5;
  #local Q = Twice(Q)
  #debug concat("own name: ", str(Q, 0, 3), "\n")
  #declare G = Twice(7)
  #debug concat("declare in macro: ", str(G, 0, 3), "\n")
#end
Caller()
#debug concat("global after: ", str(G, 0, 3), "\n")
#ifdef (R) #debug "R leaked\n" #else #debug "R gone\n" #end
#local S = Twice(4)
#debug concat("top level: ", str(S, 0, 3), "\n")
#declare V = 1;
#macro SetV() #declare V = Twice(10) #end
SetV()
#debug concat("declare visible: ", str(V, 0, 3), "\n")
camera {}
sphere { 0, 1 }
