// The photon pass (photon_shoot.hpp). Facts from POV-Ray 3.7's lighting/photonshootingtask.cpp, photonstrategytask.cpp,
// photonestimationtask.cpp and photons.cpp (ShootingDirection, LightTargetCombo); the code is our own.
#include "renderer/photons/photon_shoot.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include "renderer/csg_build.hpp"
#include "renderer/located_error.hpp"
#include "renderer/photons/photon_file.hpp"
#include "renderer/shading_helpers.hpp"
#include "renderer/shapes/shape_registry.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render::photons {

namespace {
void collect_groups(const Object& o, std::uint32_t top, std::uint32_t group, PhotonGroups& out) {
  if (group == kNoPhotonTarget && o.photons.target > 0) {
    group = static_cast<std::uint32_t>(out.targets.size());
    out.targets.push_back(&o);
    out.top_level.push_back(top);
  }
  if (group != kNoPhotonTarget) out.group_of.emplace(&o, group);
  if (const auto* csg = std::get_if<Csg>(&o.shape))
    for (const Object& c : csg->children) collect_groups(c, top, group, out);
}

// A scene-level object as POV-Ray lists it: a union it splits (splits_into_children) is its children, each one a
// scene-level object (and a target of its own when the union is one, since the flag reaches them).
void collect_scene_object(const Object& o, std::uint32_t top, PhotonGroups& out) {
  if (splits_into_children(o)) {
    for (const Object& c : std::get<Csg>(o.shape).children) collect_scene_object(c, top, out);
    return;
  }
  collect_groups(o, top, kNoPhotonTarget, out);
}

// The light's direction as POV-Ray keeps it (from the light toward point_at), for parallel, spot and cylinder lights.
Vec3 light_direction(const RenderLight& l) {
  const Vec3 axis = l.light.point_at - l.light.location;
  return length(axis) > 0 ? normalize(axis) : Vec3{0, 0, 0};
}

// Rotation of `v` by `angle` about the unit axis `k`.
Vec3 rotate(Vec3 v, Vec3 k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0 - c));
}

// POV-Ray's ShootingDirection: the target's bounding sphere seen from `origin`.
struct Frame {
  Vec3 centre;
  double radius = 0;
  Vec3 toward;          // unit, origin → centre
  double distance = 0;
  Vec3 left;            // unit, perpendicular to `toward` (parallel lights: to the light's direction)
};

Frame frame_from(const PhotonTarget& t, Vec3 origin, const RenderLight& l) {
  Frame f;
  f.centre = t.centre;
  f.radius = t.radius;
  const Vec3 v = f.centre - origin;
  f.distance = length(v);
  if (f.distance < tolerance::epsilon) {   // the light at the centre: any frame will do
    f.toward = {0, 0, 1};
    f.left = {0, 1, 0};
    return f;
  }
  f.toward = v / f.distance;
  const Vec3 up = std::fabs(std::fabs(f.toward.z) - 1.0) < 0.1 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  f.left = normalize(cross(l.light.parallel ? light_direction(l) : f.toward, up));
  return f;
}

// One light and one target (POV-Ray's LightTargetCombo).
struct Unit {
  const RenderLight* light;
  const PhotonTarget* target;
  std::uint32_t group;   // its index in RenderScene::photon_targets
  Frame frame;
  double spread = 0, dtheta = 0, max_theta = 0;
};

bool shoots(const Light& light, const ObjectPhotons& target) {
  const auto on = [](const std::optional<bool>& a, const std::optional<bool>& b) { return a == true || b == true; };
  const auto off = [](const std::optional<bool>& a, const std::optional<bool>& b) { return a == false || b == false; };
  return (on(light.photon_refraction, target.refraction) && !off(light.photon_refraction, target.refraction)) ||
         (on(light.photon_reflection, target.reflection) && !off(light.photon_reflection, target.reflection));
}

