// triangle, smooth_triangle, polygon, mesh and mesh2 (povray-sdl-and-geometry.md §8).
//
// POV-Ray behaviour reproduced (facts read from source/backend/parser/parse.cpp, shape/triangle.cpp, mesh.cpp and
// polygon.cpp, 3.7-stable):
// - triangle: degenerate when |(P1−P2)×(P3−P2)| is exactly 0 — warned ("Degenerate triangle") and never hit.
//   smooth_triangle: also degenerate when a vertex normal has zero length, or when the three normals are not all
//   strictly on the same side of the geometric normal (Compute_Smooth_Triangle); normals are normalised.
// - polygon: at least three points; a sub-polygon closes where its first point recurs (within 1e-10 per
//   component, then made exactly equal); an unclosed last sub-polygon is closed with a warning. The points are
//   projected into a plane frame (origin = first point, u = first point farther than 1e-5, w = u×v of the next
//   point that is not collinear); collinear or non-coplanar (1e-10) points make the polygon degenerate: POV-Ray
//   then silently never hits it, povtrace also warns.
// - mesh: triangle/smooth_triangle items, each optionally `uv_vectors A B C` then `texture { T_id }` (repeatable,
//   the last counts) or `texture_list { T1 T2 T3 }`; `inside_vector V` anywhere among them. Degenerate triangles
//   (zero area on the values as written, in double precision) are dropped silently by POV-Ray; povtrace warns
//   once per mesh with their count. A zero smooth normal becomes <1,0,0> with a warning; three equal normals
//   (squared differences ≤ 1e-10) make a flat triangle. Vertices and normals are stored in single precision.
//   POV-Ray merges equal vertices with a hash table searched linearly per bucket; here a hash map on the
//   single-precision values does it in linear time (POV-Ray's 1e-10 tolerance merges float values only below
//   about 1e-3 that differ in the last bit; exact equality is used here).
// - mesh2: vertex_vectors, normal_vectors (normalised, zero → <1,0,0> with a warning), uv_vectors in any order
//   (a repeated block replaces the earlier one with a warning), then texture_list { n, texture {…} … }, then the
//   mandatory face_indices { n, <a,b,c> [, ti [, tj, tk]] … }, then uv_indices and normal_indices in either
//   order (each at most once), then inside_vector. Indices are 0-based and truncated to integers; out of range is
//   an error. Without normal_indices, normal_vectors of the vertex count pair with the vertices; fewer normal
//   indices than faces leave the remaining faces flat. Degenerate faces (zero area of the single-precision
//   vertices) are never hit in POV-Ray; povtrace drops them with a warning.
// - uv_vectors (per mesh triangle, or mesh2's list with uv_indices) are kept in double precision for uv_mapping.
#include <algorithm>
#include <bit>
#include <cmath>

#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/lexing/mesh_scan.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON

bool is_zero_vector(Vec3 v) {
  return std::fabs(v.x) < kEpsilon && std::fabs(v.y) < kEpsilon && std::fabs(v.z) < kEpsilon;
}

// Three single-precision components as a hash key (+0 and −0 are the same value).
struct FloatTriple {
  std::array<float, 3> v;
  bool operator==(const FloatTriple& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
};
struct FloatTripleHash {
  std::size_t operator()(const FloatTriple& k) const {
    std::size_t h = 0;
    for (float f : k.v) {
      const std::uint32_t bits = f == 0.0f ? 0u : std::bit_cast<std::uint32_t>(f);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
    }
    return h ^ (h >> 29);
  }
};
FloatTriple single_precision(Vec3 p) {
  return {{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)}};
}

