// Glyph outlines from the glyf table as POV-Ray 3.7 reads them (source/backend/shape/truetype.cpp
// ExtractGlyphOutline, ConvertOutlineToGlyph, 3.7-stable). Facts reproduced:
// - A glyph is read from glyf + loca[index] on, whatever the next loca entry says (an empty glyph therefore reads
//   the header of the glyph stored after it).
// - Simple glyphs: contour end points, instructions skipped, flags with repeats (repeats past the last point are
//   dropped), then x and y deltas (one byte with a sign flag, none, or a signed 16-bit value) summed in 16-bit
//   arithmetic. The header box (xMin … yMax) is widened to the points read. Points are stored as coordinate /
//   unitsPerEm.
// - Composite glyphs: each component has flags, a glyph index, two arguments (16-bit signed words, or two
//   *unsigned* bytes, high byte first) and an optional scale (one, x and y, or a 2×2 matrix, each 2.14 fixed
//   point). Only components placed by x/y offsets are used (the others are skipped). A component's point (x, y)
//   becomes (xscale·x + scale01·y + xoff, scale10·x + yscale·y + yoff) with the offsets divided by unitsPerEm.
//   USE_MY_METRICS makes the component the glyph whose metrics the layout uses. The header box is then compared
//   with these em-unit points *as if they were font units* and takes them truncated to integers when they lie
//   outside it (a POV-Ray quirk that moves a composite's box edges to 0; reproduced because the layout and the
//   bounding box use that box).
// - Each contour is closed by repeating its first point and flag.
// Beyond POV-Ray, which trusts the file: nesting and size of composites are limited, decreasing end points and out-of-range
// glyph indices are errors, and the total number of points is capped, so no font can crash or exhaust the parser.
#include <algorithm>
#include <cmath>

#include "runtime/truetype.hpp"

namespace povtrace::ttf {

namespace {
constexpr int kMaxCompositeDepth = 16;
constexpr std::size_t kMaxPoints = 1 << 20;
constexpr std::size_t kMaxGlyphReads = 1 << 16;   // composites sharing parts could otherwise multiply without end

// Flag bits of simple glyph points.
constexpr std::uint8_t kOnCurve = 0x01, kXShort = 0x02, kYShort = 0x04, kRepeat = 0x08, kXSame = 0x10,
                       kYSame = 0x20;
// Flag bits of composite glyph components.
constexpr std::uint16_t kArgsAreWords = 0x0001, kArgsAreXY = 0x0002, kHaveScale = 0x0008,
                        kMoreComponents = 0x0020, kHaveXYScale = 0x0040, kHaveTwoByTwo = 0x0080,
                        kUseMyMetrics = 0x0200;

// The outline while it is read: POV-Ray's GlyphOutline (points in em units, box in 16-bit font units).
struct RawOutline {
  std::int16_t contours = 0;
  std::int16_t x_min = 0, y_min = 0, x_max = 0, y_max = 0;
  std::vector<std::uint16_t> end_points;
  std::vector<std::uint8_t> flags;
  std::vector<double> x, y;
  std::uint16_t metrics = 0;
};

struct GlyfReader {
  const Bytes& bytes;
  std::size_t glyf;
  const std::vector<std::uint32_t>& loca;
  double units_per_em;
  std::size_t points_read = 0;
  std::size_t glyphs_read = 0;

