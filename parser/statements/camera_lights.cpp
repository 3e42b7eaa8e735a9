// camera { } and light_source { } (povray-pixel-pipeline.md §1 and §3).
#include <cmath>
#include <limits>

#include "scene/description_transforms.hpp"
#include "scene/pov_vector_math.hpp"
#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/statements/camera_light_parser.hpp"
#include "parser/objects/object_transform.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
struct CameraInput {
  Camera camera;
  Vec3 sky{0, 1, 0};
  std::optional<Vec3> look_at;
  std::optional<double> angle;
  bool up_given = false, right_given = false;
  bool planar = true;   // perspective or orthographic: `angle` sets the direction's length
  std::optional<Vec3> focal_point;   // POV-Ray 3.5 and later: its distance from the location once resolved
  Matrix transform;
};

// A vector too short to normalise: zero, or so small that its squared length underflows. This test has no scale
// of its own (unlike POV-Ray's EPSILON on the squared length), so a camera in a tiny scene is not refused for being
// tiny (issue 7: such scenes render as their twins at an ordinary scale).
bool is_zero(Vec3 v) { return !(dot(v, v) >= std::numeric_limits<double>::min()); }

bool is_finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// POV-Ray's fixed order of application (its vectors normalised as POV-Ray does, so that every camera ray agrees
// with POV-Ray's to the last bit: chaotic patterns such as a fractal's escape value amplify any difference), whatever the textual order (§1): vectors as given; then angle; then
// look_at; then the orthographic resize; finally the camera's own transforms.
Camera resolve_camera(const CameraInput& in, const std::function<void(const std::string&)>& warn) {
  Camera c = in.camera;
  double direction_length = 1.0;   // POV-Ray's Direction_Length: set by angle and look_at only
  if (in.angle && *in.angle > 0 && in.planar) {   // POV-Ray applies an angle of 0 as no angle
    direction_length = length(c.right) / std::tan(*in.angle * kPovPiOver360) / 2.0;
    c.direction = pov_normalized(c.direction) * direction_length;
  }
  if (in.angle && !in.planar) c.angle = *in.angle;   // the other projections read it as it is
  if (in.look_at) {   // parse_camera has refused a look_at at the location, and a zero right where it is needed
    const double dl = length(c.direction), ul = length(c.up), rl = length(c.right);
    direction_length = dl;
    const double handedness = dot(cross(c.up, c.direction), c.right);
    const Vec3 d = pov_normalized(*in.look_at - c.location);
    Vec3 r = cross(in.sky, d);
    if (length(r) < 1e-10) {   // the same test as check_camera's
      warn("camera look_at is parallel to sky: the previous 'right' is kept");
      r = c.right;
    }
    r = pov_normalized(r);
    const Vec3 u = cross(d, r);
    c.direction = d * dl;
    c.right = r * (handedness > 0 ? rl : -rl);
    c.up = u * ul;
  }
  // The orthographic resize happens when neither up nor right is given, or when any angle is (0 included: the
  // orthographic `angle` with no value means 0, POV-Ray's way of asking for the resize). Like POV-Ray it skips a
  // zero distance or a zero direction (EPSILON on the lengths) instead of scaling by 0 or infinity.
  if (c.projection == Projection::orthographic && ((!in.up_given && !in.right_given) || in.angle)) {
    const Vec3 target = in.look_at.value_or(Vec3{0, 0, 1});
    const double k1 = length(target - c.location), k2 = length(c.direction);
    if (k1 > 1e-10 && k2 > 1e-10) {
      c.right = c.right * (k1 / k2);
      c.up = c.up * (k1 / k2);
    }
  }
  // The focal distance (Parse_Camera): focal_point's distance from the location, before the transforms; else the
  // direction's length as angle or look_at left it; 0 becomes 1.
  FocalBlur& blur = c.focal_blur;
  if (in.focal_point) blur.focal_distance = length(*in.focal_point - c.location);
  if (blur.focal_distance < 0.0) blur.focal_distance = direction_length;
  if (blur.focal_distance == 0.0) blur.focal_distance = 1.0;
  c.location = in.transform.point(c.location);
  c.direction = in.transform.vector(c.direction);
  c.up = in.transform.vector(c.up);
  c.right = in.transform.vector(c.right);
  return c;
}

