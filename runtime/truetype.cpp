// TrueType tables as POV-Ray 3.7 reads them (source/backend/shape/truetype.cpp ProcessFontFile, ProcessHeadTable,
// ProcessLocaTable, ProcessMaxpTable, ProcessHheaTable, ProcessHmtxTable, ProcessKernTable, ProcessCharMap,
// ProcessFormat{0,4,6}Glyph, ProcessCharacter; 3.7-stable). Facts reproduced:
// - A collection ("ttcf") is read from its first font. At most the first 40 entries of the table directory are
//   looked at; cmap, glyf, head, loca, hhea, hmtx and maxp must be there, kern is optional.
// - head: the magic number must be 0x5F0F3CF5; unitsPerEm and indexToLocFormat (0: 16-bit loca entries ×2,
//   otherwise 32-bit). maxp: numGlyphs. loca: numGlyphs entries (the last glyph's end is never needed: a glyph is
//   read from its offset on). hhea: numberOfHMetrics; hmtx: that many (advance, lsb) pairs, then lsbs that reuse
//   the last advance.
// - kern: only format-0 subtables keep their pairs; the next subtable follows the pairs directly. Other formats
//   are skipped by their length.
// - The character map is chosen by platform only (the encoding id is not looked at): for ASCII strings Macintosh
//   (1) first, then Microsoft (3), Unicode (0), Microsoft; for `charset utf8` Unicode, Microsoft, Macintosh,
//   Microsoft. Within that order the first subtable of the platform in format 0, 4 or 6 is used for every
//   character, even when it does not hold the character.
// - Format 0 reads the byte at the character's position. Format 4 takes the first segment whose end is at or
//   above the code; inside it the index is code + idDelta, or the idRangeOffset entry plus idDelta when that is not
//   zero (sums kept unreduced until the index is returned as 16 bits); a code below 0x100 with no glyph is tried
//   once more at code + 0xF000 (symbol fonts). Format 6: firstCode and entryCount bound a plain array.
// - Glyphs are cached per font: a character seen before gets its first glyph back, a new character whose index was
//   read before gets that glyph (so a space shares the outline of another character with its glyph index).
// POV-Ray does not check most of these values (a glyph index past numGlyphs, a unitsPerEm of 0, a table outside the
// file); povtrace refuses such a font with a FontError instead of reading garbage.
#include "runtime/truetype.hpp"

#include <array>
#include <cstring>

