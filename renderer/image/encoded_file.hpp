// Whole files as bytes: the writers encode a file in memory (so that it can go to a file or to standard output
// all at once) and the simple readers parse one from memory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace povtrace::image {

// Creates or truncates `file` and writes `bytes`. Throws ImageError (without the path).
void write_bytes(const std::filesystem::path& file, const std::string& bytes);

// The whole of `file`. Throws ImageError (without the path).
std::string read_bytes(const std::filesystem::path& file);

// Little-endian integers, as TGA and BMP store them.
inline void put_le16(std::string& out, unsigned value) {
  out.push_back(static_cast<char>(value & 0xff));
  out.push_back(static_cast<char>((value >> 8) & 0xff));
}
inline void put_le32(std::string& out, std::uint32_t value) {
  put_le16(out, value & 0xffff);
  put_le16(out, value >> 16);
}
inline unsigned get_le16(const std::string& in, std::size_t pos) {
  return static_cast<unsigned char>(in[pos]) | (unsigned(static_cast<unsigned char>(in[pos + 1])) << 8);
}
inline std::uint32_t get_le32(const std::string& in, std::size_t pos) {
  return get_le16(in, pos) | (std::uint32_t(get_le16(in, pos + 2)) << 16);
}

}  // namespace povtrace::image