// Where the items that the checks point at were written.
struct CameraTokens {
  Token keyword;
  std::optional<Token> angle, look_at, direction, right;
};

// The camera inputs POV-Ray refuses, and those it turns into NaN vectors or rays without a direction (an image of
// the background colour, or worse): each an error at the item that causes it.
// `fail` throws (the parser's fail_at).
void check_camera(const CameraInput& in, const CameraTokens& at, bool povray_tolerances,
                  const std::function<void(const Token&, const std::string&)>& fail,
                  const std::function<void(const std::string&)>& warn) {
  const Camera& c = in.camera;
  const Token& keyword = at.keyword;
  const std::optional<Token>& angle_at = at.angle;
  const std::optional<Token>& look_at_at = at.look_at;
  const std::optional<Token>& direction_at = at.direction;
  const std::optional<Token>& right_at = at.right;
  if (!is_finite(c.location) || !is_finite(c.direction) || !is_finite(c.up) || !is_finite(c.right) ||
      !is_finite(in.sky) || (in.look_at && !is_finite(*in.look_at)))
    fail(keyword, "the camera's vectors must be finite (one has an infinite or undefined coordinate)");
  if (in.angle && in.planar && *in.angle >= 180)
    fail(*angle_at, "the camera angle must be less than 180 degrees for a perspective or orthographic camera");
  // POV-Ray's Parse_Camera refuses a look_at at the location (before the camera's transforms). Its test is absolute,
  // a squared distance below EPSILON (1e-10): a camera 1e-6 times the usual size fails it; povtrace applies it under
  // --povray-tolerances only, and otherwise refuses a distance that is zero at any scale.
  if (in.look_at) {
    const Vec3 d = *in.look_at - c.location;
    if (povray_tolerances ? dot(d, d) < 1e-10 : is_zero(d))
      fail(*look_at_at, "Camera location and look_at point must be different.");
  }
  if (in.angle && *in.angle == 0 && c.projection == Projection::perspective)
    warn("a perspective camera's angle 0 leaves its field of view as it is (POV-Ray ignores it)");
  const bool zero_width = in.angle && *in.angle == 0 && !in.planar && c.projection != Projection::omnimax &&
                          c.projection != Projection::panoramic;
  if (zero_width || (c.projection == Projection::spherical && (c.h_angle == 0 || c.v_angle == 0)))
    warn("a camera angle of 0: every pixel along that axis of the image sees the same ray");
  // An angle rescales the direction vector to the length the angle asks for: POV-Ray normalises a zero direction
  // into NaN and renders nothing but the background.
  if (in.angle && *in.angle > 0 && in.planar && is_zero(c.direction))
    fail(direction_at ? *direction_at : *angle_at,
         "the camera direction is the zero vector: the angle has no direction to set the length of");
  // look_at takes `right` across its direction from the sky; when the two are parallel it keeps the given right
  // (POV-Ray warns) and normalises it: a zero right would become NaN.
  if (in.look_at && length(cross(in.sky, normalize(*in.look_at - c.location))) < 1e-10 && is_zero(c.right))
    fail(right_at ? *right_at : *look_at_at,
         "the camera right vector is zero and look_at is parallel to sky (or sky is zero): the image has no "
         "horizontal direction");
  // Rays without a direction: an orthographic camera whose direction is zero (every ray), or any camera whose
  // direction, up and right are all zero. POV-Ray renders the background colour everywhere.
  const bool zero_direction = is_zero(c.direction) || (in.angle && *in.angle > 0 && in.planar && is_zero(c.right));
  if (c.projection == Projection::orthographic && zero_direction)
    fail(direction_at ? *direction_at : (right_at ? *right_at : keyword),
         "the orthographic camera's direction is the zero vector: its rays have no direction");
  if (zero_direction && is_zero(c.up) && is_zero(c.right))
    fail(keyword, "the camera's direction, up and right vectors are all zero: its rays have no direction");
}
}  // namespace

