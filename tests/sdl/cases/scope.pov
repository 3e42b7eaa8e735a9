// #declare and #local: macro-local identifiers, #declare from inside a macro, dynamic scope (a macro
// sees the locals of the macros that called it), include-file locals, and shadowing.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Show(Label, Value)
  #debug concat(Label, " = ", str(Value, 0, 6), "\n")
#end

#declare A = 1;
#macro SetLocal()
  #local A = 2;
  Show("A inside SetLocal", A)
#end
SetLocal()
Show("A after SetLocal", A)

#macro SetGlobal()
  #declare A = 3;
#end
SetGlobal()
Show("A after SetGlobal", A)

#macro MakeNew()
  #declare NewGlobal = 7;
  #local NewLocal = 8;
#end
MakeNew()
Show("NewGlobal", NewGlobal)
#ifdef (NewLocal)
  #debug "NewLocal leaked\n"
#else
  #debug "NewLocal is gone after the macro\n"
#end

// Dynamic scope: Inner reads B, which exists only as a local of whichever macro called it.
#macro Inner()
  Show("B seen by Inner", B)
#end
#macro OuterOne()
  #local B = 11;
  Inner()
#end
#macro OuterTwo()
  #local B = 22;
  Inner()
#end
OuterOne()
OuterTwo()
#declare B = 33;
Inner()

// #declare of a name that is local in the calling macro.
#macro DeclareOverLocal()
  #local C = 1;
  #declare C = 2;
  Show("C inside after #declare", C)
#end
DeclareOverLocal()
#ifdef (C)
  Show("C after the macro", C)
#else
  #debug "C undefined after the macro\n"
#end

// A #local in a nested macro does not touch the caller's local of the same name.
#macro Nested()
  #local D = 5;
  Show("D in Nested", D)
#end
#macro Caller()
  #local D = 4;
  Nested()
  Show("D in Caller after Nested", D)
#end
Caller()

// #declare in a called macro changes the caller's local of that name when there is one.
#macro SetE()
  #declare E = 99;
#end
#macro HasE()
  #local E = 1;
  SetE()
  Show("E in HasE after SetE", E)
#end
HasE()
#ifdef (E)
  Show("global E", E)
#else
  #debug "no global E\n"
#end

// Top-level #local in the main file.
#local TopLocal = 6;
Show("TopLocal", TopLocal)
#macro ReadTop() Show("TopLocal from a macro", TopLocal) #end
ReadTop()

// Include files.
#declare Shared = 1;
#local CallerLocal = 3;
#include "scope_helper.inc"
Show("IncGlobal", IncGlobal)
Show("Shared", Shared)
#ifdef (IncLocal)
  #debug "IncLocal leaked\n"
#else
  #debug "IncLocal is local to the include file\n"
#end

// Changing the type of an identifier with #declare.
#declare T = 1;
#declare T = "now a string";
#debug concat("T = ", T, "\n")
#declare T = <1,2,3>;
#debug concat("T = ", vstr(3, T, ",", 0, 0), "\n")

camera {}
sphere { 0, 1 }
