// The derived dimensions of an ovus, as POV-Ray 3.7's Parse_Ovus computes them (parse.cpp): the spindle torus that
// joins the two spheres (its tube radius and its centre circle's height and radius) and the heights between which
// the spindle, not a sphere, is the surface. Used by the parser's bounding box and the renderer's intersections.
#pragma once

#include <algorithm>
#include <cmath>

#include "scene/description.hpp"

namespace povtrace {

struct OvusGeometry {
  double connecting_radius = 0;     // the spindle's tube radius
  double vertical_position = 0;     // the height of its centre circle
  double horizontal_position = 0;   // that circle's radius
  double bottom_vertical = 0;       // below this height the bottom sphere is the surface
  double top_vertical = 0;          // above this height the top sphere is
};

// For top_radius < 2 · bottom_radius (the parser makes a sphere of the others).
inline OvusGeometry ovus_geometry(const Ovus& o) {
  const double b = o.bottom_radius, t = o.top_radius;
  OvusGeometry g;
  if (b > t) {
    g.connecting_radius = 2.0 * b;
    g.vertical_position = 2.0 * t - b - (t * t / (2.0 * b));
    g.horizontal_position = std::sqrt(b * b - g.vertical_position * g.vertical_position);
    g.bottom_vertical = -g.vertical_position;
    const double distance = g.connecting_radius - t;
    g.top_vertical = ((b - g.vertical_position) * t / distance) + b;
  } else {
    g.connecting_radius = 2.0 * t;
    g.vertical_position = -2.0 * t + b + (1.5 * t * t / b);
    g.horizontal_position = std::sqrt(t * t - ((g.vertical_position - b) * (g.vertical_position - b)));
    g.top_vertical = 2.0 * b - g.vertical_position;
    const double distance = g.connecting_radius - b;
    g.bottom_vertical = -g.vertical_position * b / distance;
  }
  return g;
}

// Ovus::Compute_BBox: a box as wide as the widest of the spindle and the spheres, from −bottom to bottom + top.
inline double ovus_box_half_width(const Ovus& o) {
  const OvusGeometry g = ovus_geometry(o);
  return std::max({g.connecting_radius - g.horizontal_position, o.bottom_radius, o.top_radius});
}

}  // namespace povtrace