namespace povtrace::ttf {

namespace {
constexpr std::uint32_t kHeadMagic = 0x5F0F3CF5;
constexpr std::uint32_t kMaxTables = 40;          // POV-Ray reads at most 40 directory entries
constexpr std::uint32_t kSymbolArea = 0xF000;     // where symbol fonts put their glyphs
constexpr std::uint16_t kMinUnitsPerEm = 16, kMaxUnitsPerEm = 16384;

std::string tag_at(const Bytes& b, std::size_t at) {
  std::string tag;
  for (std::size_t i = 0; i < 4; ++i) tag += static_cast<char>(b.u8(at + i));
  return tag;
}
}  // namespace

std::uint8_t Bytes::u8(std::size_t at) const {
  if (at >= data_.size()) throw FontError("the file ends inside a table (a read at byte " + std::to_string(at) + ")");
  return data_[at];
}

std::uint16_t Bytes::u16(std::size_t at) const {
  return static_cast<std::uint16_t>(u8(at) << 8 | u8(at + 1));
}

std::uint32_t Bytes::u32(std::size_t at) const {
  return static_cast<std::uint32_t>(u16(at)) << 16 | u16(at + 2);
}

Font::Font(std::vector<std::uint8_t> data, StringEncoding encoding) : data_(std::move(data)) {
  read_directory();
  for (const char* tag : {"cmap", "glyf", "head", "loca", "hhea", "hmtx", "maxp"})
    if (!tables_.contains(tag)) throw FontError(std::string("not a TrueType font: it has no '") + tag + "' table");
  read_head(tables_["head"]);
  glyph_count_ = bytes_.u16(tables_["maxp"] + 4);
  if (glyph_count_ == 0) throw FontError("the font has no glyphs (maxp numGlyphs is 0)");
  read_loca(tables_["loca"]);
  read_hmtx(tables_["hhea"], tables_["hmtx"]);
  if (tables_.contains("kern")) read_kern(tables_["kern"]);
  choose_char_map(encoding);
}

void Font::read_directory() {
  std::size_t at = 0;
  if (bytes_.size() >= 4 && tag_at(bytes_, 0) == "ttcf") at = bytes_.u32(12);
  const std::uint16_t count = bytes_.u16(at + 4);
  for (std::uint32_t i = 0; i < count && i < kMaxTables; ++i) {
    const std::size_t entry = at + 12 + 16 * std::size_t{i};
    const std::string tag = tag_at(bytes_, entry);
    const std::uint32_t offset = bytes_.u32(entry + 8);
    if (offset != 0) tables_[tag] = offset;   // POV-Ray takes an offset of 0 as "no such table"
  }
}

void Font::read_head(std::size_t at) {
  if (bytes_.u32(at + 12) != kHeadMagic) throw FontError("not a TrueType font: wrong magic number in its 'head' table");
  units_per_em_ = bytes_.u16(at + 18);
  const std::int16_t loc_format = bytes_.s16(at + 50);
  if (units_per_em_ < kMinUnitsPerEm || units_per_em_ > kMaxUnitsPerEm)
    throw FontError("invalid TrueType font data: unitsPerEm is " + std::to_string(units_per_em_) +
                    " (16 to 16384 allowed)");
  if (loc_format != 0 && loc_format != 1)
    throw FontError("invalid TrueType font data: indexToLocFormat is " + std::to_string(loc_format));
  long_offsets_ = loc_format != 0;
}

void Font::read_loca(std::size_t at) {
  const std::size_t entry = long_offsets_ ? 4 : 2;
  if (at + entry * glyph_count_ > bytes_.size()) throw FontError("the 'loca' table runs past the end of the file");
  loca_.resize(glyph_count_);
  for (std::size_t i = 0; i < glyph_count_; ++i)
    loca_[i] = long_offsets_ ? bytes_.u32(at + 4 * i) : std::uint32_t{bytes_.u16(at + 2 * i)} << 1;
}

void Font::read_hmtx(std::size_t hhea, std::size_t hmtx) {
  const std::uint16_t long_metrics = bytes_.u16(hhea + 34);
  hmtx_.resize(glyph_count_);
  std::uint16_t last_advance = 0;
  std::size_t at = hmtx;
  for (std::size_t i = 0; i < glyph_count_; ++i) {
    if (i < long_metrics) {
      last_advance = bytes_.u16(at);
      at += 2;
    }
    hmtx_[i] = HorizontalMetric{last_advance, bytes_.s16(at)};
    at += 2;
  }
}

void Font::read_kern(std::size_t at) {
  const std::uint16_t count = bytes_.u16(at + 2);
  std::size_t pos = at + 4;
  for (std::uint16_t t = 0; t < count; ++t) {
    const std::uint16_t length = bytes_.u16(pos + 2);
    KernSubtable sub;
    sub.coverage = bytes_.u16(pos + 4);
    pos += 6;
    if (sub.coverage >> 8 == 0) {
      const std::uint16_t pairs = bytes_.u16(pos);
      pos += 8;
      if (pos + 6 * std::size_t{pairs} > bytes_.size()) throw FontError("the 'kern' table runs past the end of the file");
      for (std::uint16_t k = 0; k < pairs; ++k, pos += 6)
        sub.pairs.push_back(KernPair{bytes_.u16(pos), bytes_.u16(pos + 2), bytes_.s16(pos + 4)});
    } else {
      pos = pos + length - 6;   // length < 6 steps back, as POV-Ray's relative seek does
    }
    kerning_.push_back(std::move(sub));
  }
}

void Font::choose_char_map(StringEncoding encoding) {
  static constexpr std::array<std::uint16_t, 4> ascii_order{1, 3, 0, 3}, utf8_order{0, 3, 1, 3};
  const auto& order = encoding == StringEncoding::ascii ? ascii_order : utf8_order;
  const std::size_t cmap = tables_["cmap"];
  const std::uint16_t count = bytes_.u16(cmap + 2);
  for (const std::uint16_t platform : order)
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t entry = cmap + 4 + 8 * i;
      if (bytes_.u16(entry) != platform) continue;
      const std::size_t sub = cmap + bytes_.u32(entry + 4);
      const std::uint16_t format = bytes_.u16(sub);
      bytes_.u16(sub + 4);   // POV-Ray reads the subtable's length and version: they must be in the file
      if (format == 0 || format == 4 || format == 6) {
        char_map_ = CharMap{format, sub + 6};
        return;
      }
    }
}

