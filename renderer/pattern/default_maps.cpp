// Built-in colour maps. POV-Ray stores map values and colours in single precision, hence single() on every
// value that is not exactly representable. Most patterns go from black at 0 to white at 1; bozo, wood, agate,
// radial, marble, brick, hexagon, checker and mandel have their own maps.
#include "renderer/pattern/default_maps.hpp"

namespace povtrace::render {

namespace {
double single(double d) { return static_cast<double>(static_cast<float>(d)); }

MapEntry entry(double value, double r, double g, double b) {
  return MapEntry{single(value), Colour{single(r), single(g), single(b), 0, 0}, nullptr};
}

// bozo: white below 0.4, then bands of green, blue and red with hard edges.
std::vector<MapEntry> bozo_map() {
  return {entry(0.4, 1, 1, 1), entry(0.4, 0, 1, 0), entry(0.6, 0, 1, 0),
          entry(0.6, 0, 0, 1), entry(0.8, 0, 0, 1), entry(0.8, 1, 0, 0)};
}
// wood: light and dark brown meeting at 0.6.
std::vector<MapEntry> wood_map() { return {entry(0.6, 0.666, 0.312, 0.2), entry(0.6, 0.4, 0.1333, 0.066)}; }
std::vector<MapEntry> agate_map() {
  return {entry(0.0, 1, 1, 1),       entry(0.5, 0.95, 0.75, 0.5), entry(0.5, 0.9, 0.7, 0.5),
          entry(0.6, 0.9, 0.7, 0.4), entry(0.6, 1.0, 0.7, 0.4),   entry(1.0, 0.6, 0.3, 0.0)};
}
// radial: cyan, yellow, magenta and back to cyan around the turn.
std::vector<MapEntry> radial_map() {
  return {entry(0.0, 0, 1, 1), entry(0.333, 1, 1, 0), entry(0.666, 1, 0, 1), entry(1.0, 0, 1, 1)};
}
std::vector<MapEntry> marble_map() {
  return {entry(0.0, 0.9, 0.8, 0.8), entry(0.9, 0.9, 0.08, 0.08), entry(0.9, 0, 0, 0)};
}
std::vector<MapEntry> brick_map() { return {entry(0.0, 0.5, 0.5, 0.5), entry(1.0, 0.6, 0.15, 0.15)}; }
// hexagon: blue, green, red; checker uses the first two of them (blue, green).
std::vector<MapEntry> hexagon_map() { return {entry(0.0, 0, 0, 1), entry(1.0, 0, 1, 0), entry(2.0, 1, 0, 0)}; }
std::vector<MapEntry> checker_map() { return {entry(0.0, 0, 0, 1), entry(1.0, 0, 1, 0)}; }
// mandel: black inside and just outside, then cyan, yellow, magenta and cyan again within the first tenth (the
// exterior value is the escape iteration's share of the limit).
std::vector<MapEntry> mandel_map() {
  return {entry(0.001, 0, 0, 0), entry(0.001, 0, 1, 1), entry(0.012, 1, 1, 0), entry(0.015, 1, 0, 1),
          entry(0.1, 0, 1, 1)};
}
std::vector<MapEntry> grey_map() { return {entry(0.0, 0, 0, 0), entry(1.0, 1, 1, 1)}; }
}  // namespace

const std::vector<MapEntry>& default_colour_map(const Pigment& pigment) {
  static const std::vector<MapEntry> bozo = bozo_map(), wood = wood_map(), agate = agate_map(),
                                     radial = radial_map(), marble = marble_map(), brick = brick_map(),
                                     hexagon = hexagon_map(), checker = checker_map(), grey = grey_map(),
                                     mandel = mandel_map();
  switch (pigment.pattern) {
    case PatternKind::mandel: return pigment.fractal.exponent == 2 ? mandel : grey;
    case PatternKind::bozo: return bozo;
    case PatternKind::wood: return wood;
    case PatternKind::agate: return agate;
    case PatternKind::radial: return radial;
    case PatternKind::marble: return marble;
    case PatternKind::brick: return brick;
    case PatternKind::hexagon: return hexagon;
    case PatternKind::checker: return checker;
    default: return grey;
  }
}

}  // namespace povtrace::render
