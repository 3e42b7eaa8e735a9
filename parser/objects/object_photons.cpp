// The object modifier photons { target [F] refraction B reflection B collect [B] pass_through [B] }, as POV-Ray 3.7's
// Parse_Object_Mods reads it (docs/issue20-photons.md §1), with its CheckPassThru rule: a target that lets photons
// pass through cannot refract them, and whichever of the two was written last gives way, with POV-Ray's warning.
#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/objects/object_photons.hpp"

namespace povtrace::sdl {

namespace {
enum class PassThruCause { pass_through, target, refraction_on };

// POV-Ray's CheckPassThru after `cause` was set on `p`.
template <class Warn>
void check_pass_through(ObjectPhotons& p, PassThruCause cause, const Warn& warn) {
  if (!(p.pass_through && p.target > 0 && p.refraction != false)) return;
  const bool refraction_written_on = p.refraction == true;
  if (cause == PassThruCause::pass_through || (cause == PassThruCause::target && !refraction_written_on)) {
    warn("Cannot use pass_through with refraction & target. Turning off refraction.");
    p.refraction = false;
  } else {
    warn("Cannot use pass_through with refraction & target. Turning off pass_through.");
    p.pass_through = false;
  }
}
}  // namespace

void inherit_photon_flags(const ObjectPhotons& parent, ObjectPhotons& child,
                           const std::function<void(const std::string&)>& warn) {
  if (parent.target > 0) {
    child.target = parent.target;
    check_pass_through(child, PassThruCause::target, warn);
  }
  if (parent.pass_through) {
    child.pass_through = true;
    check_pass_through(child, PassThruCause::pass_through, warn);
  }
  if (parent.reflection) child.reflection = parent.reflection;
  if (parent.refraction) {
    child.refraction = parent.refraction;
    if (*child.refraction) check_pass_through(child, PassThruCause::refraction_on, warn);
  }
  if (!parent.collect) child.collect = false;
}

void ObjectParser::parse_object_photons(const Token& keyword, Object& object) {
  expect("{", " after 'photons'");
  ObjectPhotons& p = object.photons;
  while (true) {
    const Token t = next();
    if (t.is("}")) return;
    const auto warn_here = [&](const std::string& message) { warn(t.loc, message); };
    if (t.is("target")) {
      p.target = optional_float(1.0);
      if (p.target > 0) check_pass_through(p, PassThruCause::target, warn_here);
      else p.target = 0;
    } else if (t.is("refraction")) {
      p.refraction = saturating_cast<int>(parse_float()) != 0;   // POV-Ray truncates: (int)Parse_Float()
      if (*p.refraction) check_pass_through(p, PassThruCause::refraction_on, warn_here);
    } else if (t.is("reflection")) {
      p.reflection = saturating_cast<int>(parse_float()) != 0;
    } else if (t.is("pass_through")) {
      p.pass_through = saturating_cast<int>(optional_float(1.0)) != 0;
      if (p.pass_through) check_pass_through(p, PassThruCause::pass_through, warn_here);
    } else if (t.is("collect")) {
      p.collect = optional_float(1.0) > 0.0;
    } else {
      (void)keyword;
      fail_expected(t, "target, refraction, reflection, collect, pass_through or '}' in the object's photons { }");
    }
  }
}

}  // namespace povtrace::sdl
