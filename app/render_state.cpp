#include "app/render_state.hpp"

#include <bit>
#include <chrono>
#include <cerrno>
#include <cinttypes>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "renderer/image/atomic_file.hpp"
#include "scene/source.hpp"

namespace povtrace::app {

namespace fs = std::filesystem;
using image::PixelRect;

namespace {

constexpr const char* kMagic = "povtrace render state 1";
constexpr char kTag[4] = {'B', 'L', 'K', '1'};
constexpr std::size_t kRecordHead = sizeof kTag + 4 * sizeof(std::int32_t);

// FNV-1a, 64 bits, for the tails of the word-wise hash below.
std::uint64_t fnv1a(const void* data, std::size_t n, std::uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  return h;
}

// A 64-bit hash of n bytes, 8 bytes a step (records are 16 KB, a scene can be 100 MB of mesh), then mixed: the
// records' checksum and the scene's digest.
std::uint64_t hash_bytes(const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = 0xcbf29ce484222325ull;
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t word = 0;
    std::memcpy(&word, p + i, 8);
    h = (h ^ word) * 0x100000001b3ull;
    h ^= h >> 29;
  }
  h = fnv1a(p + i, n - i, h);
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return h;
}

std::uint64_t record_check(const void* data, std::size_t n) { return hash_bytes(data, n); }

std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string digest(const std::string& text) {
  char hex[48];
  std::snprintf(hex, sizeof hex, "%016" PRIx64 " (%zu bytes)", hash_bytes(text.data(), text.size()), text.size());
  return hex;
}

const char* on_off(bool b) { return b ? "on" : "off"; }

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// The value of `key` in "key=value" lines, or "(none)".
std::string value_of(const std::string& lines, const std::string& key) {
  std::istringstream in(lines);
  for (std::string line; std::getline(in, line);) {
    if (line.compare(0, key.size() + 1, key + "=") == 0) return line.substr(key.size() + 1);
  }
  return "(none)";
}

// The first setting that differs between two settings texts, as "key: a in the state file, b now".
std::string first_difference(const std::string& saved, const std::string& now) {
  std::istringstream a(saved), b(now);
  std::string la, lb;
  while (true) {
    const bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) return "the settings differ";
    if (more_a && more_b && la == lb) continue;
    const std::string& line = more_b ? lb : la;
    const std::string key = line.substr(0, line.find('='));
    return key + ": " + value_of(saved, key) + " in the state file, " + value_of(now, key) + " now";
  }
}

}  // namespace

fs::path state_file_path(const fs::path& output) {
  fs::path p = output;
  p.replace_filename(output.stem().string() + ".povtrace-state");
  return p;
}

