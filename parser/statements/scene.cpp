// Top-level statements, global settings, #default, right-hand values, and the entry points.
#include <iostream>

#include "parser/expressions/int_cast.hpp"
#include "parser/extents/object_notes.hpp"
#include "parser/extents/placed_boxes.hpp"
#include "parser/interpreter.hpp"
#include "parser/lexing/reserved_words.hpp"
#include "parser/statements/scene_statements.hpp"
#include "parser/objects/object_transform.hpp"
#include "parser/objects/object_photons.hpp"

namespace povtrace::sdl {

Interpreter::Interpreter(const ParseOptions& options)
    : reader_(options, symbols_, directives_, arrays_, diagnostics_, directives_), options_(options) {}

std::string SceneStatements::reached_from() const { return reader_.stream().reached_from(); }

SceneDescription SceneStatements::run(std::unique_ptr<SourceFile> main_file) {
  reader_.stream().open_main(std::move(main_file));
  // Identifiers the front end predeclares as ordinary globals (§3), then the INI/command-line Declare=s.
  const ParseOptions::FrameValues& f = options_.frame;
  const std::pair<const char*, double> predeclared[] = {
      {"image_width", options_.image_width}, {"image_height", options_.image_height},
      {"clock_delta", f.clock_delta},        {"final_clock", f.final_clock},
      {"final_frame", f.final_frame},        {"frame_number", f.frame_number},
      {"initial_clock", f.initial_clock},    {"initial_frame", f.initial_frame}};
  for (const auto& [name, value] : predeclared) symbols_.declare(name, Numeric::scalar(value));
  for (const auto& [name, value] : options_.declares) symbols_.declare(name, Numeric::scalar(value));
  for (const auto& [name, value] : options_.string_declares) symbols_.declare(name, Value(value));
  if (options_.initial_language_version) scene_.language_version = *options_.initial_language_version;
  if (options_.include_header) open_include_header(*options_.include_header);

  try {
    while (true) {
      reader_.set_between_statements(true);
      Token t = next();
      reader_.set_between_statements(false);
      if (t.kind == TokenKind::end_of_input) break;
      parse_statement(t);
    }
  } catch (const ParseError& e) {
    // Errors from below the interpreter (the lexer: an unterminated string in an include file) get the chain of
    // includes and macro calls that fail() gives the others; the frame stack is still as it was at the throw.
    if (!e.context().empty() || reader_.stream().depth() < 2) throw;
    throw ParseError(e, reached_from());
  }
  directives_.check_closed_at_end();
  radiosity_.finish(scene_.radiosity);
  scene_.language_version_set = version_directive_seen_ || options_.initial_language_version.has_value();
  scene_.file_names = reader_.stream().file_names();
  return std::move(scene_);
}

// +HI: the header is read as an #include at the scene's first position, so its errors name the header's own
// file and line, and "included from" names the scene.
void SceneStatements::open_include_header(const std::filesystem::path& header) {
  const std::optional<std::filesystem::path> found = directives_.find_include(header.string());
  Token at;
  at.kind = TokenKind::identifier;
  at.loc = SourceLoc{reader_.stream().frame().file->name, 1, 1};
  if (!found) {
    throw ParseError(at.loc, "cannot find the Include_Header file \"" + header.string() + "\"");
  }
  reader_.stream().push_file(*found, at, TokenStream::Frame::Kind::include);
  symbols_.push_scope();   // the include's #local scope, closed when the header ends (leaving_include)
}

void SceneStatements::directive_version(const Token& at) {
  const double v = expressions_.parse_float();
  scene_.language_version = static_cast<int>(std::lround(v * 100.0));
  version_directive_seen_ = true;
  if (peek_raw().is(";")) next();
  if (!statement_seen_ && reader_.stream().depth() == 1) scene_.version_given = true;
  (void)at;
}

void SceneStatements::parse_statement(const Token& t) {
  statement_seen_ = true;
  const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
  if (k == "camera") {
    scene_.camera = camera_lights_.parse_camera(t);
    unsupported_.refuse_if_unsupported(scene_.camera.unsupported, t.loc, "camera");
    camera_seen_ = true;
    return;
  }
  if (k == "global_settings") return parse_global_settings(t);
  if (k == "default") {   // the pre-3.0 spelling of #default, still accepted by POV-Ray
    warn(t.loc, "'default' without '#' is an old form of #default");
    return parse_default(t);
  }
  if (k == "background") return parse_background(t);
  if (k == "sky_sphere") {
    if (scene_.sky_sphere) warn(t.loc, "only one sky_sphere is used: this one replaces the earlier one");
    SkySphere sky = textures_.parse_sky_sphere(t);
    unsupported_.refuse_if_unsupported(sky.unsupported, t.loc, "sky_sphere");
    scene_.sky_sphere = std::move(sky);
    return;
  }
  if (k == "object") return objects_.place_object_block(t);
  if (auto item = objects_.try_parse_item(t)) {
    if (auto* light = std::get_if<Light>(&*item)) place_light(std::move(*light), t.loc);
    else place_object(std::move(std::get<Object>(*item)), t.loc);
    return;
  }
  if (k == "fog") {
    // POV-Ray keeps fogs in a list, the newest first.
    scene_.fogs.insert(scene_.fogs.begin(), textures_.parse_fog(t));
    return;
  }
  if (k == "media") {   // atmospheric media: fills the space outside non-hollow objects
    scene_.atmosphere.push_back(textures_.parse_media_block(t));
    unsupported_.refuse_if_unsupported(scene_.atmosphere.back().unsupported, t.loc, "atmospheric media");
    return;
  }
  if (k == "rainbow") {   // POV-Ray lists rainbows as it lists fogs, the newest first
    scene_.rainbows.insert(scene_.rainbows.begin(), textures_.parse_rainbow(t));
    return;
  }
  static const std::string_view unsupported[] = {"photons"};
  for (auto u : unsupported)
    if (k == u) fail_unsupported(t, "'" + std::string(k) + "' at the top level of a scene");
  if (k == "radiosity")   // POV-Ray reads radiosity only in global_settings (and #default, objects: importance)
    fail_expected(t, "an object, light_source, camera, background, global_settings or a directive (radiosity { } "
                     "is written inside global_settings { })");
  if (k == "declare" || k == "include" || k == "version")
    fail_at(t, "'" + std::string(k) + "' must be written as a directive: '#" + std::string(k) + "'");
  if (t.is(";")) fail_at(t, "unexpected ';' (a ';' only ends #declare, #local and #version values)");
  fail_expected(t, "an object, light_source, camera, background, global_settings or a directive");
}

void SceneStatements::parse_global_settings(const Token& keyword) {
  (void)keyword;
  expect("{", " after 'global_settings'");
  while (true) {
    Token t = next();
    if (t.is("}")) return;
    const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
    if (k == "assumed_gamma") {
      scene_.settings.assumed_gamma = expressions_.parse_float();
      if (*scene_.settings.assumed_gamma <= 0) fail_at(t, "assumed_gamma must be positive");
    } else if (k == "ambient_light") {
      Colour c = expressions_.parse_colour();
      scene_.settings.ambient_light = Colour{c.r, c.g, c.b, 0, 0};
    } else if (k == "max_trace_level") {
      // Clamped to 1…256 (pipeline §4 "Recursion limits").
      scene_.settings.max_trace_level = std::clamp(saturating_cast<int>(expressions_.parse_float()), 1, 256);
    } else if (k == "adc_bailout") {
      scene_.settings.adc_bailout = expressions_.parse_float();
    } else if (k == "noise_generator") {
      // 1 (original), 2 (range-corrected) or 3 (Perlin's); POV-Ray truncates the value and refuses the rest.
      const Token value_at = peek();
      const double g = std::trunc(expressions_.parse_float());
      if (!(g >= 1 && g <= 3)) fail_at(value_at, "Value for noise_generator in global_settings must be 1, 2, or 3.");
      scene_.settings.noise_generator = static_cast<int>(g);
    } else if (k == "charset") {
      // ascii or utf8 (sys is refused): how text { } turns strings into characters and picks a character map.
      const Token c = next();
      if (c.is("sys")) fail_unsupported(c, "the global setting 'charset sys'");
      if (!c.is("ascii") && !c.is("utf8")) fail_expected(c, "ascii, utf8 or sys after 'charset'");
      objects_.set_string_encoding(c.is("utf8") ? ttf::StringEncoding::utf8 : ttf::StringEncoding::ascii);
    } else if (k == "number_of_waves") {
      // POV-Ray truncates it and makes a value below 1 into 1 with a warning.
      const Token value_at = peek();
      const double n = std::trunc(expressions_.parse_float());
      if (n > 65536) fail_at(value_at, "number_of_waves above 65536 is refused (each wave is summed at every sample)");
      scene_.settings.number_of_waves = n >= 1 ? static_cast<int>(n) : 1;
      if (!(n >= 1)) warn(value_at.loc, "Illegal Value: number_of_waves must be greater than 0. Changed to 1.");
    } else if (k == "irid_wavelength") {   // a colour, single precision as POV-Ray's RGBColour
      const Colour c = expressions_.parse_colour();
      scene_.settings.irid_wavelength = Colour{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), 0, 0};
    } else if (k == "radiosity") {
      radiosity_.parse_settings(t, scene_.radiosity);
    } else if (k == "photons") {
      parse_photon_settings(t);
    } else if (k == "hf_gray_16") {
      // POV-Ray 3.7 reads an optional float and ignores the setting with this warning (grey output is a command-line
      // option there).
      expressions_.optional_float(1.0);
      warn(t.loc, "In POV-Ray 3.7 and later 'hf_gray_16' has to be specified as an option on the command-line; "
                  "the 'hf_gray_16' setting here is ignored (as in POV-Ray).");
    } else if (!k.empty() && is_reserved_word(k)) {
      fail_unsupported(t, "the global setting '" + std::string(k) + "'");
    } else {
      fail_expected(t, "assumed_gamma, ambient_light, max_trace_level, adc_bailout or '}'");
    }
  }
}

