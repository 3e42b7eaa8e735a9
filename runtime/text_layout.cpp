// POV-Ray's layout of a text string (source/backend/shape/truetype.cpp ProcessNewTTF, 3.7-stable). Facts
// reproduced (all lengths in em units: font units × 1/unitsPerEm):
// - The first glyph is moved left by its box's xMin, so its outline starts at x = 0; the pen then stands at its
//   advance width minus its left side bearing.
// - Every later glyph is placed at the pen plus (lsb − xMin + kerning) in x and the vertical kerning in y, and the
//   pen moves on by (advance width + kerning). Metrics are those of the glyph's USE_MY_METRICS component.
// - After each glyph the pen moves by the offset vector, in x and y; its z never reaches a glyph (POV-Ray places
//   the glyphs in the plane z = 0).
// - Kerning: the pair (previous glyph's index, this glyph's metrics glyph) is looked up in each kern subtable in
//   order, stopping in a subtable at the first pair whose left glyph is larger. Every subtable is judged by the
//   *first* subtable's coverage bits (a POV-Ray quirk): skipped unless horizontal; "minimum" pairs set lower
//   limits; cross-stream pairs kern vertically (0x8000 resets); "override" replaces the value instead of adding.
//   Values are 16-bit, and each is raised to its limit (−unitsPerEm unless a minimum pair says otherwise).
#include "runtime/truetype.hpp"

#include <algorithm>

namespace povtrace::ttf {

namespace {
constexpr std::uint16_t kHorizontal = 0x01, kMinimum = 0x02, kCrossStream = 0x04, kOverride = 0x08;
constexpr std::int16_t kResetCrossStream = -32768;   // the value 0x8000

struct Kerning {
  std::int16_t x = 0, y = 0;
};

std::int16_t add16(std::int16_t a, std::int16_t b) { return static_cast<std::int16_t>(a + b); }

Kerning kerning_between(const Font& font, std::uint16_t left, std::uint16_t right) {
  Kerning k;
  const auto limit = static_cast<std::int16_t>(-static_cast<int>(font.units_per_em()));
  std::int16_t min_x = limit, min_y = limit;
  const auto& tables = font.kerning();
  for (const KernSubtable& table : tables) {
    const std::uint16_t coverage = tables.front().coverage;
    if (!(coverage & kHorizontal)) continue;
    for (const KernPair& pair : table.pairs) {
      if (pair.left == left && pair.right == right) {
        if (coverage & kMinimum) (coverage & kCrossStream ? min_y : min_x) = pair.value;
        else if (coverage & kCrossStream)
          k.y = pair.value == kResetCrossStream ? 0 : (coverage & kOverride) ? pair.value : add16(k.y, pair.value);
        else k.x = (coverage & kOverride) ? pair.value : add16(k.x, pair.value);
        break;
      }
      if (pair.left > left) break;
    }
  }
  k.x = std::max(k.x, min_x);
  k.y = std::max(k.y, min_y);
  return k;
}
}  // namespace

Text lay_out_text(Font& font, const std::vector<std::uint32_t>& codes, double thickness, Vec3 offset) {
  Text text;
  text.thickness = thickness;
  const double funit = 1.0 / static_cast<double>(font.units_per_em());
  Vec3 pen{0, 0, 0};
  std::uint16_t previous = 0;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const Glyph g = font.glyph_for(codes[i]);
    const HorizontalMetric& m = font.metric(g.metrics);
    const int x_min = g.outline->x_min;
    if (i == 0) {
      text.glyphs.push_back(TextGlyph{g.outline, -x_min * funit, 0.0});
      pen.x = (m.advance_width - m.lsb) * funit;
    } else {
      const Kerning k = kerning_between(font, previous, g.metrics);
      text.glyphs.push_back(TextGlyph{g.outline, pen.x + (m.lsb - x_min + k.x) * funit, pen.y + k.y * funit});
      pen.x += (m.advance_width + k.x) * funit;
    }
    pen += offset;
    previous = g.index;
  }
  return text;
}

namespace {
// One UTF-8 sequence at s[i]; malformed bytes stand for themselves.
std::uint32_t decode_utf8(const std::string& s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(s[k]); };
  const std::uint8_t lead = byte(i++);
  int extra = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
  if (lead < 0x80 || extra == 0 || i + extra > s.size()) return lead;
  std::uint32_t code = lead & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return lead;
    code = code << 6 | (byte(i + k) & 0x3F);
  }
  i += extra;
  return code & 0xFFFF;   // POV-Ray's characters are 16-bit (UCS-2)
}
}  // namespace

std::vector<std::uint32_t> character_codes(const std::string& text, StringEncoding encoding, int language_version) {
  std::vector<std::uint32_t> codes;
  for (std::size_t i = 0; i < text.size();) {
    if (encoding == StringEncoding::utf8) {
      codes.push_back(decode_utf8(text, i));
      continue;
    }
    const auto c = static_cast<std::uint8_t>(text[i++]);
    codes.push_back(c > 127 && language_version >= 350 ? std::uint32_t{' '} : c);
  }
  return codes;
}

}  // namespace povtrace::ttf