// The distinct triples of one x y z array, found by open addressing in a table of 4-byte slots (an entry's
// index + 1; 0 = free) kept at most half full: 8 to 16 bytes per distinct triple, where an unordered_map took
// about 50 (25 MB for the 500 000 vertices of a million-triangle mesh). The array itself holds the keys.
class TripleIndex {
 public:
  // The index of `key` in `array`, appended to it when new.
  std::uint32_t find_or_add(std::vector<float>& array, const FloatTriple& key) {
    const std::size_t count = array.size() / 3;
    if (2 * (count + 1) > slots_.size()) grow(array);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = slot_of(key, mask);; s = (s + 1) & mask) {
      const std::uint32_t entry = slots_[s];
      if (entry == 0) {
        slots_[s] = static_cast<std::uint32_t>(count + 1);
        array.insert(array.end(), key.v.begin(), key.v.end());
        return static_cast<std::uint32_t>(count);
      }
      const float* v = &array[3 * std::size_t(entry - 1)];
      if (FloatTriple{{v[0], v[1], v[2]}} == key) return entry - 1;
    }
  }

 private:
  static std::size_t slot_of(const FloatTriple& key, std::size_t mask) {
    std::uint64_t h = FloatTripleHash{}(key);   // then a full avalanche, since only the low bits index
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    return static_cast<std::size_t>(h) & mask;
  }
  void grow(const std::vector<float>& array) {
    slots_.assign(std::max<std::size_t>(1024, 2 * slots_.size()), 0);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = 0; i < array.size() / 3; ++i) {
      const FloatTriple key{{array[3 * i], array[3 * i + 1], array[3 * i + 2]}};
      std::size_t s = slot_of(key, mask);
      while (slots_[s] != 0) s = (s + 1) & mask;
      slots_[s] = static_cast<std::uint32_t>(i + 1);
    }
  }
  std::vector<std::uint32_t> slots_;
};
}  // namespace

// mesh { } under construction: vertices and normals merged through hash tables, textures by identity.
struct ObjectParser::MeshBuilder {
  MeshData data;
  std::vector<std::shared_ptr<const Texture>> textures;
  TripleIndex vertex_index, normal_index;
  std::size_t degenerate = 0;
  bool zero_normal_warned = false;

  std::uint32_t add(std::vector<float>& array, TripleIndex& index, Vec3 p) {
    return index.find_or_add(array, single_precision(p));
  }
  std::int32_t texture(const std::shared_ptr<const Texture>& t) {
    if (!t) return -1;
    for (std::size_t i = 0; i < textures.size(); ++i)
      if (textures[i] == t) return static_cast<std::int32_t>(i);
    textures.push_back(t);
    return static_cast<std::int32_t>(textures.size() - 1);
  }
  void add_triangle(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>* smooth_normals,
                    const std::array<std::int32_t, 3>& tex, const std::optional<std::array<double, 6>>& uv) {
    const std::size_t before = data.triangle_count();
    // uv_vectors: the first triangle with some adds a <0, 0> (index 0) for the earlier ones.
    if (uv && data.uvs.empty()) {
      data.uvs = {0.0, 0.0};
      data.face_uvs.assign(3 * before, 0);
    }
    if (uv) {
      for (int k = 0; k < 3; ++k) {
        data.face_uvs.push_back(static_cast<std::uint32_t>(data.uvs.size() / 2));
        data.uvs.push_back((*uv)[2 * k]);
        data.uvs.push_back((*uv)[2 * k + 1]);
      }
    } else if (!data.uvs.empty()) {
      data.face_uvs.insert(data.face_uvs.end(), 3, 0);
    }
    for (const Vec3& v : p) data.faces.push_back(add(data.vertices, vertex_index, v));
    // Compute_Mesh_Triangle's flat normal, from the corners before they are rounded (a non-degenerate triangle).
    Vec3 flat = cross(p[2] - p[0], p[1] - p[0]);
    flat = flat * (1.0 / std::sqrt(flat.x * flat.x + flat.y * flat.y + flat.z * flat.z));
    for (const double c : {flat.x, flat.y, flat.z}) data.flat_normals.push_back(static_cast<float>(c));
    // The per-face arrays start with the first face that needs them, earlier faces filled in as flat/untextured.
    if (smooth_normals) {
      data.face_normals.resize(3 * before, MeshData::flat);
      for (const Vec3& n : *smooth_normals) data.face_normals.push_back(add(data.normals, normal_index, n));
    } else if (!data.face_normals.empty()) {
      data.face_normals.insert(data.face_normals.end(), 3, MeshData::flat);
    }
    if (tex[0] >= 0 || !data.face_textures.empty()) {
      data.face_textures.resize(3 * before, -1);
      data.face_textures.insert(data.face_textures.end(), tex.begin(), tex.end());
    }
  }
};

