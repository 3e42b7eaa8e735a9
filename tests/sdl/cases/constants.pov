// Built-in constants and read-only values: pi, true/false/yes/no/on/off, the animation values when
// no animation is running, the image size (+W8 +H8 for both renderers), and the axis vectors.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro F(Label, V)
  #debug concat(Label, " = ", str(V, 0, 6), "\n")
#end

F("pi", pi)
F("2*pi", 2*pi)
F("true", true)
F("false", false)
F("yes", yes)
F("no", no)
F("on", on)
F("off", off)
F("clock", clock)
F("clock_delta", clock_delta)
F("clock_on", clock_on)
F("initial_clock", initial_clock)
F("final_clock", final_clock)
F("initial_frame", initial_frame)
F("final_frame", final_frame)
F("frame_number", frame_number)
F("image_width", image_width)
F("image_height", image_height)
F("image_width/image_height", image_width/image_height)
#debug concat("x y z = ", vstr(3, x, ",", 0, 0), " ", vstr(3, y, ",", 0, 0), " ",
              vstr(3, z, ",", 0, 0), "\n")
#debug concat("u v = ", vstr(2, u, ",", 0, 0), " ", vstr(2, v, ",", 0, 0), "\n")

camera {}
sphere { 0, 1 }