void SceneStatements::parse_background(const Token& keyword) {
  (void)keyword;
  expect("{", " after 'background'");
  scene_.background = expressions_.parse_colour();
  expect("}", " after the background colour");
}

// #default { texture{} | pigment{} | finish{} } edits the texture given to objects created later (§4);
// #default { radiosity { importance F } } the importance of objects that do not write theirs.
void SceneStatements::parse_default(const Token& keyword) {
  (void)keyword;
  expect("{", " after #default");
  while (true) {
    Token t = next();
    if (t.is("}")) return;
    if (t.is("radiosity")) {
      if (const std::optional<double> importance = parse_radiosity_importance(t))
        scene_.radiosity_default_importance = *importance;
      continue;
    }
    placed_default_texture_.reset();   // the #default changes: later objects get a new shared copy
    TextureLayer& layer = default_texture_.layers.back();
    if (t.is("pigment")) layer.pigment = textures_.parse_pigment_block(t, layer.pigment);
    else if (t.is("finish")) layer.finish = textures_.parse_finish_block(t, layer.finish);
    else if (t.is("texture")) {
      auto tex = textures_.parse_texture_block(t);
      if (tex->patterned()) fail_unsupported(t, "a patterned #default texture");
      default_texture_ = *tex;
    }
    else if (t.is("normal")) {
      layer.normal =
          std::make_shared<const Normal>(textures_.parse_normal_block(t, textures_.starting_normal(layer.normal.get())));
      unsupported_.refuse_if_unsupported(layer.normal->unsupported, t.loc, "#default");
    } else if (t.is("camera"))
      fail_unsupported(t, "#default { " + std::string(t.text) + " }");
    else fail_expected(t, "texture, pigment, normal, finish or radiosity in #default { }");
  }
}