const HorizontalMetric& Font::metric(std::uint16_t glyph) const {
  if (glyph >= hmtx_.size()) throw FontError("glyph " + std::to_string(glyph) + " has no horizontal metrics");
  return hmtx_[glyph];
}

std::uint32_t Font::format4_index(std::uint32_t code) const {
  const std::size_t body = char_map_->body;
  const std::size_t segments = bytes_.u16(body) >> 1;
  const std::size_t ends = body + 8, starts = ends + 2 * segments + 2, deltas = starts + 2 * segments,
                    range_offsets = deltas + 2 * segments;
  for (std::size_t i = 0; i < segments; ++i) {
    if (code > bytes_.u16(ends + 2 * i)) continue;
    const std::uint16_t start = bytes_.u16(starts + 2 * i);
    if (code < start) return 0;
    const std::uint16_t delta = bytes_.u16(deltas + 2 * i), range = bytes_.u16(range_offsets + 2 * i);
    if (range == 0) return code + delta;
    const std::uint32_t index = bytes_.u16(range_offsets + 2 * i + range + 2 * (code - start));
    return index == 0 ? 0 : index + delta;
  }
  return 0;
}

std::uint16_t Font::format6_index(std::uint32_t code) const {
  const std::size_t body = char_map_->body;
  const std::uint32_t first = bytes_.u16(body), count = bytes_.u16(body + 2);
  if (code < first || code >= first + count) return 0;
  return bytes_.u16(body + 4 + 2 * std::size_t{code - first});
}

std::uint16_t Font::glyph_index(std::uint32_t code) const {
  if (!char_map_) return 0;
  switch (char_map_->format) {
    case 0: return bytes_.u8(char_map_->body + code);
    case 6: return format6_index(code);
    default: break;
  }
  std::uint32_t index = format4_index(code);
  if (index == 0 && code < 0x100) index = format4_index(code + kSymbolArea);
  return static_cast<std::uint16_t>(index);
}

Glyph Font::read_glyph(std::uint16_t index, std::uint32_t code) const {
  if (index >= glyph_count_)
    throw FontError("the character map gives glyph " + std::to_string(index) + " but the font has only " +
                    std::to_string(glyph_count_) + " glyphs");
  Glyph g;
  g.index = index;
  g.metrics = index;
  if (code == ' ') {   // POV-Ray reads no outline for a space: an empty glyph with a zero box
    auto empty = std::make_shared<GlyphOutline>();
    empty->units_per_em = units_per_em_;
    g.outline = std::move(empty);
    return g;
  }
  g.outline = read_outline(bytes_, tables_.at("glyf"), loca_, units_per_em_, index, g.metrics);
  return g;
}

Glyph Font::glyph_for(std::uint32_t code) {
  if (auto it = by_code_.find(code); it != by_code_.end()) return it->second;
  const std::uint16_t index = glyph_index(code);
  if (auto it = by_index_.find(index); it != by_index_.end()) return it->second;
  Glyph g = read_glyph(index, code);
  by_code_.emplace(code, g);
  by_index_.emplace(index, g);
  return g;
}

}  // namespace povtrace::ttf
