// #if / #elseif / #else / #end, #ifdef / #ifndef, defined(), nesting, skipped branches that contain
// other directives, and POV-Ray's truth test (|value| > 1e-10).
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Classify(V)
  #if (V < 0)
    #debug concat(str(V, 0, 2), " is negative\n")
  #elseif (V = 0)
    #debug concat(str(V, 0, 2), " is zero\n")
  #elseif (V < 10)
    #debug concat(str(V, 0, 2), " is small\n")
  #else
    #debug concat(str(V, 0, 2), " is large\n")
  #end
#end
Classify(-3)
Classify(0)
Classify(4.5)
Classify(10)
Classify(1e-12)

#macro Truth(Label, V)
  #if (V)
    #debug concat(Label, " is true\n")
  #else
    #debug concat(Label, " is false\n")
  #end
#end
Truth("1", 1)
Truth("0", 0)
Truth("-0.5", -0.5)
Truth("1e-9", 1e-9)
Truth("1e-11", 1e-11)
Truth("-1e-11", -1e-11)
Truth("yes", yes)
Truth("off", off)

// #elseif branches after a true one are not evaluated (an undeclared name there is fine).
#if (1)
  #debug "first branch\n"
#elseif (Undeclared_Name > 0)
  #debug "never\n"
#else
  #debug "never either\n"
#end
// #if without #else, false.
#if (0)
  #debug "not printed\n"
#end
// A skipped branch may contain other directives and unbalanced-looking text.
#if (0)
  #declare Skipped = 1;
  #macro NotDefined() 1 #end
  #while (1) #end
  #if (1) #debug "nested, skipped\n" #else #debug "also skipped\n" #end
  #debug "skipped"
  this is not parsed {
#else
  #debug "else of a branch with nested directives\n"
#end
#ifdef (Skipped)
  #debug "Skipped is declared\n"
#else
  #debug "Skipped is not declared\n"
#end

// Nested conditionals.
#declare P = 2;
#declare Q = 5;
#if (P > 1)
  #if (Q < 3)
    #debug "P>1, Q<3\n"
  #elseif (Q < 6)
    #if (P = 2 & Q = 5)
      #debug "P=2 and Q=5\n"
    #end
  #end
#else
  #debug "P<=1\n"
#end

// #ifdef, #ifndef, defined() with floats, strings, macros and locals.
#declare Fl = 1;
#declare St = "s";
#ifdef (Fl) #debug "Fl defined\n" #end
#ifdef (Nope) #debug "Nope defined\n" #else #debug "Nope undefined\n" #end
#ifndef (Nope) #debug "ifndef Nope: taken\n" #end
#ifndef (St) #debug "ifndef St: taken\n" #else #debug "ifndef St: else\n" #end
#debug concat("defined(Fl) = ", str(defined(Fl), 0, 0), "\n")
#debug concat("defined(Nope) = ", str(defined(Nope), 0, 0), "\n")
#macro LocalCheck()
  #local Lc = 1;
  #ifdef (Lc) #debug "Lc defined inside the macro\n" #end
#end
LocalCheck()
#ifndef (Lc) #debug "Lc undefined outside\n" #end
#if (defined(Fl) & !defined(Nope))
  #debug "defined() combines with & and !\n"
#end
#ifdef (Fl)
  #debug "ifdef with elseif: "
#elseif (1)
  #debug "wrong\n"
#end
#debug "done\n"

// Conditions built from comparisons of strings through strcmp.
#if (strcmp(St, "s") = 0)
  #debug "St is \"s\"\n"
#end

camera {}
sphere { 0, 1 }