namespace {
// The first feature povtrace cannot render anywhere in an object: its shape or modifiers, its texture's
// layers, its interior, or (for CSG) its children and lights.
Unsupported first_unsupported(const Texture& texture) {
  if (texture.unsupported) return texture.unsupported;
  for (const auto& l : texture.layers) {
    if (l.pigment.unsupported) return l.pigment.unsupported;
    if (l.finish.unsupported) return l.finish.unsupported;
    if (l.normal && l.normal->unsupported) return l.normal->unsupported;
  }
  return std::nullopt;
}

Unsupported first_unsupported(const Object& o) {
  if (o.unsupported) return o.unsupported;
  for (const auto* texture : {o.texture.get(), o.interior_texture.get()})
    if (texture)
      if (auto u = first_unsupported(*texture)) return u;
  if (o.interior && o.interior->unsupported) return o.interior->unsupported;
  if (const auto* csg = std::get_if<Csg>(&o.shape)) {
    for (const auto& c : csg->children)
      if (auto u = first_unsupported(c)) return u;
    for (const auto& l : csg->lights) {
      if (l.unsupported) return l.unsupported;
      for (const auto& shown : l.looks_like)
        if (auto u = first_unsupported(shown)) return u;
      for (const auto& through : l.projected_through)
        if (auto u = first_unsupported(through)) return u;
    }
  }
  for (const auto* list : {&o.clipped_by, &o.bounded_by})
    for (const auto& c : *list)
      if (auto u = first_unsupported(c)) return u;
  return std::nullopt;
}

// A placed object is edited no more: transforms deferred for textures that no longer ignore them (edited since)
// are applied; those deferred for textures that ignore them go with the notes when the object is placed
// (SceneStatements::placed). Light sources' looks_like objects are settled when the lights are added.
void settle_deferred_texture_transforms(Object& o, const NotesPool& pool) {
  if (o.texture && !texture_ignores_transforms(*o.texture)) apply_deferred_texture_transforms(o, pool);
  if (auto* csg = std::get_if<Csg>(&o.shape))
    for (Object& child : csg->children) settle_deferred_texture_transforms(child, pool);
  for (auto* list : {&o.clipped_by, &o.bounded_by, &o.removed_bounds})
    for (Object& c : *list) settle_deferred_texture_transforms(c, pool);
}
}  // namespace

