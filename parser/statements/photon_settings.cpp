// global_settings { photons { … } } as POV-Ray 3.7's Parse_Global_Settings reads it (docs/issue20-photons.md §1):
// every photons block starts again from the defaults, and the map is enabled when the gather maximum is positive.
#include <algorithm>
#include <cmath>
#include <string>

#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/statements/scene_statements.hpp"

namespace povtrace::sdl {

namespace {
constexpr std::string_view kPhotonWords =
    "a photons setting (spacing, count, gather, media, jitter, max_trace_level, adc_bailout, autostop, "
    "expand_thresholds, radius, load_file, save_file) or '}'";
}  // namespace

void SceneStatements::parse_photon_settings(const Token& keyword) {
  expect("{", " after 'photons'");
  PhotonSettings s;   // POV-Ray resets every photon setting at each photons block
  s.loc = keyword.loc;
  while (true) {
    const Token t = next();
    if (t.is("}")) break;
    const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
    if (k == "spacing") {
      const Token at = peek();
      s.spacing = parse_float();
      if (!(s.spacing > 0)) fail_at(at, "photon spacing must be positive (found " + std::to_string(s.spacing) + ")");
    } else if (k == "count") {
      s.count = saturating_cast<int>(parse_float());
    } else if (k == "gather") {
      s.gather_min = saturating_cast<int>(parse_float());
      accept(",");
      s.gather_max = saturating_cast<int>(parse_float());
    } else if (k == "expand_thresholds") {
      s.expand_tolerance = parse_float();
      accept(",");
      s.expand_min = saturating_cast<int>(parse_float());
      if (s.expand_tolerance < 0) {
        warn(t.loc, "The first parameter of expand_thresholds must be greater than or equal to 0. Setting it to 0 now.");
        s.expand_tolerance = 0;
      }
      if (s.expand_min < 0) {
        warn(t.loc, "The second parameter of expand_thresholds must be greater than or equal to 0. Setting it to 0 now.");
        s.expand_min = 0;
      }
    } else if (k == "jitter") {
      s.jitter = parse_float();
    } else if (k == "autostop") {
      s.autostop = parse_float();
    } else if (k == "adc_bailout") {
      s.adc_bailout = parse_float();
    } else if (k == "max_trace_level") {
      // Clamped as the scene's max_trace_level is (1…256): a deeper photon path would only exhaust the stack.
      s.max_trace_level = std::clamp(saturating_cast<int>(parse_float()), 1, 256);
    } else if (k == "radius") {
      // radius [gather], [multiplier], [media gather], [media multiplier]: each may be left out.
      s.radius = optional_float(-1.0);
      accept(",");
      s.radius_multiplier = optional_float(1.0);
      accept(",");
      s.media_radius = optional_float(-1.0);
      accept(",");
      s.media_radius_multiplier = optional_float(1.0);
    } else if (k == "media") {
      const Token at = peek();
      s.media_steps = saturating_cast<int>(parse_float());
      if (s.media_steps < 0) fail_at(at, "max media steps must be non-negative.");
      accept(",");
      const Token factor_at = peek();
      s.media_spacing_factor = optional_float(1.0);
      if (!(s.media_spacing_factor > 0)) fail_at(factor_at, "media spacing factor must be greater than zero.");
      // POV-Ray deposits photons in media only with a positive step count; povtrace has no media photon map yet.
      if (s.media_steps > 0) fail_unsupported(t, "media photons (photons { media " + std::to_string(s.media_steps) + " })");
    } else if (k == "load_file" || k == "save_file") {
      // POV-Ray keeps one file name: a second one replaces the first, with a warning.
      const bool load = k == "load_file";
      if (!s.load_file.empty() || !s.save_file.empty()) {
        const bool was_load = !s.load_file.empty();
        warn(t.loc, was_load == load ? "Filename already given, using new name"
                    : load          ? "Cannot both load and save photon map. Now switching to load mode."
                                    : "Cannot both load and save photon map. Now switching to save mode.");
      }
      const std::string name = parse_string();
      s.load_file = load ? name : std::string();
      s.save_file = load ? std::string() : name;
      s.file_loc = t.loc;
    } else {
      fail_expected(t, kPhotonWords);
    }
  }
  // POV-Ray: a gather maximum of 0 means no photon map.
  if (s.gather_max <= 0) {
    scene_.photons.reset();
    warn(keyword.loc, "a photons block with a gather maximum of 0 leaves photons disabled (as in POV-Ray)");
    return;
  }
  if (s.gather_min < 0) fail_at(keyword, "min_gather_count cannot be negative.");
  if (s.gather_min > s.gather_max) fail_at(keyword, "min_gather_count must be less than max_gather_count.");
  scene_.photons = s;
}

}  // namespace povtrace::sdl
