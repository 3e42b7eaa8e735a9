// seed() and rand(): each stream repeats for the same seed, streams are independent of each other,
// fractional and negative seeds, and rand() stays in [0,1].
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Sequence(Label, Stream, Count)
  #local Text = Label;
  #local I = 0;
  #while (I < Count)
    #local Text = concat(Text, " ", str(rand(Stream), 0, 6));
    #local I = I + 1;
  #end
  #debug concat(Text, "\n")
#end

#declare S1 = seed(42);
Sequence("seed(42):", S1, 6)
#declare S2 = seed(42);
Sequence("seed(42) again:", S2, 3)
Sequence("first stream goes on:", S1, 3)
#declare S3 = seed(0);
Sequence("seed(0):", S3, 5)
#declare S4 = seed(12345.9);
Sequence("seed(12345.9):", S4, 5)
#declare S5 = seed(-7);
Sequence("seed(-7):", S5, 5)
#declare S6 = seed(2147483647);
Sequence("seed(2147483647):", S6, 5)

// Interleaved draws from two streams.
#declare A = seed(1);
#declare B = seed(2);
#debug concat("A B A B: ", str(rand(A),0,6), " ", str(rand(B),0,6), " ",
              str(rand(A),0,6), " ", str(rand(B),0,6), "\n")

// Range check over many draws, and the mean to 2 places.
#declare R = seed(2024);
#declare Lo = 1;
#declare Hi = 0;
#declare Sum = 0;
#declare N = 0;
#while (N < 1000)
  #declare V = rand(R);
  #declare Lo = min(Lo, V);
  #declare Hi = max(Hi, V);
  #declare Sum = Sum + V;
  #declare N = N + 1;
#end
#debug concat("min ", str(Lo,0,6), " max ", str(Hi,0,6), " mean ", str(Sum/N,0,2), "\n")

camera {}
sphere { 0, 1 }
