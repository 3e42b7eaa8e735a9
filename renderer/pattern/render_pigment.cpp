#include "renderer/pattern/render_pigment.hpp"
#include "renderer/object_geometry.hpp"

#include "renderer/pattern/default_maps.hpp"
#include "renderer/pattern/render_texture.hpp"

namespace povtrace::render {

namespace {
PatternStep step(const Matrix& world_from_pattern, const std::optional<Turbulence>& turbulence) {
  PatternStep s;
  s.transformed = !(world_from_pattern == Matrix::identity());
  if (s.transformed) s.pattern_from_world = world_from_pattern.inverse();
  s.turbulence = turbulence;
  return s;
}

// POV-Ray keeps transforms and warps in one list applied newest first (Transform_Tpattern, Parse_Warp): from the
// outside in, the transforms written last, then the last warp, the transforms before it, and so on.
std::vector<PatternStep> steps_of(const Pigment& p) {
  std::vector<PatternStep> steps;
  const Matrix* outer = &p.world_from_pattern;
  for (auto it = p.warps.rbegin(); it != p.warps.rend(); ++it) {
    steps.push_back(step(*outer, it->turbulence));   // the transforms after this warp, then the warp
    if (it->repeat || it->mapping || it->black_hole) {
      steps.back().turbulence.reset();
      steps.back().repeat = it->repeat;
      steps.back().mapping = it->mapping;
      steps.back().black_hole = it->black_hole;
    }
    outer = &it->before;
  }
  steps.push_back(step(*outer, std::nullopt));
  std::erase_if(steps, [](const PatternStep& s) {
    return !s.transformed && !s.turbulence && !s.repeat && !s.mapping && !s.black_hole;
  });
  return steps;
}

void add_map(RenderPigment& r, const std::vector<MapEntry>& entries, ImageCache* images, bool quick_colours) {
  for (const auto& e : entries) {
    RenderMapEntry m{e.value, e.colour, -1};
    if (e.pigment) {
      m.child = static_cast<int>(r.children.size());
      r.children.push_back(build_render_pigment(*e.pigment, images, quick_colours));
    }
    r.map.push_back(m);
  }
}


}  // namespace

std::shared_ptr<const RenderImageMap> build_render_image(const ImageMap& map, ImageCache* images) {
  auto r = std::make_shared<RenderImageMap>();
  r->image = images ? images->load(map) : load_map_image(map);
  r->mapping = image_mapping(map, *r->image);
  r->opaque = !(map.once || map.has_filter || r->image->transparent);
  return r;
}

void set_generator(RenderPigment& r, NoiseGenerator generator) {
  const int own = r.params.own_noise_generator;
  r.params.noise_generator = own != 0 ? static_cast<NoiseGenerator>(own) : generator;
  r.params.function_noise_generator = static_cast<int>(generator);
  if (r.params.object_description)
    r.params.object = RendererGeometry().prepare(*r.params.object_description, static_cast<int>(generator));
  for (auto& c : r.children) set_generator(c, generator);
  if (r.params.pigment) {   // copies of this pigment share it until one is set
    r.params.pigment = std::make_shared<RenderPigment>(*r.params.pigment);
    set_generator(*r.params.pigment, generator);
  }
}

void set_function_generator(RenderPigment& r, int generator) {
  r.params.function_noise_generator = generator;
  if (r.params.object_description) r.params.object = RendererGeometry().prepare(*r.params.object_description, generator);
  for (auto& c : r.children) set_function_generator(c, generator);
  if (r.params.pigment) {
    r.params.pigment = std::make_shared<RenderPigment>(*r.params.pigment);
    set_function_generator(*r.params.pigment, generator);
  }
}

RenderPigment build_render_pigment(const Pigment& p, ImageCache* images, bool quick_colours) {
  RenderPigment r;
  if (quick_colours && p.quick_colour) {   // POV-Ray's Compute_Pigment returns it before looking at the pattern
    r.colour = *p.quick_colour;
    return r;
  }
  r.pattern = p.pattern;
  r.colour = p.colour;
  if (p.pattern == PatternKind::solid) return r;
  if (p.pattern == PatternKind::uv_mapping) {   // its one pigment, at the hit's uv (no transforms of its own)
    r.children.push_back(build_render_pigment(*p.entries.front().pigment, images, quick_colours));
    return r;
  }
  r.params = PatternParams{p.pattern,    p.gradient, p.brick_size, p.mortar,
                           p.agate_turb, p.crackle,  p.turbulence, NoiseGenerator::range_corrected,
                           p.frequency,  p.phase,    p.function,   p.arms,
                           p.control0,   p.control1, 2,   // both generators set for the scene (set_generator)
                           p.density_file, p.density_interpolation, p.fractal, p.slope, nullptr, p.noise_generator,
                           nullptr, nullptr, nullptr};
  if (p.pattern_pigment)
    r.params.pigment = std::make_shared<RenderPigment>(build_render_pigment(*p.pattern_pigment, images, quick_colours));
  if (p.object) {
    r.params.object_description = p.object;
    r.params.object = RendererGeometry().prepare(*p.object, 2);   // made again for the scene's (set_generator)
  }
  r.wave = WaveParams{p.frequency, p.phase, p.wave, p.exponent};
  r.steps = steps_of(p);
  // marble and wood use the classic turbulence inside the pattern instead (Warp_EPoint skips it for them).
  r.classic_turbulence_warps =
      p.turbulence && p.pattern != PatternKind::marble && p.pattern != PatternKind::wood;
  if (p.pattern == PatternKind::image_map || p.pattern == PatternKind::material_map) {
    r.image = build_render_image(*p.image, images);
  } else {
    if (p.pattern == PatternKind::image_pattern) {
      auto image = std::make_shared<RenderImageMap>(*build_render_image(*p.image, images));
      image->use_alpha = p.image->use_alpha;
      r.params.image = std::move(image);
    }
    add_map(r, p.entries.empty() ? default_colour_map(p) : p.entries, images, quick_colours);
  }
  return r;
}

bool pigment_has_transparency(const RenderPigment& p) {
  auto clear = [](const Colour& c) { return c.f != 0.0 || c.t != 0.0; };
  if (clear(p.colour)) return true;
  if (p.image && !p.image->opaque) return true;
  for (const auto& e : p.map)
    if (e.child < 0 && clear(e.colour)) return true;
  for (const auto& c : p.children)
    if (pigment_has_transparency(c)) return true;
  return false;
}

void use_noise_generator(std::vector<Material>& materials, NoiseGenerator generator) {
  for (auto& m : materials) set_texture_generator(m.texture, generator);
}

}  // namespace povtrace::render
