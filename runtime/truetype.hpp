// A TrueType font file read the way POV-Ray 3.7 reads it for the text shape (source/backend/shape/truetype.cpp,
// 3.7-stable): the tables it uses (head, maxp, loca, hhea, hmtx, kern, cmap, glyf), its choice of character map
// and its glyph outlines, quirks included, so that text lays out and renders as in POV-Ray. Everything is read from
// the file's bytes in memory; every read is bounds-checked, and a file POV-Ray could not read, or that would make
// it read outside the file, is a FontError (a hostile font never crashes or hangs the parser).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/text_description.hpp"

namespace povtrace::ttf {

struct FontError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Bounds-checked big-endian reads from the whole file (POV-Ray seeks within the file, not within a table).
class Bytes {
 public:
  explicit Bytes(const std::vector<std::uint8_t>& data) : data_(data) {}
  std::uint8_t u8(std::size_t at) const;
  std::uint16_t u16(std::size_t at) const;
  std::int16_t s16(std::size_t at) const { return static_cast<std::int16_t>(u16(at)); }
  std::uint32_t u32(std::size_t at) const;
  std::size_t size() const { return data_.size(); }

 private:
  const std::vector<std::uint8_t>& data_;
};

// Which strings the scene's text uses (global_settings { charset }): it orders the character maps POV-Ray tries.
enum class StringEncoding { ascii, utf8 };

struct HorizontalMetric {
  std::uint16_t advance_width = 0;
  std::int16_t lsb = 0;
};
struct KernPair {
  std::uint16_t left = 0, right = 0;
  std::int16_t value = 0;
};
struct KernSubtable {
  std::uint16_t coverage = 0;
  std::vector<KernPair> pairs;   // empty for subtables of a format other than 0
};

// A glyph as POV-Ray's text layout uses it: the outline and the glyph whose metrics it takes (USE_MY_METRICS).
struct Glyph {
  std::shared_ptr<const GlyphOutline> outline;
  std::uint16_t index = 0;
  std::uint16_t metrics = 0;
};

class Font {
 public:
  // Reads the table directory (of the first font in a .ttc collection) and the tables; throws FontError.
  Font(std::vector<std::uint8_t> data, StringEncoding encoding);
  Font(const Font&) = delete;   // bytes_ refers to data_
  Font& operator=(const Font&) = delete;

  std::uint16_t units_per_em() const { return units_per_em_; }
  std::uint16_t glyph_count() const { return glyph_count_; }
  const HorizontalMetric& metric(std::uint16_t glyph) const;
  const std::vector<KernSubtable>& kerning() const { return kerning_; }

  // The glyph index of a character code through the character map POV-Ray picks (0 when it has none).
  std::uint16_t glyph_index(std::uint32_t code) const;
  // The glyph of a character, through POV-Ray's per-font glyph cache (by character, then by glyph index); a space
  // has no outline. Not thread-safe: the parser is single-threaded.
  Glyph glyph_for(std::uint32_t code);
  // The outline of a glyph as read for character `code` (a space reads nothing).
  Glyph read_glyph(std::uint16_t index, std::uint32_t code) const;

 private:
  struct CharMap {
    std::uint16_t format = 0;
    std::size_t body = 0;   // file offset just after format, length and version/language
  };
  void read_directory();
  void read_head(std::size_t at);
  void read_loca(std::size_t at);
  void read_hmtx(std::size_t hhea, std::size_t hmtx);
  void read_kern(std::size_t at);
  void choose_char_map(StringEncoding encoding);
  std::uint32_t format4_index(std::uint32_t code) const;
  std::uint16_t format6_index(std::uint32_t code) const;

  std::vector<std::uint8_t> data_;
  Bytes bytes_{data_};
  std::map<std::string, std::size_t> tables_;   // tag → file offset
  std::uint16_t units_per_em_ = 0, glyph_count_ = 0;
  bool long_offsets_ = false;
  std::vector<std::uint32_t> loca_;
  std::vector<HorizontalMetric> hmtx_;
  std::vector<KernSubtable> kerning_;
  std::optional<CharMap> char_map_;
  std::map<std::uint32_t, Glyph> by_code_;
  std::map<std::uint16_t, Glyph> by_index_;
};

// The outline of glyph `index` (truetype_glyf.cpp): simple glyphs and composites, as POV-Ray's
// ExtractGlyphOutline and ConvertOutlineToGlyph build them. `metrics` receives the USE_MY_METRICS glyph.
std::shared_ptr<const GlyphOutline> read_outline(const Bytes& bytes, std::size_t glyf,
                                                 const std::vector<std::uint32_t>& loca, std::uint16_t units_per_em,
                                                 std::uint16_t index, std::uint16_t& metrics);

}  // namespace povtrace::ttf

namespace povtrace::ttf {

// POV-Ray's layout of a string (truetype.cpp ProcessNewTTF): one glyph per character code, placed by advance
// widths, left side bearings, kerning and the per-character offset (text_layout.cpp).
Text lay_out_text(Font& font, const std::vector<std::uint32_t>& codes, double thickness, Vec3 offset);

// The character codes of a scene string as POV-Ray's String_To_UCS2 makes them: with ASCII strings a byte above
// 127 becomes a space (from #version 3.5 on; earlier the byte itself); with utf8 strings the decoded characters.
std::vector<std::uint32_t> character_codes(const std::string& text, StringEncoding encoding, int language_version);

}  // namespace povtrace::ttf