void SceneStatements::place_light(Light light, const SourceLoc& at) {
  unsupported_.refuse_if_unsupported(light.unsupported, at, "light_source");
  for (Object& shown : light.looks_like) unsupported_.refuse_if_unsupported(first_unsupported(shown), at, "light_source");
  for (Object& through : light.projected_through)
    unsupported_.refuse_if_unsupported(first_unsupported(through), at, "light_source");
  add_light(std::move(light), std::nullopt);
}

// A light joins the scene's lights; its looks_like object joins the objects. POV-Ray post-processes that object as
// the light's child: without an importance of its own it takes the light's, which is the CSG parent's when the
// light is inside one and otherwise unset, so the #default in force now (`importance`).
void SceneStatements::add_light(Light light, std::optional<double> importance) {
  for (Object& shown : light.looks_like) {
    if (!shown.radiosity_importance)
      shown.radiosity_importance = importance.value_or(scene_.radiosity_default_importance);
    settle_deferred_texture_transforms(shown, notes_pool());
    post_process(shown);
    set_placed_boxes(shown, extents());
    placed(shown);
    scene_.objects.push_back(std::move(shown));
  }
  light.looks_like.clear();
  for (Object& through : light.projected_through) clear_notes(through);   // photons intersect it; nothing edits it
  scene_.lights.push_back(std::move(light));
}

// An object joining the scene's objects is edited, moved and queried no more and its box is made: the parser's notes
// on it go (ParseOptions::placing sees them last).
void SceneStatements::placed(Object& object) {
  if (options_.placing) options_.placing(object);
  clear_notes(object);
}

