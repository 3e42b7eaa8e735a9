// isosurface (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser (source/backend/parser/parse.cpp
// Parse_Isosurface, function.cpp Parse_Function; shape/isosurf.cpp and isosurf.h, 3.7-stable):
// - isosurface { function { F } items… modifiers }, or a declared object as the body. The function must come first;
//   it is one expression of x, y, z (a call of a declared function included).
// - Items in any order, each as often as wanted (the last wins): contained_by { box { C1, C2 } | sphere { C, R } }
//   (an empty block keeps the default box <-1,-1,-1> to <1,1,1>; box corners are sorted per axis), threshold T (0),
//   accuracy A (0.001), max_gradient G (1.1), max_trace N (1; truncated), all_intersections (max_trace 10),
//   evaluate P0, P1, P2, open.
// - Then: accuracy ≤ 0 becomes 0.001, max_gradient ≤ 0 becomes 1.1, max_trace above 10 becomes 10 and below 1
//   becomes 1, each with a warning.
// - `evaluate P0, P1, P2` (any values, no checks) switches on the adaptive max_gradient (renderer/shapes/isosurface.cpp).
// - A function povtrace cannot evaluate (noise-based internal functions, patterns) is refused by name.
#include "runtime/function_value.hpp"
#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

namespace {
constexpr int kMaxTrace = 10;   // isosurf.h ISOSURFACE_MAXTRACE
}

void ObjectParser::parse_isosurface_function(Isosurface& iso, Object& o) {
  const Token keyword = next();
  if (!keyword.is("function")) fail_expected(keyword, "'function' starting the isosurface");
  auto fn = parse_function_definition(keyword);
  if (fn->return_size != 0 || fn->parameter_count != 3)
    fail_at(keyword, "an isosurface needs a float function of x, y and z");
  if (auto part = unevaluable_part(*fn))
    taint(o.unsupported, UnsupportedFeature{"an isosurface of " + *part, keyword.loc});
  iso.function = std::move(fn);
}

// contained_by { box { C1, C2 } | sphere { C, R } } (or empty: the default box).
void ObjectParser::parse_isosurface_container(Isosurface& iso) {
  expect("{", " after 'contained_by'");
  const Token t = next();
  if (t.is("box")) {
    expect("{", " after 'box' in contained_by");
    const Vec3 a = parse_vector();
    accept(",");
    const Vec3 b = parse_vector();
    expect("}", " closing the container box");
    iso.sphere_container = false;
    iso.corner1 = min(a, b);
    iso.corner2 = max(a, b);
  } else if (t.is("sphere")) {
    expect("{", " after 'sphere' in contained_by");
    iso.centre = parse_vector();
    accept(",");
    iso.radius = parse_float();
    expect("}", " closing the container sphere");
    iso.sphere_container = true;
  } else {
    unget(t);
  }
  expect("}", " closing contained_by (a box or a sphere)");
}

bool ObjectParser::try_isosurface_item(const Token& t, Isosurface& iso) {
  if (t.is("contained_by")) parse_isosurface_container(iso);
  else if (t.is("threshold")) iso.threshold = parse_float();
  else if (t.is("accuracy")) iso.accuracy = parse_float();
  else if (t.is("max_gradient")) iso.max_gradient = parse_float();
  else if (t.is("max_trace")) iso.max_trace = saturating_cast<short>(parse_float());
  else if (t.is("all_intersections")) iso.max_trace = kMaxTrace;
  else if (t.is("open")) iso.open = true;
  else if (t.is("evaluate")) {
    iso.evaluate = true;
    for (int k = 0; k < 3; ++k) {
      if (k > 0) accept(",");
      iso.evaluate_params[static_cast<std::size_t>(k)] = parse_float();
    }
  } else {
    return false;
  }
  return true;
}

void ObjectParser::correct_isosurface_values(const Token& keyword, Isosurface& iso) {
  if (iso.accuracy <= 0.0) {
    warn(keyword.loc, "isosurface 'accuracy' is not positive; using 0.001 (the default), as POV-Ray does");
    iso.accuracy = 0.001;
  }
  if (iso.max_gradient <= 0.0) {
    warn(keyword.loc, "isosurface 'max_gradient' is not positive; using 1.1 (the default), as POV-Ray does");
    iso.max_gradient = 1.1;
  }
  if (iso.max_trace > kMaxTrace) {
    warn(keyword.loc, "isosurface 'max_trace' exceeds the maximum of 10; using 10, as POV-Ray does");
    iso.max_trace = kMaxTrace;
  }
  if (iso.max_trace < 1) {
    warn(keyword.loc, "isosurface 'max_trace' is not positive; using 1 (the default), as POV-Ray does");
    iso.max_trace = 1;
  }
}

Object ObjectParser::parse_isosurface(const Token& keyword) {
  expect("{", " after 'isosurface'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  Isosurface iso;
  parse_isosurface_function(iso, o);
  while (true) {
    const Token t = next();
    if (!try_isosurface_item(t, iso)) {
      unget(t);
      break;
    }
  }
  correct_isosurface_values(keyword, iso);
  o.shape = std::move(iso);
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl
