// The photon pass (POV-Ray 3.7's PhotonEstimationTask, PhotonStrategyTask and PhotonShootingTask;
// docs/issue20-photons.md §2): every light that is not a fill light shoots photons at every photon target's bounding
// sphere, in rings of equal angular spacing around the direction to its centre, jittered; the map is built from
// all the photons stored. Deterministic: each ring draws its own random sequence, rings run in parallel and the
// autostop rule is applied in ring order afterwards, so any thread count gives the same map.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "renderer/photons/photon_map.hpp"
#include "renderer/build_context.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::render::photons {

// The scene's photon targets and which objects are in each one's tree (for their materials).
struct PhotonGroups {
  std::vector<const Object*> targets;      // the target objects, in scene order
  std::vector<std::uint32_t> top_level;    // the top-level object index (Primitive::object) of each
  std::unordered_map<const Object*, std::uint32_t> group_of;   // every object in a target's tree → its target
};
PhotonGroups find_photon_groups(const SceneDescription& scene);
// Each target's bounding sphere: from the box the parser placed it with (POV-Ray's BBox), else from its shape's or
// its top-level object's primitives.
std::vector<PhotonTarget> bound_photon_targets(const PhotonGroups& groups, const Accelerator& accelerator,
                                               const BuildContext& context);

// Shoots the photons of `scene` (photon_settings and photon_targets set) with `threads` threads (0: all) at
// quality level `quality`; null when no photon was stored. Notes for the user go to `warnings`.
std::shared_ptr<const PhotonMap> shoot_photons(const RenderScene& scene, int quality, int threads,
                                               std::vector<std::string>& warnings);

}  // namespace povtrace::render::photons