// The projection keywords of camera { }; `cylinder N` takes its type number (1 to 4, else POV-Ray's error).
std::optional<Projection> CameraLightParser::try_camera_type(const Token& t) {
  static const std::pair<std::string_view, Projection> types[] = {
      {"perspective", Projection::perspective}, {"orthographic", Projection::orthographic},
      {"fisheye", Projection::fisheye},         {"ultra_wide_angle", Projection::ultra_wide_angle},
      {"omnimax", Projection::omnimax},         {"panoramic", Projection::panoramic},
      {"spherical", Projection::spherical}};
  for (const auto& [name, type] : types)
    if (t.is(name)) return type;
  if (!t.is("cylinder")) return std::nullopt;
  const Token at = peek();
  switch (static_cast<int>(parse_float())) {
    case 1: return Projection::cylinder1;
    case 2: return Projection::cylinder2;
    case 3: return Projection::cylinder3;
    case 4: return Projection::cylinder4;
    default: fail_at(at, "invalid cylinder camera type, valid are types 1 to 4 (as in POV-Ray)");
  }
}

// aperture, blur_samples, confidence, variance and focal_point (POV-Ray's Parse_Camera_Mods; before 3.5 its old
// syntax: blur_samples takes one number and focal_point's distance is taken from the location written so far).
void CameraLightParser::parse_focal_blur_item(const Token& t, Camera& camera, std::optional<Vec3>& focal_point) {
  FocalBlur& blur = camera.focal_blur;
  const bool new_syntax = language_version() >= 350;
  if (t.is("aperture")) {
    blur.aperture = parse_float();
  } else if (t.is("blur_samples")) {
    const int first = saturating_cast<int>(parse_float());
    if (first <= 0) fail_at(t, "blur_samples must be at least 1 (POV-Ray: \"Illegal number of focal blur samples\")");
    if (!new_syntax) {
      blur.samples = first;
      return;
    }
    accept(",");
    const int second = saturating_cast<int>(optional_float(0.0));
    if (second == 0) {   // one number: the maximum, with no minimum
      blur.samples = first;
      blur.min_samples = 0;
    } else if (first > second) {
      fail_at(t, "the minimum of blur_samples must not be larger than its maximum (as in POV-Ray)");
    } else {
      blur.min_samples = first;
      blur.samples = second;
    }
  } else if (t.is("confidence")) {
    const double k = parse_float();
    if (k > 0.0 && k < 1.0) blur.confidence = k;
    else warn(t.loc, "illegal confidence value (it must lie between 0 and 1); the default 0.9 is used, as in POV-Ray");
  } else if (t.is("variance")) {
    const double k = parse_float();
    if (k >= 0.0 && k <= 1.0) blur.variance = k;
    else warn(t.loc, "illegal variance value (it must lie in 0 … 1); the default 1/10000 is used, as in POV-Ray");
  } else {   // focal_point
    const Vec3 p = parse_vector();
    if (new_syntax) focal_point = p;
    else blur.focal_distance = length(p - camera.location);
  }
}

