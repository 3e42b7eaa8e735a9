// File I/O in the case's folder: #fopen for write, append and read, #write of strings, floats and
// vectors, #read back into identifiers (floats, vectors, strings) until defined() turns false,
// #fclose, and file_exists(). The files are written next to the scene (a scratch copy).
#version 3.7;
global_settings { assumed_gamma 1 }

#debug concat("exists before = ", str(file_exists("sdl_io_data.txt"), 0, 0), "\n")

#fopen Out "sdl_io_data.txt" write
#write (Out, "\"first\",", 1.5, ",", <1,2,3>, ",", -4, ",\n")
#write (Out, 2/3, ",", "\"second\"", ",")
#fclose Out
#debug concat("exists after write = ", str(file_exists("sdl_io_data.txt"), 0, 0), "\n")

#fopen More "sdl_io_data.txt" append
#write (More, 1e-3, ",", <0.5, -0.25, 8>, "\n")
#fclose More

#fopen In "sdl_io_data.txt" read
#declare Count = 0;
#while (defined(In))
  #read (In, Item)
  #declare Count = Count + 1;
#end
#debug concat("items read = ", str(Count, 0, 0), "\n")

// Read known types one by one.
#fopen In2 "sdl_io_data.txt" read
#read (In2, S1, F1, V1, F2)
#debug concat("S1 = ", S1, "\n")
#debug concat("F1 = ", str(F1, 0, 6), "\n")
#debug concat("V1 = ", vstr(3, V1, ",", 0, 6), "\n")
#debug concat("F2 = ", str(F2, 0, 6), "\n")
#read (In2, F3, S2, F4, V2)
#debug concat("F3 = ", str(F3, 0, 6), "\n")
#debug concat("S2 = ", S2, "\n")
#debug concat("F4 = ", str(F4, 0, 6), "\n")
#debug concat("V2 = ", vstr(3, V2, ",", 0, 6), "\n")
#fclose In2

// Numbers go through #write's formatting (6 significant digits) and back. The read that meets the
// end of the file leaves its identifier as it was and makes the file identifier undefined.
#fopen Nums "sdl_io_nums.txt" write
#for (I, 1, 5)
  #write (Nums, I * I / 7, ",")
#end
#fclose Nums
#fopen Nums "sdl_io_nums.txt" read
#declare N = 0;
#while (defined(Nums))
  #read (Nums, Value)
  #declare N = N + 1;
  #debug concat("read ", str(N, 0, 0), ": ", str(Value, 0, 8), "\n")
#end

// Large and small magnitudes through #write.
#fopen Big "sdl_io_big.txt" write
#write (Big, 1234567, ",", -0.000012345, ",", 1e20, ",", 100, ",", "\"", "quoted", "\"", ",")
#fclose Big
#fopen Big "sdl_io_big.txt" read
#read (Big, B1, B2, B3, B4, B5)
#fclose Big
#debug concat(str(B1, 0, 3), " ", str(B2, 0, 12), " ", str(B3/1e18, 0, 3), " ", str(B4, 0, 3),
              " ", B5, "\n")

camera {}
sphere { 0, 1 }
