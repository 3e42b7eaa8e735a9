// The contract between the parser and the renderer: a plain scene description. The parser fills it (with
// every POV-Ray 3.7 default already in the member initialisers), the renderer builds its own render-ready form
// from it. No renderer type appears here and nothing here computes anything but the values POV-Ray's parser
// itself resolves at parse time (camera vectors, transforms already composed into matrices).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "mesh_description.hpp"
#include "source_location.hpp"
#include "vecmath.hpp"

namespace povtrace {

// Five-channel colour: rgb plus filter and transmit (povray-pixel-pipeline.md notation).
struct Colour {
  double r = 0, g = 0, b = 0, f = 0, t = 0;
  friend constexpr bool operator==(const Colour&, const Colour&) = default;
};

// A POV-Ray feature that povtrace parses but does not render yet (issue 3: standard include files and scenes
// must parse whole). A value built with one carries it; the parser refuses the value by this name, with both
// positions, when it reaches the rendered scene. A SceneDescription returned by the parser never holds one.
struct UnsupportedFeature {
  std::string name;   // e.g. "the pigment pattern 'granite'"
  SourceLoc loc;      // where the feature is written
};
using Unsupported = std::optional<UnsupportedFeature>;

// ---- Textures -------------------------------------------------------------------------------------------
enum class PatternKind { solid, checker };

struct Pigment {
  PatternKind pattern = PatternKind::solid;
  Colour colour;                 // solid colour (default: black, rgbft 0)
  std::vector<Colour> entries;   // checker: the two colours (defaults blue/green as POV-Ray when omitted)
  Matrix world_from_pattern;     // every transform applied to the pigment since it was created
  SourceLoc loc;
  Unsupported unsupported;
};

// Finish defaults for #version 3.7 (povray-pixel-pipeline.md §2).
struct Finish {
  Colour ambient{0.1f, 0.1f, 0.1f};   // a colour, so single precision as in POV-Ray
  Colour emission{};
  double diffuse = 0.6;
  double diffuse_back = 0.0;     // second `diffuse` value
  double brilliance = 1.0;
  double phong = 0.0;
  double phong_size = 40.0;
  double specular = 0.0;
  double roughness = 0.05;       // as written; the shading exponent is 1/roughness
  double metallic = 0.0;
  Colour reflection_min{}, reflection_max{};
  double reflection_falloff = 1.0;
  double reflection_exponent = 1.0;
  bool reflection_fresnel = false;
  double reflection_metallic = 0.0;
  bool conserve_energy = false;
  double crand = 0.0;
  SourceLoc loc;
  Unsupported unsupported;
};

struct TextureLayer {
  Pigment pigment;
  Finish finish;
};

// Layers in written order: the *last* one is the top layer (pipeline §2 "Layers").
struct Texture {
  std::vector<TextureLayer> layers;
  SourceLoc loc;
  Unsupported unsupported;
};

struct Interior {
  double ior = 1.0;
  double fade_distance = 0.0;
  double fade_power = 0.0;
  Colour fade_colour{};
  Unsupported unsupported;
};

// ---- Geometry -------------------------------------------------------------------------------------------
struct Sphere { Vec3 centre; double radius = 1; };
struct Plane { Vec3 normal{0, 1, 0}; double distance = 0; };   // normal as written (unit-normalised by parser)
struct Box { Vec3 corner1{-1, -1, -1}, corner2{1, 1, 1}; };     // sorted per axis by the parser

enum class CsgKind { union_, merge, intersection, difference };
struct Object;
struct Light;
struct Csg {
  CsgKind kind = CsgKind::union_;
  std::vector<Object> children;
  std::vector<Light> lights;      // light sources written inside the CSG move with it
};

using Shape = std::variant<Sphere, Plane, Box, Csg, Triangle, Polygon, Mesh>;

struct Object {
  Shape shape;
  Matrix world_from_object;                 // composed object transforms in written order
  std::shared_ptr<const Texture> texture;   // never null once the parser has placed the object
  std::optional<Interior> interior;
  bool inverse = false;
  bool no_shadow = false;
  SourceLoc loc;
  Unsupported unsupported;
};

// ---- Camera and lights ----------------------------------------------------------------------------------
enum class Projection { perspective, orthographic };

// Final camera vectors, resolved by the parser in POV-Ray's fixed order (pipeline §1).
struct Camera {
  Projection projection = Projection::perspective;
  Vec3 location{0, 0, 0};
  Vec3 direction{0, 0, 1};
  Vec3 up{0, 1, 0};
  Vec3 right{1.33, 0, 0};
  SourceLoc loc;
  Unsupported unsupported;
};

struct Light {
  Vec3 location;
  Colour colour{1, 1, 1};
  bool parallel = false;
  bool spotlight = false;
  bool shadowless = false;
  Vec3 point_at{0, 0, 1};
  double radius = 30.0;     // spotlight, degrees
  double falloff = 45.0;    // spotlight, degrees
  double tightness = 0.0;   // spotlight
  double fade_distance = 0.0;
  double fade_power = 0.0;
  SourceLoc loc;
  Unsupported unsupported;
};

// ---- Whole scene ----------------------------------------------------------------------------------------
struct GlobalSettings {
  std::optional<double> assumed_gamma;   // absent: 1.0 for #version ≥ 3.7, legacy sRGB otherwise (pipeline §6)
  Colour ambient_light{1, 1, 1};
  int max_trace_level = 5;
  double adc_bailout = 1.0 / 255.0;
};

struct SceneDescription {
  int language_version = 370;            // round(100 · #version); 370 when no #version was seen
  bool version_given = false;            // a #version directive appeared before the first statement
  GlobalSettings settings;
  Camera camera;
  Colour background{0, 0, 0, 0, 1};      // POV-Ray 3.7's default: rgbt <0,0,0,1>
  std::vector<Light> lights;
  std::vector<Object> objects;           // every object has a texture after parsing (CSG inheritance and the
                                         // #default texture resolved as POV-Ray's Post_Process does)
};

}  // namespace povtrace