// POV-Ray's PhotonEstimationTask: roughly how many photons a spacing gives, to derive the spacing from `count`.
double estimated_photons(const RenderScene& scene, double spacing) {
  double total = 0;
  for (const RenderLight& l : scene.lights) {
    if (l.light.shadowless || l.light.group >= 0) continue;   // a light_group's lights shoot no photons
    for (const PhotonTarget& t : scene.photon_targets) {
      if (!shoots(l.light, t.flags) || !t.bounded) continue;
      const Light& light = l.light;
      const auto go = [](const std::optional<bool>& a, const std::optional<bool>& b) {
        return (a == true || b == true) && !(a == false || b == false);
      };
      const bool refracts = go(light.photon_refraction, t.flags.refraction);
      const bool reflects = go(light.photon_reflection, t.flags.reflection);
      const Frame f = frame_from(t, light.location, l);
      double x = f.radius / (t.flags.target * spacing);
      x = x * x * M_PI;
      if (refracts && reflects) x *= 1.5;
      if (t.flags.collect && refracts) x *= reflects ? 3 : 2;
      total += x * 0.5;
    }
  }
  return total;
}

// Spot and cylinder lights' attenuation of a photon leaving in `direction` (POV-Ray's computeAttenuation);
// `off_axis`: a cylinder light's distance of the photon's start from its axis.
double attenuation(const RenderLight& l, Vec3 direction, double off_axis) {
  const Light& light = l.light;
  if (light.cylinder) {
    if (!(dot(direction, l.spot_axis) > 0) || !(off_axis < light.falloff)) return 0.0;
    const double d = 1.0 - off_axis / light.falloff;
    double a = std::pow(d, light.tightness);
    if (light.radius > 0 && off_axis > light.radius) a *= smoothstep(0.0, 1.0 - light.radius / light.falloff, d);
    return a;
  }
  if (light.spotlight) {
    const double c = dot(direction, l.spot_axis);
    if (!(c > 0)) return 0.0;
    double a = std::pow(c, light.tightness);
    if (l.cos_radius > 0) a *= smoothstep(l.cos_falloff, l.cos_radius, c);
    return a;
  }
  return 1.0;
}

// POV-Ray's photon pass draws its jitter from a table of 32768 numbers in [0, 1): the first outputs of a Mersenne
// twister with its standard seed, each divided by 2^32 (RandomDoubleSequence over boost's mt19937). A shooting thread
// starts at the table's start and takes its numbers in turn; the one-thread order (+WT1) is every unit's rings one
// after the other. Each ring here knows where in the table it starts, so rings can run in parallel and the photons
// are POV-Ray's +WT1 photons whatever the thread count.
class PhotonRandom {
 public:
  static constexpr std::size_t kSize = 32768;
  explicit PhotonRandom(std::size_t index) : index_(index % kSize) {}
  double operator()() {   // POV-Ray's Generator: step first, then read
    index_ = (index_ + 1) % kSize;
    return table()[index_];
  }
  std::size_t index() const { return index_; }

 private:
  static const std::vector<double>& table() {
    static const std::vector<double> values = [] {
      std::mt19937 twister;   // default seed 5489, as boost's
      std::vector<double> v(kSize);
      for (double& x : v) x = static_cast<double>(twister()) / 4294967296.0;
      return v;
    }();
    return values;
  }
  std::size_t index_;
};

// The most photons one light may shoot at one target: far more than any scene needs (POV-Ray's sample scenes shoot
// at most a few hundred thousand), few enough to be shot in minutes.
constexpr double kMaxPhotonsShot = 1e8;

// The angle between photons along a ring at `theta` (POV-Ray's dphi).
double ring_step(const Unit& u, double theta) {
  if (theta < tolerance::epsilon) return 2 * M_PI;
  return u.light->light.parallel ? u.dtheta / theta : u.dtheta / std::sin(theta);
}

