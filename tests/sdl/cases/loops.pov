// #while and #for: counting up and down, fractional steps, empty loops, nesting, loops in macros, and
// the value the #for variable keeps after the loop.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Line(Text) #debug concat(Text, "\n") #end

#declare I = 0;
#declare Text = "while:";
#while (I < 5)
  #declare Text = concat(Text, " ", str(I, 0, 0));
  #declare I = I + 1;
#end
Line(Text)
Line(concat("I after the while = ", str(I, 0, 6)))

#while (0)
  Line("never")
#end
Line("an empty while runs zero times")

#declare Text = "for 1..5:";
#for (K, 1, 5)
  #declare Text = concat(Text, " ", str(K, 0, 0));
#end
Line(Text)
Line(concat("K after #for (K, 1, 5) = ", str(K, 0, 6)))

#declare Text = "for 0..1 by 0.25:";
#for (K, 0, 1, 0.25)
  #declare Text = concat(Text, " ", str(K, 0, 2));
#end
Line(Text)
Line(concat("K after = ", str(K, 0, 6)))

#declare Text = "for 5..1 by -2:";
#for (K, 5, 1, -2)
  #declare Text = concat(Text, " ", str(K, 0, 0));
#end
Line(Text)
Line(concat("K after = ", str(K, 0, 6)))

#declare Text = "for 0..1 by 0.3:";
#for (K, 0, 1, 0.3)
  #declare Text = concat(Text, " ", str(K, 0, 2));
#end
Line(Text)
Line(concat("K after = ", str(K, 0, 6)))

#declare Text = "for 0..1 by 0.1, count:";
#declare Count = 0;
#for (K, 0, 1, 0.1)
  #declare Count = Count + 1;
#end
Line(concat(Text, " ", str(Count, 0, 0), ", K after = ", str(K, 0, 6)))

#declare Text = "for 3..1 (no steps):";
#for (K, 3, 1)
  #declare Text = concat(Text, " ", str(K, 0, 0));
#end
Line(Text)
Line(concat("K after = ", str(K, 0, 6)))

#declare Text = "for 2..2:";
#for (K, 2, 2)
  #declare Text = concat(Text, " ", str(K, 0, 0));
#end
Line(Text)
Line(concat("K after = ", str(K, 0, 6)))

// The loop variable may be changed inside the body.
#declare Text = "for 1..10, body adds 2:";
#for (K, 1, 10)
  #declare Text = concat(Text, " ", str(K, 0, 0));
  #declare K = K + 2;
#end
Line(Text)
Line(concat("K after = ", str(K, 0, 6)))

// Bounds are evaluated once.
#declare Limit = 3;
#declare Text = "for 1..Limit, Limit grows:";
#for (K, 1, Limit)
  #declare Text = concat(Text, " ", str(K, 0, 0));
  #declare Limit = Limit + 1;
#end
Line(Text)

// Nested loops: a multiplication table row by row.
#for (R, 1, 3)
  #declare Text = "";
  #for (C, 1, 4)
    #declare Text = concat(Text, str(R*C, 4, 0));
  #end
  Line(Text)
#end

// A while loop inside a macro with locals, called twice.
#macro Digits(N)
  #local Rest = N;
  #local Out = "";
  #while (Rest > 0)
    #local Out = concat(str(mod(Rest, 10), 0, 0), Out);
    #local Rest = div(Rest, 10);
  #end
  Out
#end
Line(concat("Digits(9021) = ", Digits(9021)))
Line(concat("Digits(7) = ", Digits(7)))

// #for inside a macro with a local loop variable.
#macro SumTo(N)
  #local S = 0;
  #for (J, 1, N)
    #local S = S + J;
  #end
  S
#end
Line(concat("SumTo(100) = ", str(SumTo(100), 0, 0)))
#ifdef (J) Line("J leaked") #else Line("J is local to SumTo") #end

camera {}
sphere { 0, 1 }