std::string state_settings(const RenderOptions& o, const Frame& frame, const std::optional<image::PixelRect>& region,
                           int block_size, const std::string& scene_text, const std::vector<std::string>& files_read) {
  std::ostringstream s;
  s << "byte order=" << (std::endian::native == std::endian::little ? "little" : "big") << "\n";
  s << "scene=" << digest(scene_text) << "\n";
  for (const std::string& name : files_read) {
    std::error_code ec;
    if (name == o.input.string() || !fs::is_regular_file(name, ec)) continue;
    if (fs::equivalent(name, o.input, ec)) continue;
    try {
      s << "file " << name << "=" << digest(read_text_file(name)) << "\n";
    } catch (const std::exception&) {   // gone since the parse: it counts as a change
      s << "file " << name << "=(unreadable)\n";
    }
  }
  if (o.include_header) {
    std::string header;
    try {
      header = read_text_file(*o.include_header);
    } catch (const std::exception&) {   // found along the library path: the parse has read it; its name counts
      header = o.include_header->string();
    }
    s << "Include_Header=" << digest(header) << "\n";
  }
  s << "Width=" << o.width << "\nHeight=" << o.height << "\n";
  if (region) s << "region=" << region->x0 << " " << region->y0 << " " << region->x1 << " " << region->y1 << "\n";
  s << "block size=" << block_size << "\n";
  s << "Antialias=" << on_off(o.antialias) << "\n";
  if (o.antialias) {
    s << "Antialias_Threshold=" << exact(o.antialias_threshold) << "\nAntialias_Depth=" << o.antialias_depth
      << "\nSampling_Method=" << o.sampling_method << "\nJitter=" << on_off(o.jitter)
      << "\nJitter_Amount=" << exact(o.jitter_amount) << "\nAntialias_Gamma=" << exact(o.antialias_gamma) << "\n";
  }
  s << "Output_Alpha=" << on_off(o.output_alpha) << "\nQuality=" << o.quality << "\n";
  s << "lighting=" << (o.lighting == LightingModel::textbook ? "textbook" : "povray") << "\n";
  s << "povray tolerances=" << on_off(o.povray_tolerances) << "\n";
  if (o.language_version) s << "Version=" << exact(*o.language_version) << "\n";
  for (const auto& l : o.library_paths) s << "Library_Path=" << l.string() << "\n";
  for (const auto& [name, value] : o.declares) s << "Declare=" << name << "=" << exact(value) << "\n";
  for (const auto& [name, value] : o.string_declares) s << "Declare=" << name << "=\"" << value << "\"\n";
  const AnimationOptions& a = o.animation;
  if (a.initial_frame) s << "Initial_Frame=" << *a.initial_frame << "\n";
  if (a.final_frame) s << "Final_Frame=" << *a.final_frame << "\n";
  if (a.initial_clock) s << "Initial_Clock=" << exact(*a.initial_clock) << "\n";
  if (a.final_clock) s << "Final_Clock=" << exact(*a.final_clock) << "\n";
  s << "Cyclic_Animation=" << on_off(a.cyclic) << "\n";
  s << "frame=" << frame.number << "\nclock=" << (frame.clock ? exact(*frame.clock) : std::string("none")) << "\n";
  return s.str();
}

SavedState read_state(const fs::path& path, const std::string& settings, int width, int height) {
  SavedState st;
  std::error_code ec;
  if (!fs::exists(path, ec)) return st;
  std::ifstream in(path, std::ios::binary);
  st.status = SavedState::Status::unreadable;
  if (!in) return st;
  std::string magic, count;
  if (!std::getline(in, magic) || magic != kMagic || !std::getline(in, count)) return st;
  std::size_t length = 0;
  try {
    std::size_t used = 0;
    length = std::stoul(count, &used);
    if (used != count.size() || length > (1u << 20)) return st;
  } catch (const std::exception&) {
    return st;
  }
  std::string saved(length, '\0');
  if (!in.read(saved.data(), static_cast<std::streamsize>(length))) return st;
  if (saved != settings) {
    st.status = SavedState::Status::other_settings;
    st.difference = first_difference(saved, settings);
    return st;
  }
  st.status = SavedState::Status::usable;
  st.pixels = image::Image(width, height);
  std::uintmax_t position = static_cast<std::uintmax_t>(in.tellg());
  st.valid_bytes = position;
  std::vector<unsigned char> record;
  while (true) {
    record.resize(kRecordHead);
    if (!in.read(reinterpret_cast<char*>(record.data()), kRecordHead)) break;
    if (std::memcmp(record.data(), kTag, sizeof kTag) != 0) break;
    std::int32_t c[4];
    std::memcpy(c, record.data() + sizeof kTag, sizeof c);
    const image::PixelRect r{c[0], c[1], c[2], c[3]};
    if (r.empty() || r.x0 < 0 || r.y0 < 0 || r.x1 >= width || r.y1 >= height) break;
    const std::size_t floats = static_cast<std::size_t>(r.width()) * r.height() * 4;
    record.resize(kRecordHead + floats * sizeof(float));
    if (!in.read(reinterpret_cast<char*>(record.data() + kRecordHead),
                 static_cast<std::streamsize>(floats * sizeof(float))))
      break;
    std::uint64_t check = 0;
    if (!in.read(reinterpret_cast<char*>(&check), sizeof check)) break;
    if (check != record_check(record.data(), record.size())) break;
    const unsigned char* p = record.data() + kRecordHead;
    const std::size_t row = static_cast<std::size_t>(r.width()) * 4 * sizeof(float);
    for (int y = r.y0; y <= r.y1; ++y, p += row) std::memcpy(st.pixels.pixel(r.x0, y), p, row);
    st.blocks.push_back(r);
    position += record.size() + sizeof check;
    st.valid_bytes = position;
  }
  return st;
}