// Promote_Local_Lights for each light_group in a placed object, innermost first: its lights get the group's id, and
// when it has both lights and objects every object of it (nested ones included) is lit by them, after the lights of
// the groups inside it. Each placement of a declared group is a group of its own.
void SceneStatements::assign_light_groups(Object& object) {
  auto* csg = std::get_if<Csg>(&object.shape);
  if (!csg) return;
  for (Object& child : csg->children) assign_light_groups(child);
  if (!csg->light_group) return;
  const int id = next_light_group_++;
  for (Light& light : csg->lights) light.group = id;
  if (csg->lights.empty() || csg->children.empty()) return;
  // Promote_Local_Lights_Recursive: a group inside that lights its own objects keeps them to its lights (the outer
  // lights join only its own node's list, which no ray sees); other CSG pass the lights down.
  struct Promote {
    int id;
    void operator()(Object& o) const {
      o.light_groups.push_back(id);
      auto* c = std::get_if<Csg>(&o.shape);
      if (!c || (c->light_group && !c->lights.empty() && !c->children.empty())) return;
      for (Object& child : c->children) (*this)(child);
    }
  };
  for (Object& child : csg->children) Promote{id}(child);
}

// Post_Process when a finished top-level object is placed (§10 "Texture inheritance"): CSG children without a
// texture or interior take the parent's (the same texture, so it moves with the parent), the parent's no_shadow,
// no_image, no_reflection and no_radiosity are forced onto them, lights inside CSG join the scene's lights, and anything still untextured gets the
// current #default texture.
void SceneStatements::post_process(Object& object) {
  // Legacy finish items move into the interior (POV-Ray's Post_Process, before the children inherit it): the top
  // layer's `ior` and `caustics` (if not negative) when given, and its `refraction` always.
  if (object.texture && !object.texture->layers.empty()) {
    const Finish& top = object.texture->layers.back().finish;
    if (top.legacy_ior || top.legacy_caustics || top.legacy_refraction != 1.0 || object.interior) {
      Interior in = object.interior.value_or(Interior{});
      if (top.legacy_ior) in.ior = *top.legacy_ior;
      if (top.legacy_caustics && *top.legacy_caustics >= 0.0) in.caustics = *top.legacy_caustics;
      in.refraction = top.legacy_refraction;
      object.interior = in;
    }
  }
  if (auto* csg = std::get_if<Csg>(&object.shape)) {
    for (auto& child : csg->children) {
      if (!child.texture) {   // the uv_mapping flag goes with the texture (POV-Ray's Post_Process)
        child.texture = object.texture;
        child.uv_mapping = child.uv_mapping || object.uv_mapping;
      }
      if (!child.interior_texture) {   // with the uv_mapping flag, as the texture (POV-Ray's Post_Process)
        child.interior_texture = object.interior_texture;
        child.uv_mapping = child.uv_mapping || (object.interior_texture && object.uv_mapping);
      }
      if (!child.interior) child.interior = object.interior;
      if (!child.hollow) child.hollow = object.hollow;   // hollow reaches the children that did not set it
      if (object.no_shadow) child.no_shadow = true;
      // POV-Ray's Post_Process sets the parent's no_image, no_reflection and no_radiosity on every child too
      // (never clearing one a child set itself).
      if (object.no_image) child.no_image = true;
      if (object.no_reflection) child.no_reflection = true;
      if (object.no_radiosity) child.no_radiosity = true;
      inherit_photon_flags(object.photons, child.photons, [&](const std::string& m) { warn(child.loc, m); });
      // A child without a radiosity importance takes its parent's, or the #default in force now: POV-Ray fixes it
      // when the top-level object is placed, while a top-level object without one reads the #default in force at
      // the end of the parse (SceneDescription::radiosity_default_importance).
      if (!child.radiosity_importance)
        child.radiosity_importance = object.radiosity_importance.value_or(scene_.radiosity_default_importance);
      post_process(child);
    }
    const double light_importance = object.radiosity_importance.value_or(scene_.radiosity_default_importance);
    for (auto& light : csg->lights) add_light(std::move(light), light_importance);
    csg->lights.clear();
  }
  // POV-Ray gives every object an interior and keeps the hollow flag there.
  if (object.hollow.value_or(false)) {
    Interior in = object.interior.value_or(Interior{});
    in.hollow = true;
    object.interior = in;
  }
  if (!object.texture) {
    // One shared copy per #default state: untextured objects by the thousand must not copy it each.
    if (!placed_default_texture_) placed_default_texture_ = std::make_shared<const Texture>(default_texture_);
    object.texture = placed_default_texture_;
  }
}