  RawOutline read(std::uint16_t index, int depth);
  void read_simple(RawOutline& g, std::size_t pos);
  void read_composite(RawOutline& g, std::size_t pos, int depth);
};

// One axis of a simple glyph's points; returns the position after its data.
std::size_t read_axis(const Bytes& b, std::size_t pos, const std::vector<std::uint8_t>& flags, std::uint8_t short_bit,
                      std::uint8_t same_bit, double units_per_em, std::vector<double>& out, std::int16_t& lo,
                      std::int16_t& hi) {
  std::int16_t coord = 0;
  out.resize(flags.size());
  for (std::size_t i = 0; i < flags.size(); ++i) {
    if (flags[i] & short_bit) {
      const int step = b.u8(pos++);
      coord = static_cast<std::int16_t>((flags[i] & same_bit) ? coord + step : coord - step);
    } else if (!(flags[i] & same_bit)) {
      coord = static_cast<std::int16_t>(coord + b.s16(pos));
      pos += 2;
    }
    hi = std::max(hi, coord);
    lo = std::min(lo, coord);
    out[i] = static_cast<double>(coord) / units_per_em;
  }
  return pos;
}

void GlyfReader::read_simple(RawOutline& g, std::size_t pos) {
  g.end_points.resize(static_cast<std::size_t>(g.contours));
  for (auto& e : g.end_points) {
    e = bytes.u16(pos);
    pos += 2;
  }
  for (std::size_t i = 1; i < g.end_points.size(); ++i)
    if (g.end_points[i] < g.end_points[i - 1]) throw FontError("a glyph's contour end points decrease");
  pos += 2 + std::size_t{bytes.u16(pos)};   // the instructions
  const auto count = static_cast<std::uint16_t>(g.end_points.back() + 1);   // 16-bit, as POV-Ray counts
  if (count == 0) throw FontError("a glyph has 65536 points");
  points_read += count;
  if (points_read > kMaxPoints) throw FontError("the glyph outlines hold too many points");
  g.flags.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t f = bytes.u8(pos++);
    g.flags[i] = f;
    if (!(f & kRepeat)) continue;
    for (int repeats = bytes.u8(pos++); repeats > 0; --repeats, ++i)
      if (i + 1 < count) g.flags[i + 1] = f;
  }
  pos = read_axis(bytes, pos, g.flags, kXShort, kXSame, units_per_em, g.x, g.x_min, g.x_max);
  read_axis(bytes, pos, g.flags, kYShort, kYSame, units_per_em, g.y, g.y_min, g.y_max);
}

// A double stored into one of POV-Ray's 16-bit header fields (truncated towards zero).
std::int16_t to_short(double v) {
  return static_cast<std::int16_t>(std::clamp(std::trunc(v), -32768.0, 32767.0));
}

struct Placement {
  double xscale = 1, yscale = 1, scale01 = 0, scale10 = 0, xoff = 0, yoff = 0;
};

void append_component(RawOutline& g, const RawOutline& part, const Placement& p) {
  const std::size_t n = g.x.size();
  for (const std::uint16_t e : part.end_points) g.end_points.push_back(static_cast<std::uint16_t>(e + n));
  g.contours = static_cast<std::int16_t>(g.contours + part.contours);
  for (std::size_t i = 0; i < part.x.size(); ++i) {
    const double x = p.xscale * part.x[i] + p.scale01 * part.y[i] + p.xoff;
    const double y = p.scale10 * part.x[i] + p.yscale * part.y[i] + p.yoff;
    g.flags.push_back(part.flags[i]);
    g.x.push_back(x);
    g.y.push_back(y);
    if (x < g.x_min) g.x_min = to_short(x);
    if (x > g.x_max) g.x_max = to_short(x);
    if (y < g.y_min) g.y_min = to_short(y);
    if (y > g.y_max) g.y_max = to_short(y);
  }
}

void GlyfReader::read_composite(RawOutline& g, std::size_t pos, int depth) {
  g.contours = 0;
  std::uint16_t flags = 0;
  do {
    flags = bytes.u16(pos);
    const std::uint16_t part_index = bytes.u16(pos + 2);
    pos += 4;
    int arg1 = 0, arg2 = 0;
    if (flags & kArgsAreWords) {
      arg1 = bytes.s16(pos);
      arg2 = bytes.s16(pos + 2);
      pos += 4;
    } else {
      arg1 = bytes.u8(pos);
      arg2 = bytes.u8(pos + 1);
      pos += 2;
    }
    Placement p;
    const auto fixed = [&](std::size_t at) { return static_cast<double>(bytes.s16(at)) / 16384.0; };
    if (flags & kHaveScale) {
      p.xscale = p.yscale = fixed(pos);
      pos += 2;
    } else if (flags & kHaveXYScale) {
      p.xscale = fixed(pos);
      p.yscale = fixed(pos + 2);
      pos += 4;
    } else if (flags & kHaveTwoByTwo) {
      p.xscale = fixed(pos);
      p.scale01 = fixed(pos + 2);
      p.scale10 = fixed(pos + 4);
      p.yscale = fixed(pos + 6);
      pos += 8;
    }
    if (!(flags & kArgsAreXY)) continue;   // point-matched components: POV-Ray skips them
    p.xoff = arg1 / units_per_em;
    p.yoff = arg2 / units_per_em;
    if (flags & kUseMyMetrics) g.metrics = part_index;
    const RawOutline part = read(part_index, depth + 1);
    if (part.contours != 0) append_component(g, part, p);
  } while (flags & kMoreComponents);
}

RawOutline GlyfReader::read(std::uint16_t index, int depth) {
  if (depth > kMaxCompositeDepth) throw FontError("composite glyphs nest too deeply (a glyph made of itself?)");
  if (++glyphs_read > kMaxGlyphReads) throw FontError("a composite glyph is made of too many parts");
  if (index >= loca.size()) throw FontError("a composite glyph uses glyph " + std::to_string(index) + ", past the last");
  RawOutline g;
  g.metrics = index;
  const std::size_t at = glyf + loca[index];
  g.contours = bytes.s16(at);
  g.x_min = bytes.s16(at + 2);
  g.y_min = bytes.s16(at + 4);
  g.x_max = bytes.s16(at + 6);
  g.y_max = bytes.s16(at + 8);
  if (g.contours > 0) read_simple(g, at + 10);
  else if (g.contours < 0) read_composite(g, at + 10, depth);
  return g;
}

// ConvertOutlineToGlyph: the points split into contours, each closed by its first point.
std::shared_ptr<GlyphOutline> to_outline(const RawOutline& raw, std::uint16_t units_per_em) {
  auto out = std::make_shared<GlyphOutline>();
  out->x_min = raw.x_min;
  out->y_min = raw.y_min;
  out->x_max = raw.x_max;
  out->y_max = raw.y_max;
  out->units_per_em = units_per_em;
  std::size_t first = 0;
  for (std::size_t c = 0; c < raw.end_points.size() && c < static_cast<std::size_t>(std::max<int>(raw.contours, 0));
       ++c) {
    const std::size_t end = std::size_t{raw.end_points[c]} + 1;
    if (end > raw.x.size()) throw FontError("a glyph's contour ends past its last point");
    if (end <= first) continue;   // an empty contour: POV-Ray's loops never enter it
    GlyphContour contour;
    contour.x.assign(raw.x.begin() + first, raw.x.begin() + end);
    contour.y.assign(raw.y.begin() + first, raw.y.begin() + end);
    for (std::size_t i = first; i < end; ++i) contour.on_curve.push_back(raw.flags[i] & kOnCurve);
    contour.x.push_back(raw.x[first]);
    contour.y.push_back(raw.y[first]);
    contour.on_curve.push_back(contour.on_curve.front());
    out->contours.push_back(std::move(contour));
    first = end;
  }
  return out;
}
}  // namespace

std::shared_ptr<const GlyphOutline> read_outline(const Bytes& bytes, std::size_t glyf,
                                                 const std::vector<std::uint32_t>& loca, std::uint16_t units_per_em,
                                                 std::uint16_t index, std::uint16_t& metrics) {
  GlyfReader reader{bytes, glyf, loca, static_cast<double>(units_per_em)};
  const RawOutline raw = reader.read(index, 0);
  metrics = raw.metrics;
  return to_outline(raw, units_per_em);
}

}  // namespace povtrace::ttf
