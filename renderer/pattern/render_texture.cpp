#include "renderer/pattern/render_texture.hpp"

#include "renderer/pattern/normal_perturbation.hpp"
#include "renderer/pattern/render_pigment.hpp"

namespace povtrace::render {

namespace {
RenderLayer build_layer(const TextureLayer& l, ImageCache& images, bool quick_colours) {
  RenderLayer layer;
  layer.pigment = build_render_pigment(l.pigment, &images, quick_colours);
  layer.finish = l.finish;
  if (l.normal) layer.normal = build_render_normal(*l.normal, &images);
  layer.specular_exponent = 1.0 / l.finish.roughness;
  layer.has_highlights = l.finish.phong != 0.0 || l.finish.specular != 0.0;
  const auto nonzero = [](const Colour& c) { return c.r != 0 || c.g != 0 || c.b != 0; };
  layer.reflects = nonzero(l.finish.reflection_min) || nonzero(l.finish.reflection_max);
  layer.reflection_exponent_inverse = 1.0 / l.finish.reflection_exponent;
  return layer;
}

bool pigment_reads_uv(const RenderPigment& p) {
  if (p.pattern == PatternKind::uv_mapping) return true;
  if (p.params.pigment && pigment_reads_uv(*p.params.pigment)) return true;
  for (const auto& c : p.children)
    if (pigment_reads_uv(c)) return true;
  return false;
}

bool normal_reads_uv(const RenderNormal& n) { return n.uv_normal != nullptr; }

bool is_surface_pattern(PatternKind k) { return k == PatternKind::slope || k == PatternKind::aoi; }

bool pigment_reads_surface(const RenderPigment& p) {
  if (is_surface_pattern(p.pattern)) return true;
  if (p.params.pigment && pigment_reads_surface(*p.params.pigment)) return true;
  for (const auto& c : p.children)
    if (pigment_reads_surface(c)) return true;
  return false;
}

bool normal_reads_surface(const RenderNormal& n) {
  if (pigment_reads_surface(n.pattern)) return true;
  if (n.uv_normal && normal_reads_surface(*n.uv_normal)) return true;
  for (const auto& e : n.map)
    if (e.normal && normal_reads_surface(*e.normal)) return true;
  return false;
}
}  // namespace

bool texture_reads_surface(const RenderTexture& texture) {
  if (texture.patterned() && pigment_reads_surface(texture.pattern)) return true;
  for (const RenderLayer& l : texture.layers)
    if (pigment_reads_surface(l.pigment) || (l.normal && normal_reads_surface(*l.normal))) return true;
  for (const RenderTexture& c : texture.children)
    if (texture_reads_surface(c)) return true;
  return false;
}

RenderTexture build_render_texture(const Texture& texture, ImageCache& images, bool quick_colours) {
  RenderTexture r;
  if (!texture.patterned()) {
    for (auto it = texture.layers.rbegin(); it != texture.layers.rend(); ++it)
      r.layers.push_back(build_layer(*it, images, quick_colours));
    return r;
  }
  const TexturePattern& pattern = *texture.pattern;
  // The pattern as a pigment without colours; uv_mapping has no value of its own, only transforms that move the
  // layer normals below it.
  Pigment carrier = pattern.pattern;
  carrier.entries.clear();
  const PatternKind kind = carrier.pattern;
  if (kind == PatternKind::uv_mapping) carrier.pattern = PatternKind::bozo;
  r.pattern = build_render_pigment(carrier, &images);
  r.pattern.pattern = kind;
  r.pattern.map.clear();
  r.pattern.children.clear();
  Matrix pattern_from_world;
  for (const PatternStep& s : r.pattern.steps)
    if (s.transformed) pattern_from_world = pattern_from_world * s.pattern_from_world;
  r.warps_normals = !(pattern_from_world == Matrix::identity());
  r.pattern_from_world = pattern_from_world;
  r.world_from_pattern = pattern_from_world.inverse();
  for (const TextureMapEntry& e : pattern.entries) {
    r.children.push_back(build_render_texture(*e.texture, images, quick_colours));
    r.children.back().value = e.value;
  }
  return r;
}

double texture_pattern_value(const RenderTexture& texture, const TexturePoint& p) {
  const RenderPigment& pattern = texture.pattern;
  if (pattern.pattern == PatternKind::material_map)
    return static_cast<double>(material_map_index(*pattern.image, p.point, texture.children.size()));
  return apply_wave(pattern_value(pattern.params, p.point, p.surface), pattern.wave);
}

bool texture_is_opaque(const RenderTexture& texture) {
  if (texture.patterned()) return false;
  for (const RenderLayer& l : texture.layers)
    if (!pigment_has_transparency(l.pigment)) return true;
  return false;
}

bool texture_reads_uv(const RenderTexture& texture) {
  if (texture.patterned() && texture.pattern.pattern == PatternKind::uv_mapping) return true;
  for (const RenderLayer& l : texture.layers)
    if (pigment_reads_uv(l.pigment) || (l.normal && normal_reads_uv(*l.normal))) return true;
  for (const RenderTexture& c : texture.children)
    if (texture_reads_uv(c)) return true;
  return false;
}

void set_texture_generator(RenderTexture& texture, NoiseGenerator generator) {
  set_generator(texture.pattern, generator);
  for (RenderLayer& l : texture.layers) {
    set_generator(l.pigment, generator);
    if (l.normal) set_normal_generator(*l.normal, generator);
  }
  for (RenderTexture& c : texture.children) set_texture_generator(c, generator);
}

}  // namespace povtrace::render