namespace {
// POV-Ray's Post_Tnormal: a normal that reaches an object without a pattern is the error "No normal type given".
const Normal* untyped_normal(const Normal& n) {
  if (n.uv_normal) return untyped_normal(*n.uv_normal);
  return !n.has_type && !n.unsupported ? &n : nullptr;
}

const Normal* untyped_normal(const Texture* texture) {
  if (!texture) return nullptr;
  for (const TextureLayer& layer : texture->layers)
    if (layer.normal)
      if (const Normal* n = untyped_normal(*layer.normal)) return n;
  if (texture->pattern)   // the textures of a patterned texture
    for (const TextureMapEntry& e : texture->pattern->entries)
      if (const Normal* n = untyped_normal(e.texture.get())) return n;
  return nullptr;
}

const Normal* first_untyped_normal(const Object& o) {
  if (const Normal* n = untyped_normal(o.texture.get())) return n;
  if (const auto* mesh = std::get_if<Mesh>(&o.shape))
    for (const auto& t : mesh->textures)
      if (const Normal* n = untyped_normal(t.get())) return n;
  if (const auto* csg = std::get_if<Csg>(&o.shape))
    for (const Object& child : csg->children)
      if (const Normal* n = first_untyped_normal(child)) return n;
  return nullptr;
}
}  // namespace

void SceneStatements::place_object(Object&& object, const SourceLoc& at) {
  unsupported_.refuse_if_unsupported(first_unsupported(object), at, "object");
  objects_.remove_unnecessary_bounds(object);
  settle_deferred_texture_transforms(object, notes_pool());
  assign_light_groups(object);
  post_process(object);
  if (const Normal* n = first_untyped_normal(object)) fail(n->loc, "no normal type given (as in POV-Ray)");
  set_placed_boxes(object, extents());   // the renderer culls the object's rays with them (csg_build.cpp)
  placed(object);
  scene_.objects.push_back(std::move(object));
}

}  // namespace povtrace::sdl

namespace povtrace {

namespace {
ParseOptions with_standard_includes(const ParseOptions& options) {
  ParseOptions o = options;
  std::error_code ec;
  const std::filesystem::path standard(kStandardIncludeDir);
  if (std::filesystem::is_directory(standard, ec) &&
      std::find(o.library_paths.begin(), o.library_paths.end(), standard) == o.library_paths.end())
    o.library_paths.push_back(standard);
  return o;
}

// Takes the text over: a scene file read from disk is not copied once more (7 MB in a large scene).
SceneDescription parse_owned_text(std::string text, const std::string& name, const ParseOptions& options) {
  const ParseOptions o = with_standard_includes(options);
  sdl::Interpreter interpreter(o);
  auto file = std::make_unique<SourceFile>();
  file->name = interpreter.file_name(name);
  file->path = name;
  file->text = std::move(text);
  return interpreter.run(std::move(file));
}
}  // namespace

SceneDescription parse_scene_text(const std::string& text, const std::string& name, const ParseOptions& options) {
  return parse_owned_text(text, name, options);
}

SceneDescription parse_scene(const std::filesystem::path& path, const ParseOptions& options) {
  std::string text;
  try {
    text = read_text_file(path);
  } catch (const std::exception& e) {
    FileNames name;   // the error keeps a copy
    throw ParseError(SourceLoc{name.intern(path.string()), 0, 0}, e.what());
  }
  return parse_owned_text(std::move(text), path.string(), options);
}

}  // namespace povtrace
