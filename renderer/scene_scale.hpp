// Scale invariance (issue 7). POV-Ray's tolerances are absolute (1e-4 minimum hit depth, 1e-3 shadow tolerance,
// 1e7 maximum distance, and the shapes' own epsilons), so a scene built at a very small or very large scale loses
// shadows, surfaces or its horizon. povtrace renders such a scene as its twin at an ordinary scale: the whole
// scene is scaled by a power of two (exact in floating point) that brings its size into the range where those
// tolerances are harmless. Scenes already in that range — every ordinary scene — are left exactly as they are,
// so they still match POV-Ray pixel for pixel; `--povray-tolerances` turns the rescaling off (and reproduces
// POV-Ray's own renders of such scenes, tests/stress/povray_tolerances.cmake).
#pragma once

#include <vector>

#include "parser/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

// The scene's size: the diagonal of the box around the camera location and every finite primitive (planes and
// other unbounded shapes left out). Lights are left out too: they are often placed far away on purpose.
double scene_size(const std::vector<Primitive>& primitives, Vec3 camera_location);

// The factor (a power of two) that brings `size` into the ordinary range, or 1 when it is already there (or is
// zero or not finite).
double normalizing_scale(double size);

// The scene with every length multiplied by k: objects, lights, camera, fog, and the distances interiors and
// lights carry (fade_distance, cylinder light radius and falloff).
SceneDescription scaled_scene(const SceneDescription& scene, double k);

// The scene as POV-Ray holds it (for --povray-tolerances): every sphere that only translations, rotations and
// uniform scales reached (Sphere::ellipsoid false) has them folded into its centre and radius, so its EPSILON
// grazing test and DEPTH_TOLERANCE act on world lengths, as POV-Ray's do. Ellipsoids keep their transform.
SceneDescription with_world_space_spheres(const SceneDescription& scene);

}  // namespace povtrace::render