// projected_through (POV-Ray's photon shooting task): a photon that misses the object is not shot; one that meets it
// starts beyond its last crossing, each crossing passed by EPSILON (1e-10), the distance added to its depth.
bool leave_through(const PreparedObject& object, Vec3& origin, Vec3 dir, double& depth) {
  std::optional<TracedHit> hit = object.trace(origin, dir);
  if (!hit) return false;
  for (int crossings = 0; hit && crossings < 1000000; ++crossings) {
    const double step = dot(hit->point - origin, dir) + tolerance::epsilon;
    origin += dir * step;
    depth += step;
    hit = object.trace(origin, dir);
  }
  return true;
}

struct RingResult {
  std::vector<Photon> photons;
  bool hit = false;
};

// One ring of photons at angle `theta` from the direction to the target (radius `theta` for parallel lights).
void shoot_ring(Tracer& tracer, const RenderScene& scene, const Unit& u, double theta, std::size_t random_start,
                double jitter, const std::vector<InteriorRef>& light_interiors, RingResult& out) {
  PhotonRandom uniform(random_start);
  const RenderLight& l = *u.light;
  const Light& light = l.light;
  const bool parallel = light.parallel;
  const bool area = light.area && light.photon_area_light && !parallel;
  const int xs = area ? light.size1 : 1, ys = area ? light.size2 : 1;
  const Vec3 direction = light_direction(l);
  const double dphi = ring_step(u, theta);
  const double min_phi = -M_PI + dphi * uniform() * 0.5;
  const double max_phi = M_PI - dphi / 2 + (min_phi + M_PI);
  Tracer::PhotonShot shot;
  shot.light = &l;
  shot.target = u.group;
  shot.spread = u.spread;
  shot.out = &out.photons;
  for (double phi = min_phi; phi < max_phi; phi += dphi) {
    const double jit_phi = phi + dphi * (uniform() - 0.5) * jitter;
    const double jit_theta = theta + u.dtheta * (uniform() - 0.5) * jitter;
    for (int ax = 0; ax < xs; ++ax) {
      for (int ay = 0; ay < ys; ++ay) {
        Vec3 origin = light.location;
        Frame f = u.frame;
        if (area) {
          if (light.size1 > 1) origin += light.axis1 * (ax / static_cast<double>(light.size1 - 1) - 0.5);
          if (light.size2 > 1) origin += light.axis2 * (ay / static_cast<double>(light.size2 - 1) - 0.5);
          f = frame_from(*u.target, origin, l);
        }
        Vec3 dir;
        double off_axis = 0;
        if (parallel) {
          dir = direction;
          origin = f.centre - dir * (dot(dir, f.toward) * f.distance) + rotate(f.left * jit_theta, direction, jit_phi);
          off_axis = length(origin - light.location);
        } else {
          const Vec3 v = f.left * -std::sin(jit_theta) + f.toward * std::cos(jit_theta);
          dir = normalize(rotate(v, f.toward, jit_phi));
        }
        const double a = attenuation(l, dir, off_axis) / (xs * ys);
        if (a < 0.00001) continue;
        double depth = 0;
        if (l.projected_through && !leave_through(*l.projected_through, origin, dir, depth)) continue;
        const bool moved_origin = parallel || area || l.projected_through;
        const std::vector<InteriorRef> moved = moved_origin ? scene.containing_interiors(origin)
                                                            : std::vector<InteriorRef>{};
        tracer.shoot_photon(Ray{origin, dir}, l.colour * a, moved_origin ? moved : light_interiors, shot, depth);
      }
    }
  }
  out.hit = shot.hit_target;
}