StateWriter::StateWriter(fs::path path, std::string settings, std::optional<std::uintmax_t> resume_after,
                         double delay_s)
    : path_(std::move(path)), settings_(std::move(settings)), resume_after_(resume_after) {
  open_at_ns_ = now_ns() + static_cast<long long>(delay_s * 1e9);
}

StateWriter::~StateWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

long long StateWriter::blocks_recorded() const {
  std::lock_guard lock(mutex_);
  return recorded_;
}

void StateWriter::open_locked() {
  if (file_ != nullptr || !error_.empty()) return;
  try {
    if (resume_after_) {
      std::error_code ec;
      fs::resize_file(path_, *resume_after_, ec);   // a damaged last record is cut off before appending
      if (ec) throw std::runtime_error(ec.message());
    } else {
      image::write_file_atomically(path_, [&](const fs::path& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << kMagic << "\n" << settings_.size() << "\n" << settings_;
        out.close();
        if (!out) throw std::runtime_error("write failed");
      });
    }
    file_ = std::fopen(path_.c_str(), "ab");
    if (file_ == nullptr) throw std::runtime_error(std::strerror(errno));
    last_flush_ns_ = now_ns();
  } catch (const std::exception& e) {
    error_ = "cannot write the render state file '" + path_.string() + "': " + e.what();
  }
}

void StateWriter::write_locked(const image::Image& image, const PixelRect& r) {
  const std::size_t row = static_cast<std::size_t>(r.width()) * 4 * sizeof(float);
  std::vector<unsigned char> bytes(kRecordHead + row * r.height() + sizeof(std::uint64_t));
  std::memcpy(bytes.data(), kTag, sizeof kTag);
  const std::int32_t c[4] = {r.x0, r.y0, r.x1, r.y1};
  std::memcpy(bytes.data() + sizeof kTag, c, sizeof c);
  unsigned char* p = bytes.data() + kRecordHead;
  for (int y = r.y0; y <= r.y1; ++y, p += row) std::memcpy(p, image.pixel(r.x0, y), row);
  const std::uint64_t check = record_check(bytes.data(), bytes.size() - sizeof check);
  std::memcpy(p, &check, sizeof check);
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size() && error_.empty()) {
    error_ = "cannot write the render state file '" + path_.string() + "': " + std::strerror(errno);
  }
}

void StateWriter::record(const image::Image& image, const PixelRect& r) {
  std::lock_guard lock(mutex_);
  ++recorded_;
  const long long t = now_ns();
  if (file_ == nullptr) {
    pending_.push_back(r);
    if (t < open_at_ns_ || !error_.empty()) return;
    open_locked();
    if (file_ == nullptr) return;
    for (const PixelRect& b : pending_) write_locked(image, b);
    pending_.clear();
  } else {
    write_locked(image, r);
  }
  if (t - last_flush_ns_ >= 250'000'000) {
    std::fflush(file_);
    last_flush_ns_ = t;
  }
}

void StateWriter::finish_interrupted(const image::Image& image) {
  std::lock_guard lock(mutex_);
  open_locked();
  if (file_ != nullptr) {
    for (const PixelRect& b : pending_) write_locked(image, b);
    pending_.clear();
    if (std::fclose(file_) != 0 && error_.empty()) error_ = "cannot write the render state file '" + path_.string() + "'";
    file_ = nullptr;
  }
  if (!error_.empty()) throw std::runtime_error(error_);
}

void StateWriter::discard() {
  std::lock_guard lock(mutex_);
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
  pending_.clear();
  std::error_code ignored;
  fs::remove(path_, ignored);
}

}  // namespace povtrace::app
