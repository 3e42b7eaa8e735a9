// Photon map files as POV-Ray 3.7 writes them (photons { save_file "F" } and load_file, PhotonSortingTask::save and
// load; docs/issue20-photons.md §4): a native-endian 32-bit count, that many 20-byte photons in the built tree's
// order (position as three floats, the RGBE colour, the tree's axis byte, theta, phi, one byte of padding), then the
// count of media photons (always 0 here). Files POV-Ray saved on a little-endian machine load here and the reverse.
#pragma once

#include <filesystem>
#include <vector>

#include "renderer/photons/photon_map.hpp"

namespace povtrace::render::photons {

// Writes the map's photons to `path` atomically; throws std::runtime_error on failure (nothing is left behind).
void save_photon_file(const std::filesystem::path& path, const std::vector<Photon>& photons);
// Reads a file written by save_photon_file or by POV-Ray; throws std::runtime_error saying what is wrong. A file with
// media photons is refused (povtrace has no media photon map).
std::vector<Photon> load_photon_file(const std::filesystem::path& path);

}  // namespace povtrace::render::photons