// `shape { Declared_Id modifiers }`: POV-Ray's Parse_Object_Id accepts a declared object as the whole body.
std::optional<Object> ObjectParser::parse_declared_object_body() {
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<std::shared_ptr<const SceneItem>>(*v)) {
    const auto& item = *std::get<std::shared_ptr<const SceneItem>>(*v);
    if (const auto* o = std::get_if<Object>(&item)) {
      Object copy = *o;
      parse_object_modifiers(copy);
      return copy;
    }
  }
  unget(t);
  return std::nullopt;
}

}  // namespace povtrace::sdl

namespace povtrace {

bool mesh_inside(const MeshData& data, const Matrix& world_from_object, Vec3 world_point) {
  const Matrix object_from_world = world_from_object.inverse();
  const Vec3 origin = object_from_world.point(world_point);
  const Vec3 direction = normalize(object_from_world.vector(*data.inside_vector));
  std::size_t crossings = 0;
  for (std::size_t i = 0; i < data.triangle_count(); ++i) {
    const Vec3 a = data.vertex(data.faces[3 * i]), b = data.vertex(data.faces[3 * i + 1]),
               c = data.vertex(data.faces[3 * i + 2]);
    // Möller–Trumbore: a parse-time query needs no watertightness, only the count.
    const Vec3 e1 = b - a, e2 = c - a, h = cross(direction, e2);
    const double det = dot(e1, h);
    if (std::fabs(det) < 1e-10) continue;
    const Vec3 s = origin - a;
    const double u = dot(s, h) / det;
    const Vec3 q = cross(s, e1);
    const double v = dot(direction, q) / det;
    const double t = dot(e2, q) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && t > 1e-6 && t < 1e7) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace povtrace

namespace povtrace::sdl {

Object ObjectParser::parse_triangle(const Token& keyword, bool smooth) {
  const std::string name(keyword.text);
  expect("{", " after '" + name + "'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  Triangle tri;
  std::array<Vec3, 3> normals;
  bool zero_normal = false;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) accept(",");
    tri.corners[k] = parse_vector();
    if (!smooth) continue;
    accept(",");
    const Vec3 n = parse_vector();
    zero_normal = zero_normal || length(n) == 0.0;
    normals[k] = length(n) == 0.0 ? n : normalize(n);
  }
  const Vec3 area = cross(tri.corners[0] - tri.corners[1], tri.corners[2] - tri.corners[1]);
  tri.degenerate = zero_normal || length(area) == 0.0;
  if (smooth) {
    tri.normals = normals;
    if (!tri.degenerate) {
      // The vertex normals must all lie strictly on one side of the face, or POV-Ray never hits the triangle.
      const Vec3 face = normalize(area);
      int positive = 0, negative = 0;
      for (const Vec3& n : normals) {
        positive += dot(face, n) > 0.0;
        negative += dot(face, n) < 0.0;
      }
      tri.degenerate = positive != 3 && negative != 3;
    }
  }
  if (tri.degenerate) warn(keyword.loc, "degenerate " + name + " (it is never hit, as in POV-Ray); please remove it");
  o.shape = tri;
  parse_object_modifiers(o);
  return o;
}

namespace {
// POV-Ray's Compute_Polygon: a plane frame for the points and their 2-D coordinates in it.
Polygon polygon_in_plane(const std::vector<Vec3>& points) {
  Polygon poly;
  const Vec3 origin = points[0];
  Vec3 u, v, w;
  std::size_t i = 1;
  for (; i < points.size(); ++i) {
    u = points[i] - origin;
    if (dot(u, u) > kEpsilon) break;
  }
  if (i == points.size()) poly.degenerate = true;
  for (++i; i < points.size(); ++i) {
    v = points[i] - origin;
    w = cross(u, v);
    if (dot(v, v) > kEpsilon && dot(w, w) > kEpsilon) break;
  }
  if (i >= points.size()) poly.degenerate = true;
  if (poly.degenerate) return poly;
  u = normalize(cross(v, w));
  v = normalize(cross(w, u));
  w = normalize(w);
  for (int k = 0; k < 3; ++k) {
    poly.world_from_plane.m[0][k] = u[k];
    poly.world_from_plane.m[1][k] = v[k];
    poly.world_from_plane.m[2][k] = w[k];
    poly.world_from_plane.m[3][k] = origin[k];
  }
  for (const Vec3& p : points) {
    const Vec3 d = p - origin;
    if (std::fabs(dot(d, w)) > kEpsilon) poly.degenerate = true;
    poly.points.push_back({dot(d, u), dot(d, v)});
  }
  return poly;
}
}  // namespace

Object ObjectParser::parse_polygon(const Token& keyword) {
  expect("{", " after 'polygon'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  const Token count_at = peek();
  const double count = parse_float();
  if (!(count >= 3)) fail_at(count_at, "a polygon needs at least three points");
  std::vector<Vec3> points;
  for (int i = 0; i < static_cast<int>(count); ++i) {
    accept(",");
    points.push_back(parse_vector());
  }
  // Sub-polygons: each closes where its first point recurs; the next point starts the next one.
  bool closed = false;
  Vec3 first = points[0];
  for (std::size_t i = 1; i < points.size(); ++i) {
    closed = false;
    const Vec3 d = points[i] - first;
    if (is_zero_vector(d)) {
      points[i] = first;   // made exactly equal, as POV-Ray does
      if (++i < points.size()) first = points[i];
      closed = true;
    }
  }
  if (!closed) {
    warn(keyword.loc, "polygon not closed; closing it (as POV-Ray does)");
    points.push_back(first);
  }
  Polygon poly = polygon_in_plane(points);
  if (poly.degenerate)
    warn(keyword.loc, "the polygon's points are collinear or not coplanar: it is never hit (as in POV-Ray)");
  o.shape = std::move(poly);
  parse_object_modifiers(o);
  return o;
}

// `texture { T_id }` (repeatable, the last counts) or `texture_list { T1 T2 T3 }` after a mesh triangle.
std::array<std::int32_t, 3> ObjectParser::parse_mesh_triangle_textures(MeshBuilder& mesh) {
  std::array<std::int32_t, 3> tex{-1, -1, -1};
  auto texture_id = [&]() {
    const Token t = next();
    const Value* v = lookup(t);
    if (!v || !std::holds_alternative<std::shared_ptr<const Texture>>(*v))
      fail_expected(t, "a texture identifier (a mesh triangle's textures must be declared)");
    return mesh.texture(std::get<std::shared_ptr<const Texture>>(*v));
  };
  while (true) {
    const Token t = next();
    if (t.is("texture")) {
      expect("{", " after 'texture'");
      tex = {texture_id(), -1, -1};
      expect("}", " after the texture identifier");
    } else if (t.is("texture_list")) {
      expect("{", " after 'texture_list'");
      for (int k = 0; k < 3; ++k) {
        if (k > 0) accept(",");
        tex[k] = texture_id();
      }
      expect("}", " after the three texture identifiers");
      return tex;
    } else {
      unget(t);
      return tex;
    }
  }
}

// triangle { P1, P2, P3 … } or smooth_triangle { P1, N1, P2, N2, P3, N3 … } inside mesh { }.
void ObjectParser::parse_mesh_triangle(const Token& keyword, bool smooth, MeshBuilder& mesh) {
  expect("{", smooth ? " after 'smooth_triangle'" : " after 'triangle'");
  std::array<Vec3, 3> p, n;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) accept(",");
    p[k] = parse_vector();
    if (!smooth) continue;
    accept(",");
    n[k] = parse_vector();
  }
  std::optional<std::array<double, 6>> uv;
  if (accept("uv_vectors")) {
    uv.emplace();
    for (int k = 0; k < 3; ++k) {
      if (k > 0) accept(",");
      std::tie((*uv)[2 * k], (*uv)[2 * k + 1]) = parse_uv_vector("in uv_vectors");
    }
  }
  const std::array<std::int32_t, 3> tex = parse_mesh_triangle_textures(mesh);
  expect("}", smooth ? " closing 'smooth_triangle'" : " closing 'triangle'");
  add_mesh_triangle(keyword.loc, smooth, p, n, tex, uv, mesh);
}

void ObjectParser::add_mesh_triangle(const SourceLoc& keyword, bool smooth, std::array<Vec3, 3> p,
                                    std::array<Vec3, 3> n, const std::array<std::int32_t, 3>& tex,
                                    const std::optional<std::array<double, 6>>& uv, MeshBuilder& mesh) {
  if (smooth) {
    for (Vec3& normal : n) {
      if (is_zero_vector(normal)) {
        normal = {1, 0, 0};
        if (!mesh.zero_normal_warned) warn(keyword, "a normal vector in a mesh cannot be zero: changed to <1,0,0>");
        mesh.zero_normal_warned = true;
      }
      normal = normalize(normal);
    }
  }
  if (length(cross(p[0] - p[1], p[2] - p[1])) == 0.0) {
    ++mesh.degenerate;
    return;
  }
  const Vec3 d1 = n[0] - n[1], d2 = n[0] - n[2];
  const bool distinct_normals = smooth && (dot(d1, d1) > kEpsilon || dot(d2, d2) > kEpsilon);
  mesh.add_triangle(p, distinct_normals ? &n : nullptr, tex, uv);
}

std::optional<ObjectParser::LiteralScanStart> ObjectParser::literal_scan_start() {
  // A #while/#for of this frame goes back to earlier tokens of the file, and what the scanner reads is not kept
  // for it to replay.
  return stream_.literal_scan_start(directives_.loop_in_frame(stream_.depth() - 1));
}

// As many literal `triangle { <…>, <…>, <…> }` / `smooth_triangle { <…>, <…>, … }` items as follow (no
// uv_vectors, no textures: those items are read the ordinary way).
void ObjectParser::scan_mesh_triangles(MeshBuilder& mesh) {
  const auto start = literal_scan_start();
  if (!start) return;
  const SourceFile& file = *stream_.frame().file;
  LiteralScanner s(file, start->at);
  std::size_t items = 0;
  const std::optional<std::array<double, 6>> no_uv;
  const std::array<std::int32_t, 3> no_texture{-1, -1, -1};
  while (true) {
    s.ahead();   // the item starts after the blanks: its keyword's location for warnings
    const LexPosition item = s.position();
    const std::uint64_t before = s.tokens();
    const bool smooth = s.word("smooth_triangle");
    bool ok = (smooth || s.word("triangle")) && s.symbol('{');
    std::array<Vec3, 3> p, n;
    std::array<double, 3> v;
    for (int k = 0; ok && k < 3; ++k) {
      if (k > 0) s.optional_comma();
      ok = s.vector(v);
      p[k] = {v[0], v[1], v[2]};
      if (!ok || !smooth) continue;
      s.optional_comma();
      ok = s.vector(v);
      n[k] = {v[0], v[1], v[2]};
    }
    ok = ok && s.symbol('}') && literal_scan_allows(s.tokens(), items, item, start->at.offset);
    if (!ok) {
      s.reset(item, before);
      break;
    }
    add_mesh_triangle(SourceLoc{file.name, item.line, item.column}, smooth, p, n, no_texture, no_uv, mesh);
    ++items;
  }
  if (items > 0) literal_scan_commit(*start, s.position(), s.tokens());
}

std::optional<Vec3> ObjectParser::parse_inside_vector() {
  const Vec3 v = parse_vector();
  if (is_zero_vector(v)) return std::nullopt;
  return normalize(v);
}

Object ObjectParser::parse_mesh(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'mesh'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  MeshBuilder mesh;
  std::optional<Vec3> inside_vector;
  while (true) {
    scan_mesh_triangles(mesh);
    const Token t = next();
    if (t.is("triangle")) parse_mesh_triangle(t, false, mesh);
    else if (t.is("smooth_triangle")) parse_mesh_triangle(t, true, mesh);
    else if (t.is("inside_vector")) inside_vector = parse_inside_vector();
    else { unget(t); break; }
  }
  if (mesh.degenerate > 0)
    warn(keyword.loc, std::to_string(mesh.degenerate) + " degenerate triangle(s) in this mesh skipped");
  if (mesh.data.triangle_count() == 0) fail_at(keyword, "no triangles in the mesh");
  mesh.data.inside_vector = inside_vector;
  o.shape = Mesh{std::make_shared<const MeshData>(std::move(mesh.data)), std::move(mesh.textures)};
  extents().made(o);
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl
