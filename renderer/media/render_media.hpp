// Media ready for sampling (POV-Ray 3.7's Media after PostProcess, interior/media.cpp): coefficients, the sampling
// settings, the densities as render pigments in POV-Ray's evaluation order, and the confidence thresholds of the
// extra samples methods 1 and 2 take.
#pragma once

#include <memory>
#include <vector>

#include "renderer/render_scene.hpp"

namespace povtrace::render {

class ImageCache;

struct RenderMedia {
  int method = 3;
  int intervals = 1;
  int min_samples = 10, max_samples = 10;
  double ratio = 0.9;
  double jitter = 0.0;
  double aa_threshold = 0.1;
  int aa_level = 3;
  Rgb absorption, emission, scattering;
  Rgb extinction;   // absorption + extinction factor · scattering (POV-Ray's Extinction)
  int scattering_type = 1;
  double eccentricity = 0.0;
  bool use_extinction = false, use_scattering = false;
  // No density block: the coefficients hold everywhere (POV-Ray's is_constant).
  bool constant = true;
  // No density, or the last one written is a plain colour: POV-Ray's test for its constant shadow-ray shortcut
  // looks at the head of its density list only.
  bool plain_for_shadows = true;
  // Multiplied together; POV-Ray keeps them last written first and multiplies in that order.
  std::vector<RenderPigment> densities;
  // Variance below which a method 1 or 2 interval with n samples takes no more (index n − 1).
  std::vector<double> sample_threshold;
};

// The media of one interior, or the atmosphere's.
struct MediaSet {
  std::vector<RenderMedia> media;
};

RenderMedia build_render_media(const Media& m, ImageCache* images, bool quick_colours);

// x with P(X > x) = q for X chi-square distributed with `dof` (a whole number) degrees of freedom: the inverse of
// the complemented chi-square distribution as POV-Ray's chdtri computes it, 0 < q < 1. For odd dof below 26
// POV-Ray's log-gamma is off, and so are its values (7.04 becomes 7.10 for dof 13 at q 0.9): reproduced, since
// media and focal blur stop sampling on these thresholds.
double inverse_chi_square_complement(double dof, double q);

}  // namespace povtrace::render
