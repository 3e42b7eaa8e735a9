// #switch / #case / #range / #break / #else: first match, fall-through without #break, ranges with
// inclusive ends, several matching clauses, nesting, #switch inside a macro, the 1e-10 tolerance of
// #case, and #break leaving #while and #for loops.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Name(V)
  #switch (V)
    #case (1)
      #debug "one"
    #break
    #case (2)
    #case (3)
      #debug "two or three"
    #break
    #range (4, 6)
      #debug "four to six"
    #break
    #range (6, 10)
      #debug "six to ten"
    #break
    #else
      #debug "something else"
  #end
  #debug concat(" (", str(V, 0, 1), ")\n")
#end
Name(1)
Name(2)
Name(3)
Name(4)
Name(6)
Name(7.5)
Name(10)
Name(10.5)
Name(0)
Name(-1)
Name(1 + 1e-12)

// Fall-through: without #break, the following clauses run too, whatever their values.
#switch (1)
  #case (1)
    #debug "case 1, "
  #case (5)
    #debug "case 5 (fell through), "
  #range (7, 8)
    #debug "range 7..8 (fell through), "
  #break
  #case (9)
    #debug "case 9\n"
#end
#debug "end of fall-through\n"

// #else runs only when nothing matched; a switch with no match and no #else does nothing.
#switch (42)
  #case (1) #debug "no\n" #break
#end
#switch (42)
  #case (1) #debug "no\n" #break
  #else #debug "else for 42\n"
#end

// Nested.
#declare Outer = 2;
#declare Inner = 20;
#switch (Outer)
  #case (1)
    #debug "outer 1\n"
  #break
  #case (2)
    #switch (Inner)
      #case (10) #debug "inner 10\n" #break
      #case (20) #debug "outer 2, inner 20\n" #break
    #end
    #debug "after the inner switch\n"
  #break
  #else
    #debug "outer else\n"
#end

// Expressions and 0.1+0.2 against 0.3 (within 1e-10).
#switch (0.1 + 0.2)
  #case (0.3) #debug "0.1+0.2 matches #case (0.3)\n" #break
  #else #debug "0.1+0.2 does not match 0.3\n"
#end
#switch (3*3)
  #range (1, 2*4) #debug "in 1..8\n" #break
  #range (2*4, 4*4) #debug "in 8..16\n" #break
#end

// #break leaves a loop.
#declare I = 0;
#while (1)
  #declare I = I + 1;
  #if (I >= 4) #break #end
#end
#debug concat("while left at I = ", str(I, 0, 0), "\n")
#declare Text = "for:";
#for (K, 1, 10)
  #if (K = 4) #break #end
  #declare Text = concat(Text, " ", str(K, 0, 0));
#end
#debug concat(Text, "; K after #break = ", str(K, 0, 0), "\n")

camera {}
sphere { 0, 1 }
