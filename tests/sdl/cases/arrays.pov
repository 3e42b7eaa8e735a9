// Arrays: declaration with and without initialisers, 1 to 3 dimensions, dimensions() and
// dimension_size(), element assignment, arrays of vectors and strings, arrays in loops, an array
// passed to a macro (and changed by it), copying an array, and defined() on elements.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro F(Label, V)
  #debug concat(Label, " = ", str(V, 0, 3), "\n")
#end

#declare A = array[4];
#declare A[0] = 10;
#declare A[3] = 13;
F("A[0]", A[0])
F("A[3]", A[3])
F("dimensions(A)", dimensions(A))
F("dimension_size(A,1)", dimension_size(A,1))
#declare A[1] = A[0] * 2 + A[3];
F("A[1]", A[1])
F("A[1+1-1]", A[1+1-1])
F("A[1.9] (index truncated)", A[1.9])

#declare B = array[2][3] { {1, 2, 3}, {4, 5, 6} };
F("dimensions(B)", dimensions(B))
F("dimension_size(B,1)", dimension_size(B,1))
F("dimension_size(B,2)", dimension_size(B,2))
F("B[1][2]", B[1][2])
#declare B[0][1] = 20;
F("B[0][1]", B[0][1])
#declare Sum = 0;
#for (I, 0, dimension_size(B,1) - 1)
  #for (J, 0, dimension_size(B,2) - 1)
    #declare Sum = Sum + B[I][J];
  #end
#end
F("sum of B", Sum)

#declare C = array[2][2][2];
#declare C[1][0][1] = 101;
F("dimensions(C)", dimensions(C))
F("dimension_size(C,3)", dimension_size(C,3))
F("C[1][0][1]", C[1][0][1])

#declare Pts = array[3] { <1,0,0>, <0,2,0>, <0,0,3> };
#declare Total = <0,0,0>;
#for (I, 0, 2)
  #declare Total = Total + Pts[I];
#end
#debug concat("sum of Pts = ", vstr(3, Total, ",", 0, 1), "\n")
F("Pts[1].y", Pts[1].y)
#declare Pts[2] = Pts[2] * 2;
#debug concat("Pts[2] = ", vstr(3, Pts[2], ",", 0, 1), "\n")

#declare Names = array[3] { "alpha", "beta", "gamma" };
#declare Joined = "";
#for (I, 0, 2)
  #declare Joined = concat(Joined, Names[I]);
  #if (I < 2) #declare Joined = concat(Joined, "+"); #end
#end
#debug concat("joined: ", Joined, "\n")
#declare Names[1] = strupr(Names[1]);
#debug concat("Names[1] = ", Names[1], ", strlen = ", str(strlen(Names[1]), 0, 0), "\n")

#macro Fill(Arr, Value)
  #for (I, 0, dimension_size(Arr, 1) - 1)
    #declare Arr[I] = Value + I;
  #end
#end
#declare D = array[3];
Fill(D, 100)
#debug concat("D after Fill = ", str(D[0], 0, 0), " ", str(D[1], 0, 0), " ",
              str(D[2], 0, 0), "\n")
#macro Mean(Arr)
  #local S = 0;
  #local N = dimension_size(Arr, 1);
  #for (I, 0, N - 1)
    #local S = S + Arr[I];
  #end
  S / N
#end
F("Mean(D)", Mean(D))

#declare E = D;
#declare E[0] = -1;
F("E[0]", E[0])
F("D[0] after changing the copy", D[0])

#declare G = array[3];
#declare G[1] = 1;
#debug concat("defined(G[0]) = ", str(defined(G[0]), 0, 0), ", defined(G[1]) = ",
              str(defined(G[1]), 0, 0), "\n")

#declare Mixed = array[2] { 1, 2 };
#declare Mixed[0] = Mixed[0] + Mixed[1];
F("Mixed[0]", Mixed[0])

camera {}
sphere { 0, 1 }
