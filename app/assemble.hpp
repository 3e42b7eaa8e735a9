// `povtrace --assemble OUT [switches] PART…`: merges region renders (+SR +ER +SC +EC, e.g. one per Slurm array
// task or GNU parallel job) into one image. Each part is a full-size EXR or PNG file that records its region
// (image::Image::region); the parts must have one size, must not overlap and must cover the image.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/image/image.hpp"

namespace povtrace::app {

// The parts' regions copied into one image (no region recorded). `names` label the parts in errors. Throws
// std::runtime_error for a part without a region, a size, alpha or encoding mismatch, an overlap or a gap.
image::Image assemble_parts(const std::vector<image::Image>& parts, const std::vector<std::string>& names);

// The whole command: args = OUT, then switches (words starting with + or -, e.g. +FN16, --format=exr32; they
// choose the output encoding as for a render) and part files in any order. Reads the parts, writes OUT
// atomically (nothing is written on an error). Returns the exit status; UsageError for a bad command line.
int run_assemble(const std::vector<std::string>& args);

}  // namespace povtrace::app
