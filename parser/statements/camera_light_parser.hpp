// The camera and light part of the parser (docs/parser-split-plan.md step S10): `camera { }` and `light_source { }`
// with their modifiers (povray-pixel-pipeline.md §1 and §3). Its bodies are in camera_lights.cpp. It owns no state:
// transforms come from the TextureParser; the object of looks_like, the notes pool that moves it and the option
// povray_tolerances come through ParserPart.
#pragma once

#include <optional>

#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class TextureParser;

class CameraLightParser : ParserPart {
 public:
  CameraLightParser(Interpreter& in, TextureParser& textures) : ParserPart(in), textures_(textures) {}

  Camera parse_camera(const Token& keyword);   // after the keyword `camera`
  Light parse_light(const Token& keyword);      // after the keyword `light_source`
  // A modifier of a light inside a CSG (transforms, and what parse_light reads inside its block): true when `t`
  // was one and has been read.
  bool try_light_modifier(const Token& t, Light& light);

 private:
  Camera parse_camera_transforms(Camera camera, Token t);
  std::optional<Projection> try_camera_type(const Token& t);
  void parse_focal_blur_item(const Token& t, Camera& camera, std::optional<Vec3>& focal_point);
  std::shared_ptr<const MeshCamera> parse_mesh_camera(const Token& keyword, Unsupported& unsupported);
  void parse_area_light(const Token& keyword, Light& light);
  void parse_light_photons(const Token& keyword, Light& light);
  void parse_looks_like(const Token& keyword, Light& light);
  void parse_projected_through(const Token& keyword, Light& light);
  using ParserPart::apply_transform;   // an object's (looks_like), next to the light's below
  void apply_transform(Light& light, const Matrix& m);

  TextureParser& textures_;
};

}  // namespace povtrace::sdl
