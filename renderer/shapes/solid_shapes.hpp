// Render-ready primitives for superellipsoid, blob, lathe, prism, sor and height_field built from their scene
// descriptions (POV-Ray builds its own shape objects at parse time; see each shape's file for the fields it uses).
// Used by render_scene.cpp and by the geometry tests.
#pragma once

#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

Primitive make_superellipsoid(const Superellipsoid& s, const Matrix& world_from_object);
// Reads the image now; a missing or unreadable file is a ParseError at the file name in the scene.
Primitive make_height_field(const HeightField& h, const Matrix& world_from_object);
Primitive make_blob(const Blob& b, const Matrix& world_from_object);
Primitive make_text(const Text& t, const Matrix& world_from_object);
Primitive make_lathe(const Lathe& l, const Matrix& world_from_object);
Primitive make_prism(const Prism& p, const Matrix& world_from_object);
Primitive make_sor(const Sor& s, const Matrix& world_from_object);
Primitive make_isosurface(const Isosurface& iso, const Matrix& world_from_object);

}  // namespace povtrace::render