Camera CameraLightParser::parse_camera(const Token& keyword) {
  expect("{", " after 'camera'");
  CameraInput in;
  in.camera.loc = keyword.loc;
  CameraTokens at{keyword, {}, {}, {}, {}};
  bool spherical = false;
  bool item_seen = false;   // an item other than the projection type has been read
  Token t = next();
  if (const Value* v = lookup(t)) {
    if (v && std::holds_alternative<Boxed<Camera>>(*v)) {
      in.camera = *std::get<Boxed<Camera>>(*v);
      t = next();
      // POV-Ray 3.5 and later (Parse_Camera's only_mods): a declared camera is final; only transforms may follow,
      // applied to it as they are (its angle, look_at and orthographic resize are not applied a second time).
      if (language_version() >= 350) return parse_camera_transforms(in.camera, t);
    }
  }
  while (!t.is("}")) {
    const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
    if (k == "mesh_camera") {   // a projection with its block (mesh_camera.cpp)
      if (item_seen && language_version() >= 350)
        fail_at(t, "the camera type 'mesh_camera' must come first in camera { }, before location, angle and the "
                   "other items (POV-Ray 3.5 and later)");
      if (in.camera.mesh) fail_at(t, "a camera has at most one mesh_camera { }");
      in.camera.mesh = parse_mesh_camera(t, in.camera.unsupported);
      in.camera.projection = Projection::mesh;
      in.planar = false;
      spherical = false;
      t = next();
      continue;
    }
    if (const std::optional<Projection> type = try_camera_type(t)) {
      // POV-Ray 3.5 and later read the projection keywords only at the start of camera { } (several may follow
      // one another, the last one counts); one after any other item is its parse error.
      if (item_seen && language_version() >= 350)
        fail_at(t, "the camera type '" + std::string(t.text) + "' must come first in camera { }, before " +
                       "location, angle and the other items (POV-Ray 3.5 and later)");
      in.camera.projection = *type;
      in.planar = *type == Projection::perspective || *type == Projection::orthographic;
      spherical = *type == Projection::spherical;
      t = next();
      continue;
    }
    item_seen = true;
    if (k == "location") in.camera.location = parse_vector();
    else if (k == "direction") { at.direction = t; in.camera.direction = parse_vector(); }
    else if (k == "up") { in.camera.up = parse_vector(); in.up_given = true; }
    else if (k == "right") { at.right = t; in.camera.right = parse_vector(); in.right_given = true; }
    else if (k == "sky") in.sky = parse_vector();
    else if (k == "look_at") {
      at.look_at = t;
      in.look_at = parse_vector();
    }
    else if (k == "angle") {
      // POV-Ray's mesh camera has no angle: its parser stops there ("No matching } in 'camera'").
      if (in.camera.projection == Projection::mesh) fail_at(t, "a mesh_camera has no angle (as in POV-Ray)");
      // Negative angles are refused at once; the 180° limit only holds for perspective and orthographic cameras
      // (fisheye and the others take up to 360°), checked once the projection is known. An orthographic camera's
      // angle may have no value: it then means 0 (POV-Ray's Allow_Float(0.0)).
      in.angle = in.camera.projection == Projection::orthographic && language_version() >= 350 ? optional_float(0.0)
                                                                                               : parse_float();
      if (*in.angle < 0) fail_at(t, "the camera angle must not be negative");
      at.angle = t;
      // A spherical camera takes a horizontal and an optional vertical angle (`angle 360, 180`); the vertical one
      // defaults to half the horizontal one (POV-Ray's Parse_Camera).
      if (spherical) {
        in.camera.h_angle = *in.angle;
        in.camera.v_angle = *in.angle * 0.5;
        in.angle.reset();
        accept(",");
        const Token v = peek();
        const Value* id = lookup(v);
        if (v.kind == TokenKind::number || v.is("(") || v.is("-") || v.is("+") ||
            (id && std::holds_alternative<Numeric>(*id))) {
          in.camera.v_angle = parse_float();
          if (in.camera.v_angle < 0) fail_at(v, "the vertical camera angle must not be negative");
        }
      }
    } else if (!textures_.try_transform(t, in.transform)) {
      if (k == "normal") {   // from the #default texture's normal, if any (Parse_Tnormal with none yet)
        const Normal start = textures_.starting_normal(nullptr);
        in.camera.normal = std::make_shared<const Normal>(textures_.parse_normal_block(t, start));
        taint(in.camera.unsupported, in.camera.normal->unsupported);
        t = next();
        continue;
      }
      if (k == "aperture" || k == "focal_point" || k == "blur_samples" || k == "confidence" || k == "variance") {
        parse_focal_blur_item(t, in.camera, in.focal_point);
        t = next();
        continue;
      }
      if (k == "bokeh") {
        taint(in.camera.unsupported, skip_unsupported(t, "the camera item 'bokeh'"));
        t = next();
        continue;
      }
      fail_expected(t, "a camera item (perspective, orthographic, location, look_at, right, up, direction, sky, "
                       "angle, translate, rotate, scale, matrix) or '}'");
    }
    t = next();
  }
  const auto warn_here = [&](const std::string& m) { warn(keyword.loc, m); };
  check_camera(in, at, povray_tolerances(), [&](const Token& where, const std::string& m) { fail_at(where, m); },
               warn_here);
  // POV-Ray traces a mesh camera's blurred rays from mesh number `ray` (one per blur sample), which povtrace does not
  // do: refused by name rather than rendered unblurred.
  if (in.camera.projection == Projection::mesh && in.camera.focal_blur.aperture != 0.0 &&
      in.camera.focal_blur.samples > 0) {
    taint(in.camera.unsupported, UnsupportedFeature{"focal blur (aperture, blur_samples) on a mesh_camera", keyword.loc});
  }
  const Camera c = resolve_camera(in, warn_here);
  if (!is_finite(c.location) || !is_finite(c.direction) || !is_finite(c.up) || !is_finite(c.right))
    fail_at(keyword, "the camera's vectors overflow (a coordinate beyond the range of floating point numbers)");
  return c;
}

