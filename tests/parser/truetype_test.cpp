// The TrueType reader and the text layout: facts of the fonts POV-Ray ships (glyph counts, metrics, kerning and
// outline points as fontTools reads them from the same files), composite
// glyphs and POV-Ray's quirks on a font written here byte by byte, and damaged fonts (truncated at every length,
// bytes flipped at random): each must give a FontError or a usable font, never a crash or a hang.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

#include "runtime/truetype.hpp"
#include "ttf_builder.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::ttf;
using povtrace::test::FontBytes;

const char* const kFontDir = "/usr/share/povray-3.7/include/";

FontBytes file_bytes(const std::string& name) {
  std::ifstream in(kFontDir + name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One outline point of a glyph (contour c, point k) in font units, with its on-curve flag.
struct Expected {
  std::size_t contour, point;
  int x, y;
  bool on;
};

// Values from fontTools (python3-fonttools 4.38, Glyph.expand on the glyf bytes of each glyph, hmtx, kern):
// character, glyph index, advance, lsb, box, contour end points, the first four points. The box is the stored
// header box widened to the points, as POV-Ray widens it (timrom's 'A' stores xMax 736, a point reaches 742).
struct GlyphFacts {
  const char* font;
  int code;
  int index, advance, lsb, x_min, y_min, x_max, y_max;
  std::vector<int> ends;
  std::vector<Expected> points;
};

const GlyphFacts kFacts[] = {
    {"timrom.ttf", 'A', 34, 750, 6, 6, 0, 742, 696, {27, 30},
     {{0, 0, 356, 696, true}, {0, 1, 380, 696, true}, {0, 2, 629, 107, true}, {0, 3, 639, 84, false}}},
    {"timrom.ttf", 'g', 72, 500, 20, 20, -212, 474, 469, {49, 66, 78},
     {{0, 0, 355, 436, true}, {0, 1, 474, 436, true}, {0, 2, 474, 398, true}, {0, 3, 395, 398, true}}},
    {"cyrvetic.ttf", 'A', 34, 664, 5, 5, 0, 651, 728, {7, 11},
     {{0, 0, 269, 728, true}, {0, 1, 386, 728, true}, {0, 2, 651, 0, true}, {0, 3, 542, 0, true}}},
    {"crystal.ttf", 'g', 74, 1065, 115, 115, -410, 938, 1114, {35, 54},
     {{0, 0, 938, 90, true}, {0, 1, 938, -217, false}, {0, 2, 817, -328, true}, {0, 3, 727, -410, false}}},
    {"povlogo.ttf", 'P', 4, 361, 1, 1, 1, 344, 513, {11, 46},
     {{0, 0, 170, 429, true}, {0, 1, 197, 429, false}, {0, 2, 236, 390, false}, {0, 3, 236, 363, true}}},
};

TEST(TrueType, ShippedFontsHaveFontToolsGlyphCounts) {
  const std::pair<const char*, int> counts[] = {{"timrom.ttf", 144}, {"cyrvetic.ttf", 165}, {"crystal.ttf", 98},
                                                {"povlogo.ttf", 5}};
  for (auto [name, count] : counts) {
    Font font(file_bytes(name), StringEncoding::ascii);
    EXPECT_EQ(font.glyph_count(), count) << name;
  }
  EXPECT_EQ(Font(file_bytes("crystal.ttf"), StringEncoding::ascii).units_per_em(), 2048);
  EXPECT_EQ(Font(file_bytes("povlogo.ttf"), StringEncoding::ascii).units_per_em(), 512);
}

TEST(TrueType, GlyphsMatchFontTools) {
  for (const GlyphFacts& f : kFacts) {
    SCOPED_TRACE(std::string(f.font) + " '" + char(f.code) + "'");
    Font font(file_bytes(f.font), StringEncoding::ascii);
    ASSERT_EQ(font.glyph_index(static_cast<std::uint32_t>(f.code)), f.index);
    EXPECT_EQ(font.metric(static_cast<std::uint16_t>(f.index)).advance_width, f.advance);
    EXPECT_EQ(font.metric(static_cast<std::uint16_t>(f.index)).lsb, f.lsb);
    const Glyph g = font.glyph_for(static_cast<std::uint32_t>(f.code));
    const GlyphOutline& o = *g.outline;
    EXPECT_EQ(o.x_min, f.x_min);
    EXPECT_EQ(o.y_min, f.y_min);
    EXPECT_EQ(o.x_max, f.x_max);
    EXPECT_EQ(o.y_max, f.y_max);
    ASSERT_EQ(o.contours.size(), f.ends.size());
    int first = 0;
    for (std::size_t c = 0; c < f.ends.size(); ++c) {
      EXPECT_EQ(o.contours[c].count(), static_cast<std::size_t>(f.ends[c] - first + 1));
      first = f.ends[c] + 1;
    }
    const double upem = font.units_per_em();
    for (const Expected& e : f.points) {
      const GlyphContour& c = o.contours[e.contour];
      EXPECT_EQ(c.x[e.point], e.x / upem);
      EXPECT_EQ(c.y[e.point], e.y / upem);
      EXPECT_EQ(c.on_curve[e.point] != 0, e.on);
    }
    // Each contour is closed by a copy of its first point.
    for (const GlyphContour& c : o.contours) {
      EXPECT_EQ(c.x.back(), c.x.front());
      EXPECT_EQ(c.y.back(), c.y.front());
    }
  }
}

TEST(TrueType, CharacterMapChoiceFollowsTheStringEncoding) {
  // povlogo's Macintosh map has 'P' (80); its Microsoft symbol map has only 0xF050, reached by the 0xF000 retry.
  for (auto encoding : {StringEncoding::ascii, StringEncoding::utf8}) {
    Font font(file_bytes("povlogo.ttf"), encoding);
    EXPECT_EQ(font.glyph_index('P'), 4);
    EXPECT_EQ(font.glyph_index('A'), 0);
  }
  Font unicode(file_bytes("timrom.ttf"), StringEncoding::utf8);   // Microsoft Unicode map first
  EXPECT_EQ(unicode.glyph_index('A'), 34);
}

TEST(TrueType, LayoutUsesAdvanceBearingAndKerning) {
  Font font(file_bytes("timrom.ttf"), StringEncoding::ascii);
  // fontTools: A = glyph 34 (advance 750, lsb 6, xMin 6); V = 55 (724, 0, xMin 0); kern (A, V) = -187.
  const Text t = lay_out_text(font, {'A', 'V'}, 0.5, {0, 0, 0});
  ASSERT_EQ(t.glyphs.size(), 2u);
  EXPECT_DOUBLE_EQ(t.glyphs[0].x, -0.006);
  EXPECT_DOUBLE_EQ(t.glyphs[1].x, 0.744 - 0.187);
  EXPECT_EQ(t.glyphs[1].y, 0.0);
  EXPECT_EQ(t.thickness, 0.5);
  // T = 53 (590, 10, xMin 10), o = 80 (506, 32, xMin 32), kern (T, o) = -42; the offset moves every later glyph.
  const Text to = lay_out_text(font, {'T', 'o'}, 1, {0.1, 0.2, 0.3});
  EXPECT_DOUBLE_EQ(to.glyphs[0].x, -0.010);
  EXPECT_DOUBLE_EQ(to.glyphs[1].x, 0.58 + 0.1 - 0.042);
  EXPECT_DOUBLE_EQ(to.glyphs[1].y, 0.2);
}

TEST(TrueType, SpaceHasNoOutlineAndCharactersAreCachedPerFont) {
  Font font(file_bytes("timrom.ttf"), StringEncoding::ascii);
  const Glyph space = font.glyph_for(' ');
  EXPECT_TRUE(space.outline->contours.empty());
  EXPECT_EQ(space.outline->x_max, 0);
  EXPECT_EQ(font.glyph_for('A').outline, font.glyph_for('A').outline);
}

TEST(TrueType, CharacterCodesFollowPovRayStringRules) {
  EXPECT_EQ(character_codes("A\xC3\xA9", StringEncoding::ascii, 370), (std::vector<std::uint32_t>{'A', ' ', ' '}));
  EXPECT_EQ(character_codes("A\xC3\xA9", StringEncoding::ascii, 310), (std::vector<std::uint32_t>{'A', 0xC3, 0xA9}));
  EXPECT_EQ(character_codes("A\xC3\xA9", StringEncoding::utf8, 370), (std::vector<std::uint32_t>{'A', 0xE9}));
}

// ---- a font written here: simple and composite glyphs -----------------------------------------------------
using test::Point;

FontBytes composite_glyph(const std::vector<std::array<int, 4>>& parts, int x_min, int y_min, int x_max, int y_max) {
  // parts: glyph index, x offset, y offset, word arguments (1) or bytes (0); the last has no MORE_COMPONENTS.
  FontBytes b;
  test::put16(b, -1);
  for (int v : {x_min, y_min, x_max, y_max}) test::put16(b, v);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto& [index, dx, dy, words] = parts[i];
    int flags = 0x0002 | (words ? 0x0001 : 0) | (i + 1 < parts.size() ? 0x0020 : 0);
    test::put16(b, flags);
    test::put16(b, index);
    if (words) {
      test::put16(b, dx);
      test::put16(b, dy);
    } else {
      b.push_back(static_cast<std::uint8_t>(dx));
      b.push_back(static_cast<std::uint8_t>(dy));
    }
  }
  return b;
}

test::FontSpec square_font() {
  test::FontSpec s;
  s.glyphs.push_back(test::simple_glyph({{{0, 0, true}, {100, 0, true}, {100, 100, true}, {0, 100, true}}}, 0, 0, 100, 100));
  s.glyphs.push_back(test::simple_glyph({{{50, 0, true}, {150, 100, false}, {50, 200, true}}}, 50, 0, 150, 200));
  s.char_to_glyph = {{'a', 0}, {'b', 1}};
  s.metrics = {{120, 0}, {200, 50}};
  return s;
}

TEST(TrueType, CompositeGlyphsAddTheirPartsWithPovRayQuirks) {
  test::FontSpec s = square_font();
  // Byte arguments are read unsigned: 200 stays +200 (a signed reading would give −56).
  s.glyphs.push_back(composite_glyph({{0, 200, 10, 0}, {1, -300, 5, 1}}, 120, 30, 500, 400));
  s.char_to_glyph['c'] = 2;
  s.metrics.push_back({600, 120});
  Font font(test::build_font(s), StringEncoding::ascii);
  const GlyphOutline& o = *font.glyph_for('c').outline;
  ASSERT_EQ(o.contours.size(), 2u);
  EXPECT_EQ(o.contours[0].x[1], 0.1 + 0.2);
  EXPECT_EQ(o.contours[0].y[2], 0.1 + 0.01);
  EXPECT_EQ(o.contours[1].x[0], 0.05 - 0.3);
  // The header box is compared with em-unit points as if they were font units: xMin 120 > −0.25 → 0 (truncated),
  // yMin 30 > 0.005 → 0; the maxima stay.
  EXPECT_EQ(o.x_min, 0);
  EXPECT_EQ(o.y_min, 0);
  EXPECT_EQ(o.x_max, 500);
  EXPECT_EQ(o.y_max, 400);
}

TEST(TrueType, KerningPairsOfABuiltFont) {
  test::FontSpec s = square_font();
  s.kern_pairs = {{0, 1, -30}};
  Font font(test::build_font(s), StringEncoding::ascii);
  const Text t = lay_out_text(font, {'a', 'b', 'a'}, 1, {0, 0, 0});
  EXPECT_DOUBLE_EQ(t.glyphs[1].x, 0.12 + (50 - 50 - 30) / 1000.0);
  EXPECT_DOUBLE_EQ(t.glyphs[2].x, 0.12 + 0.2 - 0.03);
}

TEST(TrueType, SelfReferencingCompositeIsAnError) {
  test::FontSpec s = square_font();
  s.glyphs.push_back(composite_glyph({{2, 0, 0, 1}}, 0, 0, 10, 10));
  s.char_to_glyph['c'] = 2;
  s.metrics.push_back({100, 0});
  Font font(test::build_font(s), StringEncoding::ascii);
  EXPECT_THROW(font.glyph_for('c'), FontError);
}

TEST(TrueType, NotAFontIsAnError) {
  EXPECT_THROW(Font(FontBytes{}, StringEncoding::ascii), FontError);
  EXPECT_THROW(Font(FontBytes(100, 0), StringEncoding::ascii), FontError);
  FontBytes text{'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd', '\n'};
  EXPECT_THROW(Font(text, StringEncoding::ascii), FontError);
}

// Reads a font and lays out every printable character: a FontError is fine, anything else is a failure.
void read_everything(const FontBytes& bytes) {
  try {
    Font font(bytes, StringEncoding::ascii);
    std::vector<std::uint32_t> codes;
    for (std::uint32_t c = 32; c < 127; ++c) codes.push_back(c);
    const Text t = lay_out_text(font, codes, 1, {0, 0, 0});
    for (const TextGlyph& g : t.glyphs) (void)inside_glyph(*g.outline, 0.3, 0.3);
  } catch (const FontError&) {
  }
}

TEST(TrueType, TruncatedFontsNeverCrash) {
  for (const char* name : {"timrom.ttf", "povlogo.ttf"}) {
    const FontBytes whole = file_bytes(name);
    for (std::size_t n = 0; n < whole.size(); n += 37) read_everything(FontBytes(whole.begin(), whole.begin() + n));
  }
  const FontBytes built = test::build_font(square_font());
  for (std::size_t n = 0; n < built.size(); ++n) read_everything(FontBytes(built.begin(), built.begin() + n));
}

TEST(TrueType, CorruptedFontsNeverCrash) {
  std::mt19937 rng(7);
  const FontBytes whole = file_bytes("cyrvetic.ttf");
  std::uniform_int_distribution<std::size_t> at(0, whole.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int k = 0; k < 400; ++k) {
    FontBytes damaged = whole;
    for (int flips = 0; flips < 1 + k % 8; ++flips) damaged[at(rng)] = static_cast<std::uint8_t>(byte(rng));
    read_everything(damaged);
  }
}

}  // namespace
