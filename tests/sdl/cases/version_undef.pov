// The version keyword and #version (before any #version, after changing it, restoring a saved value)
// and #undef (of globals, of locals inside a macro, then declaring the name again with another type).
#debug concat("version at the start = ", str(version, 0, 6), "\n")
#version 3.7;
global_settings { assumed_gamma 1 }
#debug concat("after #version 3.7 = ", str(version, 0, 6), "\n")
#declare Saved = version;
#version 3.5;
#debug concat("after #version 3.5 = ", str(version, 0, 6), "\n")
#version 3.6;
#debug concat("after #version 3.6 = ", str(version, 0, 6), "\n")
#version Saved;
#debug concat("after #version Saved = ", str(version, 0, 6), "\n")
#version version;
#debug concat("after #version version = ", str(version, 0, 6), "\n")
#if (version >= 3.7)
  #debug "version >= 3.7\n"
#end
#macro VersionInMacro()
  #local Old = version;
  #version 3.1;
  #debug concat("inside the macro = ", str(version, 0, 6), "\n")
  #version Old;
#end
VersionInMacro()
#debug concat("after the macro = ", str(version, 0, 6), "\n")

#declare U = 1;
#ifdef (U) #debug "U is declared\n" #end
#undef U
#ifdef (U) #debug "U is still declared\n" #else #debug "U is undeclared\n" #end
#declare U = "string now";
#debug concat("U = ", U, "\n")
#undef U
#declare U = <1,2,3>;
#debug concat("U = ", vstr(3, U, " ", 0, 0), "\n")

#declare G = 5;
#macro UndefLocal()
  #local G = 6;
  #debug concat("local G = ", str(G, 0, 0), "\n")
  #undef G
  #ifdef (G)
    #debug concat("after #undef G in the macro, G = ", str(G, 0, 0), "\n")
  #else
    #debug "after #undef G in the macro, G is undeclared\n"
  #end
#end
UndefLocal()
#ifdef (G)
  #debug concat("global G = ", str(G, 0, 0), "\n")
#else
  #debug "global G is gone\n"
#end

#macro UndefGlobal()
  #undef G
#end
UndefGlobal()
#ifdef (G) #debug "G survived UndefGlobal\n" #else #debug "UndefGlobal removed G\n" #end

camera {}
sphere { 0, 1 }