// The transforms after a declared camera's identifier, up to the closing '}' (`t` is the first token after the
// identifier).
Camera CameraLightParser::parse_camera_transforms(Camera camera, Token t) {
  Matrix transform;
  while (!t.is("}")) {
    if (!textures_.try_transform(t, transform))
      fail_expected(t, "a transform (translate, rotate, scale, matrix, transform) or '}': after a declared camera "
                       "POV-Ray 3.5 and later take only transforms");
    t = next();
  }
  camera.location = transform.point(camera.location);
  camera.direction = transform.vector(camera.direction);
  camera.up = transform.vector(camera.up);
  camera.right = transform.vector(camera.right);
  return camera;
}

void CameraLightParser::apply_transform(Light& light, const Matrix& m) { transform_noted(light, m, notes_pool()); }

bool CameraLightParser::try_light_modifier(const Token& t, Light& light) {
  Matrix m;
  if (textures_.try_transform(t, m)) { apply_transform(light, m); return true; }
  const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
  if (k == "color" || k == "colour" || k == "rgb" || k == "rgbf" || k == "rgbt" || k == "rgbft") {
    unget(t);
    light.colour = parse_colour();
  } else if (k == "spotlight") {
    // As for `cylinder`, the keyword sets the kind's defaults (a radius written before it is an error in POV-Ray).
    light.spotlight = true;
    light.cylinder = false;
    light.radius = 30.0;
    light.falloff = 45.0;
    light.tightness = 0.0;
  }
  else if (k == "cylinder") {
    // POV-Ray's defaults for a cylindrical light are set by the keyword itself.
    light.cylinder = true;
    light.spotlight = false;
    light.radius = 0.75;
    light.falloff = 1.0;
    light.tightness = 0.0;
  } else if (k == "looks_like") parse_looks_like(t, light);
  else if (k == "parallel") light.parallel = true;
  else if (k == "shadowless") light.shadowless = true;
  else if (k == "point_at") light.point_at = parse_vector();
  else if (k == "radius") light.radius = parse_float();
  else if (k == "falloff") light.falloff = parse_float();
  else if (k == "tightness") light.tightness = parse_float();
  else if (k == "fade_distance") light.fade_distance = parse_float();
  else if (k == "fade_power") light.fade_power = parse_float();
  else if (k == "area_light") parse_area_light(t, light);
  else if (k == "adaptive") light.adaptive = static_cast<int>(parse_float());
  else if (k == "jitter") light.jitter = true;
  else if (k == "circular" || k == "orient") {
    (k == "circular" ? light.circular : light.orient) = true;
    if (!light.area) warn(t.loc, "'" + std::string(k) + "' only affects an area_light");
  } else if (k == "media_interaction") light.media_interaction = optional_float(1.0) > 0.0;
  else if (k == "media_attenuation") light.media_attenuation = optional_float(1.0) > 0.0;
  else if (k == "photons") parse_light_photons(t, light);
  else if (k == "projected_through") parse_projected_through(t, light);
  else if (k == "area_illumination")
    taint(light.unsupported, skip_unsupported(t, "the light_source item '" + std::string(k) + "'"));
  else return false;
  return true;
}

// looks_like { object modifiers }: the object is moved to the light's location as it is at this point, then takes
// the modifiers written after it, and every later transform of the light (POV-Ray's Parse_Light_Source). It casts
// no shadow.
void CameraLightParser::parse_looks_like(const Token& keyword, Light& light) {
  const NestingGuard guard(*this, keyword);
  if (!light.looks_like.empty()) fail_at(keyword, "a light_source has at most one looks_like object");
  expect("{", " after 'looks_like'");
  const Token first = next();
  auto item = try_parse_item(first);
  if (!item || !std::holds_alternative<Object>(*item)) fail_expected(first, "an object in looks_like { }");
  Object object = std::move(std::get<Object>(*item));
  apply_transform(object, Matrix::translation(light.location));
  parse_object_modifiers(object);
  object.no_shadow = true;
  light.looks_like.push_back(std::move(object));
}

