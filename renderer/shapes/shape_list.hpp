// The one registration point of the renderer's shapes. Each line names a shape (its ShapeType enumerator) and the
// struct of renderer/shapes/<shape>.hpp that implements it; geometry.hpp makes the ShapeType enum from this list and
// renderer/shapes/shape_registry.hpp makes every dispatch (intersections, hits, normals, inside, bounds, uv, and the
// build from the description) from it. A new shape is its own .cpp + header plus one line here (and its include in
// shape_registry.hpp). The order is the ShapeType order.
//
// No includes: geometry.hpp includes this before the shape structs exist.
#pragma once

#define POVTRACE_SHAPES(X)                  \
  X(sphere, SphereShape)                    \
  X(plane, PlaneShape)                      \
  X(box, BoxShape)                          \
  X(cylinder, CylinderShape)                \
  X(cone, ConeShape)                        \
  X(disc, DiscShape)                        \
  X(torus, TorusShape)                      \
  X(poly, PolyShape)                        \
  X(triangle, TriangleShape)                \
  X(polygon, PolygonShape)                  \
  X(mesh, MeshShape)                        \
  X(quadric, QuadricShape)                  \
  X(superellipsoid, SuperellipsoidShape)    \
  X(ovus, OvusShape)                        \
  X(height_field, HeightFieldShape)         \
  X(blob, BlobShape)                        \
  X(csg, CsgShape)                          \
  X(text, TextShape)                        \
  X(lathe, LatheShape)                      \
  X(prism, PrismShape)                      \
  X(sor, SorShape)                          \
  X(isosurface, IsosurfaceShape)            \
  X(julia_fractal, JuliaFractalShape)       \
  X(bicubic_patch, BicubicPatchShape)
