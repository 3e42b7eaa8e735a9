// A tiny TrueType file written byte by byte for the font tests: a table directory plus the tables the text shape
// reads, so that composite glyphs, character maps and damaged files can be tested without shipping fonts.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace povtrace::test {

using FontBytes = std::vector<std::uint8_t>;

inline void put16(FontBytes& b, int v) {
  b.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
  b.push_back(static_cast<std::uint8_t>(v & 0xFF));
}
inline void put32(FontBytes& b, std::uint32_t v) {
  put16(b, static_cast<int>(v >> 16));
  put16(b, static_cast<int>(v & 0xFFFF));
}

// The file: the offset table and directory, then each table (4-byte aligned) in tag order.
inline FontBytes assemble_font(const std::map<std::string, FontBytes>& tables) {
  FontBytes out;
  put32(out, 0x00010000);
  put16(out, static_cast<int>(tables.size()));
  put16(out, 0);
  put16(out, 0);
  put16(out, 0);
  std::uint32_t offset = 12 + 16 * static_cast<std::uint32_t>(tables.size());
  for (const auto& [tag, data] : tables) {
    for (char c : tag) out.push_back(static_cast<std::uint8_t>(c));
    put32(out, 0);
    put32(out, offset);
    put32(out, static_cast<std::uint32_t>(data.size()));
    offset += static_cast<std::uint32_t>((data.size() + 3) / 4 * 4);
  }
  for (const auto& entry : tables) {
    FontBytes data = entry.second;
    while (data.size() % 4) data.push_back(0);
    out.insert(out.end(), data.begin(), data.end());
  }
  return out;
}

inline FontBytes head_table(int units_per_em) {
  FontBytes b(54, 0);
  const std::uint32_t magic = 0x5F0F3CF5;
  for (int i = 0; i < 4; ++i) b[12 + i] = static_cast<std::uint8_t>(magic >> (24 - 8 * i));
  b[18] = static_cast<std::uint8_t>(units_per_em >> 8);
  b[19] = static_cast<std::uint8_t>(units_per_em & 0xFF);
  b[51] = 1;   // indexToLocFormat 1: 32-bit loca entries
  return b;
}

// A simple glyph: contours of (x, y, on-curve) points in font units, written with 16-bit deltas.
struct Point {
  int x, y;
  bool on;
};
inline FontBytes simple_glyph(const std::vector<std::vector<Point>>& contours, int x_min, int y_min, int x_max,
                              int y_max) {
  FontBytes b;
  put16(b, static_cast<int>(contours.size()));
  for (int v : {x_min, y_min, x_max, y_max}) put16(b, v);
  int end = -1;
  for (const auto& c : contours) put16(b, end += static_cast<int>(c.size()));
  put16(b, 0);   // no instructions
  for (const auto& c : contours)
    for (const Point& p : c) b.push_back(p.on ? 1 : 0);
  int last = 0;
  for (const auto& c : contours)
    for (const Point& p : c) put16(b, p.x - last), last = p.x;
  last = 0;
  for (const auto& c : contours)
    for (const Point& p : c) put16(b, p.y - last), last = p.y;
  return b;
}

// A font of `glyphs` (glyf entries) with a Macintosh format-0 character map from `char_to_glyph`, metrics
// (advance, lsb) per glyph, and optional format-0 kern pairs (left, right, value).
struct FontSpec {
  int units_per_em = 1000;
  std::vector<FontBytes> glyphs;
  std::map<int, int> char_to_glyph;
  std::vector<std::pair<int, int>> metrics;
  std::vector<std::array<int, 3>> kern_pairs;
};

inline FontBytes build_font(const FontSpec& s) {
  std::map<std::string, FontBytes> t;
  t["head"] = head_table(s.units_per_em);
  FontBytes maxp;
  put32(maxp, 0x00005000);
  put16(maxp, static_cast<int>(s.glyphs.size()));
  t["maxp"] = maxp;
  FontBytes hhea(34, 0);
  put16(hhea, static_cast<int>(s.metrics.size()));
  t["hhea"] = hhea;
  FontBytes hmtx;
  for (auto [advance, lsb] : s.metrics) put16(hmtx, advance), put16(hmtx, lsb);
  t["hmtx"] = hmtx;
  FontBytes glyf, loca;
  for (const auto& g : s.glyphs) {
    put32(loca, static_cast<std::uint32_t>(glyf.size()));
    glyf.insert(glyf.end(), g.begin(), g.end());
  }
  put32(loca, static_cast<std::uint32_t>(glyf.size()));
  t["glyf"] = glyf;
  t["loca"] = loca;
  FontBytes cmap;
  put16(cmap, 0);
  put16(cmap, 1);
  put16(cmap, 1);   // Macintosh
  put16(cmap, 0);
  put32(cmap, 12);
  put16(cmap, 0);   // format 0
  put16(cmap, 262);
  put16(cmap, 0);
  for (int c = 0; c < 256; ++c) cmap.push_back(static_cast<std::uint8_t>(s.char_to_glyph.contains(c) ? s.char_to_glyph.at(c) : 0));
  t["cmap"] = cmap;
  if (!s.kern_pairs.empty()) {
    FontBytes kern;
    put16(kern, 0);
    put16(kern, 1);
    put16(kern, 0);
    put16(kern, 14 + 6 * static_cast<int>(s.kern_pairs.size()));
    put16(kern, 1);   // horizontal, format 0
    put16(kern, static_cast<int>(s.kern_pairs.size()));
    for (int i = 0; i < 3; ++i) put16(kern, 0);
    for (const auto& p : s.kern_pairs) put16(kern, p[0]), put16(kern, p[1]), put16(kern, p[2]);
    t["kern"] = kern;
  }
  return assemble_font(t);
}

}  // namespace povtrace::test