// projected_through { OBJECT modifiers } (POV-Ray's Parse_Light_Source): one object, not moved to the light; a
// texture or interior it has is removed with a warning, as POV-Ray removes them.
void CameraLightParser::parse_projected_through(const Token& keyword, Light& light) {
  const NestingGuard guard(*this, keyword);
  if (!light.projected_through.empty())
    fail_at(keyword, "a light_source has at most one projected_through object (as in POV-Ray)");
  expect("{", " after 'projected_through'");
  const Token first = next();
  auto item = try_parse_item(first);
  if (!item || !std::holds_alternative<Object>(*item)) fail_expected(first, "an object in projected_through { }");
  Object object = std::move(std::get<Object>(*item));
  parse_object_modifiers(object);
  if (object.interior) {
    warn(keyword.loc, "a projected_through object cannot have an interior: it is removed, as POV-Ray removes it");
    object.interior.reset();
  }
  if (object.texture) {
    warn(keyword.loc, "a projected_through object cannot have a texture: it is removed, as POV-Ray removes it");
    object.texture.reset();
  }
  light.projected_through.push_back(std::move(object));
}

// area_light <axis1>, <axis2>, size1, size2: the sizes are truncated to integers and must not be 0 (POV-Ray's
// Parse_Light_Source); a negative size is refused here too, as it would give no samples at all.
// photons { refraction B reflection B area_light } (POV-Ray's Parse_Light_Source; refraction and reflection read a
// float and truncate it).
void CameraLightParser::parse_light_photons(const Token& keyword, Light& light) {
  (void)keyword;
  expect("{", " after 'photons'");
  while (true) {
    const Token t = next();
    if (t.is("}")) return;
    if (t.is("refraction")) light.photon_refraction = saturating_cast<int>(parse_float()) != 0;
    else if (t.is("reflection")) light.photon_reflection = saturating_cast<int>(parse_float()) != 0;
    else if (t.is("area_light")) light.photon_area_light = true;
    else fail_expected(t, "refraction, reflection, area_light or '}' in the light's photons { }");
  }
}

void CameraLightParser::parse_area_light(const Token& keyword, Light& light) {
  (void)keyword;
  light.area = true;
  light.axis1 = parse_vector();
  accept(",");
  light.axis2 = parse_vector();
  accept(",");
  auto size = [this] {
    const Token at = peek();
    const double n = parse_float();
    if (!(n >= 1.0)) fail_at(at, "an area_light size must be at least 1");
    if (n > 1e6) fail_at(at, "an area_light size must be at most 1000000");
    return static_cast<int>(n);
  };
  light.size1 = size();
  accept(",");
  const Token second = peek();
  light.size2 = size();
  // Each shading point keeps one result per sample: a bound keeps that memory sane.
  if (static_cast<double>(light.size1) * light.size2 > 1e6)
    fail_at(second, "an area_light may have at most 1000000 samples (size1 × size2)");
}

Light CameraLightParser::parse_light(const Token& keyword) {
  expect("{", " after 'light_source'");
  Light light;
  light.loc = keyword.loc;
  Token t = next();
  bool copied = false;
  if (const Value* v = lookup(t)) {
    if (v && std::holds_alternative<std::shared_ptr<const SceneItem>>(*v) &&
        std::holds_alternative<Light>(*std::get<std::shared_ptr<const SceneItem>>(*v))) {
      light = std::get<Light>(*std::get<std::shared_ptr<const SceneItem>>(*v));
      copied = true;
      t = next();
    }
  }
  if (!copied) {
    unget(t);
    light.location = parse_vector();
    accept(",");
    light.colour = parse_colour();
    t = next();
  }
  while (!t.is("}")) {
    if (!try_light_modifier(t, light))
      fail_expected(t, "a light_source item (color, spotlight, parallel, shadowless, point_at, radius, falloff, "
                       "tightness, fade_distance, fade_power, a transform) or '}'");
    t = next();
  }
  return light;
}

}  // namespace povtrace::sdl
