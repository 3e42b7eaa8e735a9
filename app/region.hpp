// +SR +ER +SC +EC resolved against the image size with POV-Ray 3.7's rules (docs/issue18-plan.md §3).
#pragma once

#include <optional>

#include "app/options.hpp"
#include "renderer/image/image.hpp"

namespace povtrace::app {

// The pixel rectangle the region options select in a width × height image, or none when no region option is
// given. A start value in [0,1) is a fraction (pixel int(size × v)), otherwise a 1-based pixel (int(v) − 1); an
// end value in [0,1] is a fraction (int(size × v) − 1), otherwise a 1-based pixel, so +ER1 is the last row.
// Unset values are the image's edges. A start or end outside the image, or an end before its start, is a
// UsageError ("invalid start column or row …", POV-Ray's wording).
std::optional<image::PixelRect> resolve_region(const RegionOptions& region, int width, int height);

}  // namespace povtrace::app
