// Macros: identifier arguments are aliases (assigning to the parameter changes the caller's
// identifier), other arguments are values; recursion; a macro body is spliced into the expression
// that calls it as text, so the caller's operators apply to the body's tokens.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Show(Label, Value)
  #debug concat(Label, " = ", str(Value, 0, 6), "\n")
#end

// Alias parameters.
#macro IncDeclare(V) #declare V = V + 1; #end
#macro IncLocal(V) #local V = V + 10; #end
#declare N = 1;
IncDeclare(N)
Show("N after IncDeclare(N)", N)
IncLocal(N)
Show("N after IncLocal(N)", N)
#macro Swap(P, Q)
  #local Tmp = P;
  #declare P = Q;
  #declare Q = Tmp;
#end
#declare L = 1;
#declare R = 2;
Swap(L, R)
Show("L after Swap", L)
Show("R after Swap", R)
#declare M = 5;
IncDeclare(M + 0)
Show("M after IncDeclare(M + 0)", M)

// Arguments are evaluated in the caller before the body runs.
#macro Twice(X) 2*X #end
Show("Twice(3+1)", Twice(3+1))
#macro Sum(P, Q) P+Q #end
Show("Sum(1,2)*10 (body spliced as text)", Sum(1,2)*10)
Show("10*Sum(1,2)", 10*Sum(1,2))
Show("(Sum(1,2))*10", (Sum(1,2))*10)

// Recursion. (A bare value directly before #else or #end is not accepted by POV-Ray inside an
// expression, so the recursive macros return a local.)
#macro Fact(K)
  #if (K <= 1)
    #local Result = 1;
  #else
    #local Result = K * Fact(K - 1);
  #end
  Result
#end
Show("Fact(6)", Fact(6))
#macro Fib(K)
  #if (K < 2)
    #local Result = K;
  #else
    #local Result = Fib(K - 1) + Fib(K - 2);
  #end
  Result
#end
Show("Fib(10)", Fib(10))
Show("Fib(5)*Fact(3)", Fib(5)*Fact(3))
#macro CountDown(K)
  #if (K > 0)
    #debug concat(str(K, 0, 0), " ")
    CountDown(K - 1)
  #else
    #debug "liftoff\n"
  #end
#end
CountDown(5)

// Macros returning vectors, strings and colours; macro calls inside vector literals.
#macro Mid(P, Q) (P + Q) / 2 #end
#debug concat("Mid = ", vstr(3, Mid(<0,0,0>, <2,4,6>), ",", 0, 3), "\n")
#macro Greeting(Who) concat("hello, ", Who) #end
#debug concat(Greeting("macro"), "\n")
#macro Grey(G) rgb G #end
#declare Col = Grey(0.25);
Show("Grey(0.25).green", Col.green)
#debug concat("<Twice(1), 5, Sum(1,1)> = ",
              vstr(3, <Twice(1), 5, Sum(1,1)>, ",", 0, 0), "\n")

// Locals declared in a macro that computes a value.
#macro Hypot(P, Q)
  #local P2 = P*P;
  #local Q2 = Q*Q;
  sqrt(P2 + Q2)
#end
Show("Hypot(3,4)", Hypot(3,4))
Show("Hypot(5,12)+1", Hypot(5,12)+1)

// A macro defined inside a macro body exists after that macro ran.
#macro Definer()
  #macro Defined() 123 #end
#end
Definer()
Show("Defined()", Defined())

// A macro can be redefined.
#macro Version() 1 #end
#macro Version() 2 #end
Show("Version()", Version())

camera {}
sphere { 0, 1 }
