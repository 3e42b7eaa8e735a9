// The pattern functions behind pattern_value(), grouped by file: tilings.cpp (checker, hexagon, brick) and
// noise_patterns.cpp (bozo, spotted, granite, marble, wood, agate, spiral1, spiral2, dents, wrinkles, ripples, waves),
// cell_patterns.cpp (crackle, cells), fractal_patterns.cpp (mandel, julia, magnet), surface_patterns.cpp (slope,
// aoi), density_file.cpp (density_file). Internal to renderer/pattern.
#pragma once

#include "renderer/pattern/pattern.hpp"

namespace povtrace::render::patterns {

// The angle of (x, z) from +x towards +z, in [0, 2π), as POV-Ray's mappers and mapping warps take it: acos of
// x / len, mirrored for negative z, exact on the axes (image_map.cpp).
double angle_around_y(double x, double z, double len);
// POV-Ray's table of 32768 random doubles in [0, 1) (its PatternRands and WarpRands), index taken modulo its size
// (cell_patterns.cpp).
double pattern_random(std::size_t index);

// warp { planar | cylindrical | spherical | toroidal | cubic } and warp { black_hole } on a point (mapping_warps.cpp).
Vec3 mapping_warp(Vec3 p, const MappingWarp& w);
Vec3 black_hole_warp(Vec3 p, const BlackHoleWarp& w, int cell[3]);

double checker(Vec3 p);
double hexagon(Vec3 p);
double brick(Vec3 p, Vec3 size, double mortar);

double granite(Vec3 p, NoiseGenerator generator);
double marble(Vec3 p, const std::optional<Turbulence>& turbulence, NoiseGenerator generator);
double wood(Vec3 p, const std::optional<Turbulence>& turbulence);
double agate(Vec3 p, const Turbulence& turbulence, double agate_turb, NoiseGenerator generator);
double spiral1(Vec3 p, int arms, const std::optional<Turbulence>& turbulence, NoiseGenerator generator);
double spiral2(Vec3 p, int arms, const std::optional<Turbulence>& turbulence, NoiseGenerator generator);

// POV-Ray's Triangle_Wave: 0 → 1 → 0 over each unit.
double triangle_wave(double v);

double dents(Vec3 p, NoiseGenerator generator);
double wrinkles(Vec3 p, NoiseGenerator generator);
double ripples(Vec3 p, double frequency, double phase);
double waves(Vec3 p, double frequency, double phase);

double crackle(Vec3 p, const CrackleParams& params, NoiseGenerator generator);
double cells(Vec3 p);
// POV-Ray's facets normal (normal.cpp facets) of the warped `normal` at pattern-space point p: the random cube point
// (crackle's) nearest to normal/size (coords 0) or to p/size, by the metric; without coords that point is the new
// normal, with coords the normal gains coords times the part of the vector noise there across the normal.
Vec3 facets(Vec3 normal, Vec3 p, double coords, double size, double metric);

// mandel, julia, magnet (fractal_patterns.cpp): the exterior or interior value at the point's x + iy.
double fractal(const FractalParams& f, Vec3 p);

// slope and aoi (surface_patterns.cpp): 0 without a surface.
double slope(const SlopeParams& s, Vec3 p, const ShadingSurface* hit);
double aoi(const ShadingSurface* hit);

// density_file (density_file.cpp): the grid's value at p, 0 outside the unit cube; `interpolation` as written.
double density_file(const DensityGrid& grid, int interpolation, Vec3 p);

}  // namespace povtrace::render::patterns
