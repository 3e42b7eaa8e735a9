// The renderer's side of the parse-time geometry queries (scene/object_geometry.hpp): trace() and inside() on a
// declared object, answered by the same primitives, CSG nodes and intersection code that render the scene.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "scene/object_geometry.hpp"

namespace povtrace::render {

// The implementation to hand the parser in ParseOptions::object_geometry: the program makes one and keeps it while
// it parses. Shareable between threads; it remembers the extents of the height-field images it has read (per file,
// modification time and water level), since every CSG holding a height field asks for it when it is made.
class RendererGeometry final : public ObjectGeometry {
 public:
  std::unique_ptr<const PreparedObject> prepare(const Object& object, int noise_generator) const override;
  HeightFieldExtent height_field_extent(const HeightField& h, int noise_generator) const override;

 private:
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::string, HeightFieldExtent> file_extents_;
};

}  // namespace povtrace::render
