// The scene statements (docs/parser-split-plan.md step S11): the parse's top-level loop and what it reads between
// directives — camera, lights and objects placed in the scene, global_settings, background, sky_sphere, fog,
// #default, #version's effect — with the SceneDescription they fill. Its bodies are in scene.cpp.
//
// It owns the scene being made and the settings later statements read: the #default texture (and the copy shared
// by the untextured objects placed since it last changed) and radiosity importance, whether a camera, a statement
// and a #version were seen (POV-Ray's languageVersionSet), and through the scene the language version,
// assumed_gamma and noise generator.
//
// Public interface: run (the Interpreter), parse_default and directive_version (the DirectiveRunner), place_object
// and place_light (`object { }` and the CSG's lights, through ParserPart) and the settings' read accessors
// (ParserPart's default_texture, language_version, version_directive_seen, assumed_gamma, noise_generator).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "parser/parse_scene.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class SymbolTable;
class TokenReader;
class DirectiveRunner;
class ExpressionParser;
class TextureParser;
class CameraLightParser;
class ObjectParser;
class UnsupportedFeatures;
class RadiosityParser;

class SceneStatements : ParserPart {
 public:
  // Only kept here, not used, until the parse runs (the Interpreter builds the parts it calls after it).
  SceneStatements(Interpreter& in, const ParseOptions& options, SymbolTable& symbols, TokenReader& reader,
                  DirectiveRunner& directives, ExpressionParser& expressions, TextureParser& textures,
                  CameraLightParser& camera_lights, ObjectParser& objects, UnsupportedFeatures& unsupported,
                  RadiosityParser& radiosity)
      : ParserPart(in),
        options_(options),
        symbols_(symbols),
        reader_(reader),
        directives_(directives),
        expressions_(expressions),
        textures_(textures),
        camera_lights_(camera_lights),
        objects_(objects),
        unsupported_(unsupported),
        radiosity_(radiosity) {
    default_texture_.layers.emplace_back();   // black pigment, default finish (§11 "Default texture")
  }

  SceneDescription run(std::unique_ptr<SourceFile> main_file);
  void parse_default(const Token& keyword);
  void directive_version(const Token& at);
  void open_include_header(const std::filesystem::path& header);
  void place_object(Object&& object, const SourceLoc& at);   // finished in place, then moved into the scene once
  void place_light(Light light, const SourceLoc& at);

  const Texture& default_texture() const { return default_texture_; }
  int language_version() const { return scene_.language_version; }
  bool version_directive_seen() const { return version_directive_seen_; }
  const std::optional<double>& assumed_gamma() const { return scene_.settings.assumed_gamma; }
  // The scene's noise generator in force now (POV-Ray's: 1 before #version 3.5, 2 from then on, unless
  // global_settings set it), which functions evaluated during the parse read.
  int noise_generator() const {
    return scene_.settings.noise_generator.value_or(scene_.language_version < 350 ? 1 : 2);
  }

 private:
  void parse_statement(const Token& t);
  void parse_global_settings(const Token& keyword);
  void parse_photon_settings(const Token& keyword);   // photon_settings.cpp
  void parse_background(const Token& keyword);
  void add_light(Light light, std::optional<double> importance);   // importance: the CSG parent's, if any
  void post_process(Object& object);
  void assign_light_groups(Object& object);
  void placed(Object& object);   // the last step before the object joins scene_.objects
  std::string reached_from() const;

  const ParseOptions& options_;
  SymbolTable& symbols_;
  TokenReader& reader_;
  DirectiveRunner& directives_;
  ExpressionParser& expressions_;
  TextureParser& textures_;
  CameraLightParser& camera_lights_;
  ObjectParser& objects_;
  UnsupportedFeatures& unsupported_;
  RadiosityParser& radiosity_;
  SceneDescription scene_;
  Texture default_texture_;
  std::shared_ptr<const Texture> placed_default_texture_;   // shared by untextured objects until #default changes
  int next_light_group_ = 0;   // the id the next light_group placed gets (Light::group)
  bool camera_seen_ = false;
  bool statement_seen_ = false;
  // The scene's noise generator as functions see it when they run (POV-Ray's f_noise3d reads the scene's current
  // setting): updated at #version, at global_settings and once more when the parse ends, so that functions
  // evaluated while rendering see the final one.
  bool version_directive_seen_ = false;   // POV-Ray's languageVersionSet: any #version so far
};

}  // namespace povtrace::sdl
