// Photon map files (photon_file.hpp).
#include "renderer/photons/photon_file.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "renderer/image/atomic_file.hpp"

namespace povtrace::render::photons {

namespace {
constexpr std::size_t kRecord = 20;   // sizeof(Photon) in POV-Ray: 19 bytes of fields, aligned to 4

void to_record(const Photon& p, unsigned char* out) {
  std::memcpy(out, p.position, 12);
  std::memcpy(out + 12, p.rgbe, 4);
  out[16] = p.axis;
  out[17] = static_cast<unsigned char>(p.theta);
  out[18] = static_cast<unsigned char>(p.phi);
  out[19] = 0;
}

Photon from_record(const unsigned char* in) {
  Photon p{};
  std::memcpy(p.position, in, 12);
  std::memcpy(p.rgbe, in + 12, 4);
  p.axis = in[16] <= 2 ? in[16] : 0;
  p.theta = static_cast<std::int8_t>(in[17]);
  p.phi = static_cast<std::int8_t>(in[18]);
  return p;
}
}  // namespace

void save_photon_file(const std::filesystem::path& path, const std::vector<Photon>& photons) {
  try {
    image::write_file_atomically(path, [&](const std::filesystem::path& temp) {
      std::ofstream out(temp, std::ios::binary);
      const std::int32_t count = static_cast<std::int32_t>(photons.size()), media = 0;
      out.write(reinterpret_cast<const char*>(&count), sizeof count);
      unsigned char record[kRecord];
      for (const Photon& p : photons) {
        to_record(p, record);
        out.write(reinterpret_cast<const char*>(record), kRecord);
      }
      out.write(reinterpret_cast<const char*>(&media), sizeof media);
      out.close();
      if (!out) throw std::runtime_error("write failed");
    });
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("cannot save the photon map: ") + e.what());
  }
}

std::vector<Photon> load_photon_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the photon map file '" + path.string() + "'");
  std::int32_t count = 0;
  if (!in.read(reinterpret_cast<char*>(&count), sizeof count) || count < 0)
    throw std::runtime_error("'" + path.string() + "' is not a photon map file (no photon count)");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size < 8 + static_cast<std::uintmax_t>(count) * kRecord)
    throw std::runtime_error("the photon map file '" + path.string() + "' is shorter than its " +
                             std::to_string(count) + " photons");
  std::vector<Photon> photons(static_cast<std::size_t>(count));
  unsigned char record[kRecord];
  for (Photon& p : photons) {
    in.read(reinterpret_cast<char*>(record), kRecord);
    p = from_record(record);
  }
  std::int32_t media = 0;
  if (!in.read(reinterpret_cast<char*>(&media), sizeof media))
    throw std::runtime_error("the photon map file '" + path.string() + "' ends before its media photon count");
  if (media != 0)
    throw std::runtime_error("the photon map file '" + path.string() + "' holds " + std::to_string(media) +
                             " media photons, which povtrace does not render yet");
  return photons;
}

}  // namespace povtrace::render::photons