// The rings of one unit, in parallel batches, each starting at its place in the random table (found by running
// the rings' loops without tracing); the autostop rule (after a ring that missed the target, past the autostop
// fraction of the cone, once some ring hit it) is applied in ring order. Returns where the table stands after the
// unit, as POV-Ray's generator would.
std::size_t shoot_unit(const RenderScene& scene, const Unit& u, const PhotonSettings& settings, int threads,
                       std::vector<std::unique_ptr<Tracer>>& tracers, std::size_t random_index,
                       std::vector<Photon>& photons) {
  // A spacing far too fine for the target would shoot without end: refused before any ring is laid out.
  const Light& light = u.light->light;
  const double cells = light.area && light.photon_area_light && !light.parallel ? double(light.size1) * light.size2 : 1;
  const double ring_count = u.max_theta / u.dtheta + 1;
  const double per_ring = light.parallel ? 2 * M_PI * ring_count : 2 * M_PI * std::min(1.0, std::sin(u.max_theta) + u.dtheta) / u.dtheta + 1;
  if (ring_count * per_ring * cells > kMaxPhotonsShot) {
    char message[256];
    std::snprintf(message, sizeof message,
                  "photons: spacing %g would shoot up to %.3g photons at one target; povtrace shoots at most %.3g per "
                  "light and target (raise spacing or lower count)",
                  settings.spacing, ring_count * per_ring * cells, kMaxPhotonsShot);
    fail_at_scene(settings.loc, message);
  }
  std::vector<double> thetas;
  std::vector<std::size_t> starts;   // table index before each ring, and after the last
  for (double theta = 0; theta < u.max_theta; theta += u.dtheta) {
    thetas.push_back(theta);
    starts.push_back(random_index);
    PhotonRandom r(random_index);
    const double dphi = ring_step(u, theta);
    const double min_phi = -M_PI + dphi * r() * 0.5;
    const double max_phi = M_PI - dphi / 2 + (min_phi + M_PI);
    std::size_t draws = 1;
    for (double phi = min_phi; phi < max_phi; phi += dphi) draws += 2;
    random_index = (random_index + draws) % PhotonRandom::kSize;
  }
  starts.push_back(random_index);
  const std::vector<InteriorRef> light_interiors = scene.containing_interiors(u.light->light.location);
  bool hit_once = false;
  const std::size_t batch = static_cast<std::size_t>(threads) * 8;
  for (std::size_t start = 0; start < thetas.size(); start += batch) {
    const std::size_t end = std::min(thetas.size(), start + batch);
    std::vector<RingResult> rings(end - start);
    std::atomic<std::size_t> next{start};
    auto work = [&](int id) {
      for (std::size_t r = next++; r < end; r = next++)
        shoot_ring(*tracers[static_cast<std::size_t>(id)], scene, u, thetas[r], starts[r], settings.jitter,
                   light_interiors, rings[r - start]);
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work, i);
    work(0);
    for (auto& t : pool) t.join();
    for (std::size_t r = start; r < end; ++r) {
      RingResult& ring = rings[r - start];
      photons.insert(photons.end(), ring.photons.begin(), ring.photons.end());
      if (ring.hit) hit_once = true;
      if (hit_once && !ring.hit && thetas[r] > settings.autostop * u.max_theta) return starts[r + 1];
    }
  }
  return starts.back();
}
}  // namespace

PhotonGroups find_photon_groups(const SceneDescription& scene) {
  PhotonGroups groups;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    collect_scene_object(scene.objects[i], static_cast<std::uint32_t>(i), groups);
  return groups;
}

std::vector<PhotonTarget> bound_photon_targets(const PhotonGroups& groups, const Accelerator& accelerator,
                                               const BuildContext& context) {
  std::vector<PhotonTarget> targets(groups.targets.size());
  for (std::size_t g = 0; g < targets.size(); ++g) {
    const Object& o = *groups.targets[g];
    PhotonTarget& t = targets[g];
    t.flags = o.photons;
    Vec3 lo, hi;
    if (o.placed_box && o.placed_box->known) {   // POV-Ray's BBox: lower corner and lengths in float
      const ExtentBox& b = o.placed_box->box;
      lo = b.lo();
      t.centre = lo + Vec3{b.lengths[0] / 2.0, b.lengths[1] / 2.0, b.lengths[2] / 2.0};
      hi = b.hi();
    } else {
      Bounds box;
      std::vector<Primitive> own;
      if (!std::holds_alternative<Csg>(o.shape) && shapes::append_shape(o.shape, o.world_from_object, context, own))
        box = world_bounds(own.back());
      else
        for (const Primitive& p : accelerator.primitives())
          if (p.object == groups.top_level[g]) box.extend(world_bounds(p));
      if (box.empty()) continue;
      lo = box.lo;
      hi = box.hi;
      t.centre = box.centre();
    }
    t.radius = length(t.centre - lo);
    // POV-Ray's huge box (an unbounded target) is not shot at: its photons would be spread over the whole scene.
    t.bounded = std::isfinite(t.radius) && length(hi - lo) < 1e9;
  }
  return targets;
}

