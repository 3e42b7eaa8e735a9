// Scale invariance (issue 7). POV-Ray's tolerances are absolute (1e-4 minimum hit depth, 1e-3 shadow tolerance,
// 1e7 maximum distance, and the shapes' own epsilons), so a scene built at a very small or very large scale loses
// shadows, surfaces or its horizon. povtrace renders such a scene as its twin at an ordinary scale: the whole
// scene is scaled by a power of two (exact in floating point) that brings the size of its objects into the range
// where those tolerances are harmless, when all of them lie outside it. The objects decide, not the scene's
// extent: a sky sphere of radius 1e5 around ordinary objects leaves the scene as it is (POV-Ray renders it well;
// shrinking the scene would shrink the objects down to the tolerances). Every ordinary scene is left as it is,
// so they still match POV-Ray pixel for pixel; `--povray-tolerances` turns the rescaling off (and reproduces
// POV-Ray's own renders of such scenes, tests/stress/povray_tolerances.cmake).
#pragma once

#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

// The sizes of the scene's objects: the smallest, the (lower) median and the largest diagonal of the finite
// primitives' bounds (planes and other unbounded shapes left out; a mesh or a CSG node counts once); all 0 when
// there is none.
struct ObjectSizes {
  double smallest = 0, median = 0, largest = 0;
  // Some ray may run into POV-Ray's MAX_DISTANCE (1e7): the scene has an unbounded object, or a finite one farther
  // than half of it from the camera (rays between two objects then cross more than it).
  bool reaches_max_distance = true;
};
ObjectSizes object_sizes(const std::vector<Primitive>& primitives);
// The same, deciding reaches_max_distance from the camera's location.
ObjectSizes object_sizes(const std::vector<Primitive>& primitives, Vec3 camera);

// The factor (a power of two) that brings the median object to about 2 units when every object is below 0.05, or
// every one above 1e4 and some ray may reach MAX_DISTANCE; otherwise 1. Huge objects alone are no reason: POV-Ray's
// tolerances are small against them, and shrinking the scene would bring its small gaps (a shell 1 unit above a
// planet of radius 5e4, advanced/mediasky.pov) down to those tolerances. A scene mixing scales (a sky sphere of radius 1e5 around ordinary objects, or
// around tiny ones) is left as written, as POV-Ray renders it: no single factor would help all its objects.
double normalizing_scale(const ObjectSizes& sizes);

// The scene with every length multiplied by k: objects, lights, camera, fog, and the distances interiors and
// lights carry (fade_distance, cylinder light radius and falloff).
SceneDescription scaled_scene(const SceneDescription& scene, double k);

// The scene as POV-Ray holds it (for --povray-tolerances): every sphere that only translations, rotations and
// uniform scales reached (Sphere::ellipsoid false) has them folded into its centre and radius, so its EPSILON
// grazing test and DEPTH_TOLERANCE act on world lengths, as POV-Ray's do. Ellipsoids keep their transform.
SceneDescription with_world_space_spheres(const SceneDescription& scene);

}  // namespace povtrace::render