std::shared_ptr<const PhotonMap> shoot_photons(const RenderScene& scene, int quality, int threads,
                                               std::vector<std::string>& warnings) {
  PhotonSettings settings = *scene.photon_settings;
  if (!settings.load_file.empty()) {   // POV-Ray shoots nothing then: the file holds the built tree
    std::vector<Photon> loaded;
    try {
      loaded = load_photon_file(settings.load_file);
    } catch (const std::exception& e) {
      fail_at_scene(settings.file_loc, e.what());
    }
    if (loaded.empty()) return nullptr;
    return std::make_shared<const PhotonMap>(std::move(loaded), settings, true);
  }
  if (settings.count > 0) {   // the spacing that gives about `count` photons
    const double estimate = estimated_photons(scene, settings.spacing);
    if (estimate > 0) settings.spacing *= std::sqrt(estimate / settings.count);
  }
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  threads = std::max(1, threads > 0 ? threads : static_cast<int>(hw));
  std::vector<std::unique_ptr<Tracer>> tracers;
  for (int i = 0; i < threads; ++i)
    tracers.push_back(std::make_unique<Tracer>(scene, ShadingModel::povray, Quality::at_level(quality)));
  std::vector<Photon> photons;
  for (const PhotonTarget& t : scene.photon_targets)
    if (!t.bounded) {
      warnings.push_back("photons: a photon target without a finite bounding box (an infinite object) is not shot at");
      break;
    }
  std::size_t random_index = 0;   // POV-Ray's one shooting thread: one generator for every unit
  bool warned_cylinder = false;
  for (const RenderLight& l : scene.lights) {
    if (l.light.shadowless || l.light.group >= 0) continue;   // fill lights and a light_group's lights shoot none
    if (l.light.cylinder && !l.light.parallel && !warned_cylinder) {
      warnings.push_back("photons: cylinder lights should be parallel when used with photons (as POV-Ray warns)");
      warned_cylinder = true;
    }
    for (const PhotonTarget& t : scene.photon_targets) {
      if (!shoots(l.light, t.flags) || !t.bounded) continue;
      Unit u{&l, &t, static_cast<std::uint32_t>(&t - scene.photon_targets.data()), frame_from(t, l.light.location, l)};
      u.spread = t.flags.target * settings.spacing;
      if (!l.light.parallel) u.spread /= u.frame.distance;
      if (l.light.area && l.light.photon_area_light) u.spread *= std::sqrt(static_cast<double>(l.light.size1 * l.light.size2));
      if (!(u.spread > 0) || !std::isfinite(u.spread)) continue;
      u.dtheta = l.light.parallel ? u.spread : std::atan(u.spread);
      if (l.light.parallel) u.max_theta = u.frame.radius;
      else if (u.frame.distance >= u.frame.radius) u.max_theta = std::asin(u.frame.radius / u.frame.distance);
      else u.max_theta = M_PI;
      random_index = shoot_unit(scene, u, settings, threads, tracers, random_index, photons);
    }
  }
  if (photons.empty()) {
    if (!settings.save_file.empty())
      warnings.push_back("photons: no photon was stored, so '" + settings.save_file + "' is not written");
    return nullptr;
  }
  auto map = std::make_shared<const PhotonMap>(std::move(photons), settings);
  if (!settings.save_file.empty()) {
    try {
      save_photon_file(settings.save_file, map->photons());
    } catch (const std::exception& e) {
      fail_at_scene(settings.file_loc, e.what());
    }
  }
  return map;
}

}  // namespace povtrace::render::photons
