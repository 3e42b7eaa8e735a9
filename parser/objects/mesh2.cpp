// mesh2 { vertex_vectors … face_indices … } (povray-sdl-and-geometry.md §8; the POV-Ray behaviour reproduced is
// listed in meshes.cpp's header). Everything is read straight into flat arrays in one pass: parsing is linear in
// the size of the mesh, and a million faces cost 12 bytes each (plus 12 per smooth or textured face).
#include <algorithm>
#include <cmath>

#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/lexing/mesh_scan.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON
// Room reserved up front for a declared count: a hostile count must not allocate before the items are read.
constexpr std::size_t kMaxReserve = std::size_t(1) << 22;

std::string plural(std::size_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}
}  // namespace

template <std::size_t N, class Take>
std::size_t ObjectParser::scan_mesh2_items(std::size_t max_items, Take&& take) {
  if (max_items == 0) return 0;
  const auto start = literal_scan_start();
  if (!start) return 0;
  LiteralScanner s(*stream_.frame().file, start->at);
  std::size_t items = 0;
  std::array<double, N> v;
  while (items < max_items) {
    s.ahead();
    const LexPosition item = s.position();
    const std::uint64_t before = s.tokens();
    bool ok = s.vector(v);
    if (ok) s.optional_comma();
    // Followed by the next item or the section's end: where anything else follows (a face's texture index, an
    // expression) the ordinary reading takes the item.
    ok = ok && (s.ahead() == '<' || s.ahead() == '}') &&
         literal_scan_allows(s.tokens(), items, item, start->at.offset) && take(v);
    if (!ok) {
      s.reset(item, before);
      break;
    }
    ++items;
  }
  if (items > 0) literal_scan_commit(*start, s.position(), s.tokens());
  return items;
}

// `{ n,` of a mesh2 section: the declared count, truncated as POV-Ray's (int) cast does.
std::size_t ObjectParser::parse_mesh2_count(const Token& keyword, bool zero_allowed) {
  expect("{", " after '" + std::string(keyword.text) + "'");
  const Token at = peek();
  const double n = std::trunc(parse_float());
  accept(",");
  if (!(n >= (zero_allowed ? 0.0 : 1.0)) || n > 2e9)
    fail_at(at, "'" + std::string(keyword.text) + "' needs a count of " + (zero_allowed ? "zero" : "one") +
                    " or more first (read " + std::to_string(n) + ")");
  return static_cast<std::size_t>(n);
}

// After the last of `count` items: the section must close here.
void ObjectParser::expect_mesh2_section_end(const Token& keyword, std::size_t count, const std::string& items) {
  const Token t = next();
  if (!t.is("}"))
    fail_at(t, "'" + std::string(keyword.text) + "' declares " + plural(count, items) +
                   " but lists more (expected '}' after the last one)");
}

// Before item `index` of `count`: a '}' here means the section lists fewer items than it declares.
void ObjectParser::check_mesh2_item(const Token& keyword, std::size_t index, std::size_t count,
                                   const std::string& items) {
  const Token t = peek();
  if (t.is("}"))
    fail_at(t, "'" + std::string(keyword.text) + "' declares " + plural(count, items) + " but lists only " +
                   std::to_string(index));
}

// vertex_vectors / normal_vectors { n, V1, … }: single precision; normals normalised (zero → <1,0,0>, warned).
std::vector<float> ObjectParser::parse_mesh2_vectors(const Token& keyword, bool normals) {
  const std::size_t n = parse_mesh2_count(keyword, normals);
  std::vector<float> out;
  out.reserve(3 * std::min(n, kMaxReserve));
  bool zero_warned = false;
  auto add = [&](Vec3 v) {
    if (normals) {
      if (std::fabs(v.x) < kEpsilon && std::fabs(v.y) < kEpsilon && std::fabs(v.z) < kEpsilon) {
        v = {1, 0, 0};
        if (!zero_warned) warn(keyword.loc, "a normal vector in mesh2 cannot be zero: changed to <1,0,0>");
        zero_warned = true;
      }
      v = normalize(v);
    }
    out.push_back(static_cast<float>(v.x));
    out.push_back(static_cast<float>(v.y));
    out.push_back(static_cast<float>(v.z));
  };
  for (std::size_t i = 0; i < n; ++i) {
    i += scan_mesh2_items<3>(n - i, [&](const std::array<double, 3>& v) {
      add({v[0], v[1], v[2]});
      return true;
    });
    if (i == n) break;
    check_mesh2_item(keyword, i, n, "vector");
    add(parse_vector());
    accept(",");
  }
  expect_mesh2_section_end(keyword, n, "vector");
  return out;
}

// uv_vectors { n, UV1, … }: u v per vector.
std::vector<double> ObjectParser::parse_mesh2_uv_vectors(const Token& keyword) {
  const std::size_t n = parse_mesh2_count(keyword, true);
  std::vector<double> uvs;
  uvs.reserve(2 * std::min(n, kMaxReserve));
  for (std::size_t i = 0; i < n; ++i) {
    check_mesh2_item(keyword, i, n, "vector");
    // parameter level, as POV-Ray's Parse_UV_Vect: `<1, 1> <-1, 1>` are two vectors, not a comparison
    const auto [u, v] = parse_uv_vector("in uv_vectors");
    uvs.push_back(u);
    uvs.push_back(v);
    accept(",");
  }
  expect_mesh2_section_end(keyword, n, "vector");
  return uvs;
}

namespace {
// mesh2_index_triple() for a triple the scanner read: nothing where the ordinary reading reports an error.
std::optional<std::array<std::uint32_t, 3>> literal_index_triple(const std::array<double, 3>& v, std::size_t limit) {
  std::array<std::uint32_t, 3> out{};
  for (int k = 0; k < 3; ++k) {
    const double i = std::trunc(v[k]);
    if (!(i >= 0 && i < static_cast<double>(limit))) return std::nullopt;
    out[k] = static_cast<std::uint32_t>(i);
  }
  return out;
}
}  // namespace

// One index triple <a, b, c>, truncated to integers and checked against `limit` at its own position.
std::array<std::uint32_t, 3> ObjectParser::mesh2_index_triple(const Token& at, const Numeric& value,
                                                             std::size_t limit, const std::string& what) {
  const Vec3 v = value.terms == 1 ? Vec3{value.v[0], value.v[0], value.v[0]} : value.as_vec3();
  std::array<std::uint32_t, 3> out{};
  for (int k = 0; k < 3; ++k) {
    const double i = std::trunc(v[k]);
    if (!(i >= 0 && i < static_cast<double>(limit)))
      fail_at(at, what + " index " + std::to_string(static_cast<long long>(std::clamp(v[k], -1e18, 1e18))) +
                      " out of range (there are " + std::to_string(limit) + ", numbered from 0)");
    out[k] = static_cast<std::uint32_t>(i);
  }
  return out;
}

// uv_indices / normal_indices { n, <a,b,c>, … } against `limit` items.
std::vector<std::uint32_t> ObjectParser::parse_mesh2_indices(const Token& keyword, std::size_t count,
                                                            std::size_t limit, const std::string& what) {
  std::vector<std::uint32_t> out;
  out.reserve(3 * std::min(count, kMaxReserve));
  for (std::size_t i = 0; i < count; ++i) {
    i += scan_mesh2_items<3>(count - i, [&](const std::array<double, 3>& v) {
      const auto triple = literal_index_triple(v, limit);
      if (triple) out.insert(out.end(), triple->begin(), triple->end());
      return triple.has_value();
    });
    if (i == count) break;
    check_mesh2_item(keyword, i, count, "index triple");
    const Token at = peek();
    const auto triple = mesh2_index_triple(at, parse_additive(), limit, what);
    out.insert(out.end(), triple.begin(), triple.end());
    accept(",");
  }
  expect_mesh2_section_end(keyword, count, "index triple");
  return out;
}

// face_indices { n, <a,b,c> [, ti [, tj, tk]] … }. A face's texture indices are the floats that follow it; the
// first non-float item is the next face (POV-Ray's CASE_FLOAT look-ahead).
void ObjectParser::parse_mesh2_faces(const Token& keyword, std::size_t vertex_count, std::size_t texture_count,
                                    MeshData& data) {
  const std::size_t n = parse_mesh2_count(keyword, false);
  data.faces.reserve(3 * std::min(n, kMaxReserve));
  std::optional<Numeric> pending;   // the next face, read while looking for texture indices
  Token pending_at;
  for (std::size_t i = 0; i < n; ++i) {
    if (!pending) {
      i += scan_mesh2_items<3>(n - i, [&](const std::array<double, 3>& v) {
        const auto triple = literal_index_triple(v, vertex_count);
        if (!triple) return false;
        data.faces.insert(data.faces.end(), triple->begin(), triple->end());
        if (!data.face_textures.empty()) data.face_textures.insert(data.face_textures.end(), 3, -1);
        return true;
      });
      if (i == n) break;
      check_mesh2_item(keyword, i, n, "face");
    }
    const Token at = pending ? pending_at : peek();
    const Numeric face = pending ? *pending : parse_additive();
    pending.reset();
    const auto triple = mesh2_index_triple(at, face, vertex_count, "face_indices vertex");
    data.faces.insert(data.faces.end(), triple.begin(), triple.end());
    accept(",");
    std::array<std::int32_t, 3> tex{-1, -1, -1};
    for (int k = 0; k < 3; ++k) {
      const Token t = peek();
      if (t.is("<") || t.is("}")) break;
      const Numeric x = parse_additive();
      if (x.terms != 1) {
        pending = x;
        pending_at = t;
        break;
      }
      const double ti = std::trunc(x.v[0]);
      if (!(ti >= 0 && ti < static_cast<double>(texture_count)))
        fail_at(t, "texture index " + std::to_string(static_cast<long long>(std::clamp(x.v[0], -1e18, 1e18))) +
                       " out of range in mesh2 (its texture_list has " + std::to_string(texture_count) + ")");
      tex[k] = static_cast<std::int32_t>(ti);
      accept(",");
    }
    if (tex[1] < 0 || tex[2] < 0) tex[1] = tex[2] = -1;   // one texture unless all three are given
    if (tex[0] >= 0 || !data.face_textures.empty()) {   // the array starts with the first textured face
      data.face_textures.resize(3 * i, -1);
      data.face_textures.insert(data.face_textures.end(), tex.begin(), tex.end());
    }
  }
  if (pending) fail_at(pending_at, "'face_indices' declares " + plural(n, "face") + " but lists more");
  expect_mesh2_section_end(keyword, n, "face");
}

namespace {
// Drops faces of zero area (on the single-precision vertices, as POV-Ray computes them) from every per-face
// array; returns how many.
std::size_t drop_degenerate_faces(MeshData& data) {
  std::size_t kept = 0;
  const std::size_t count = data.triangle_count();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 p1 = data.vertex(data.faces[3 * i]), p2 = data.vertex(data.faces[3 * i + 1]),
               p3 = data.vertex(data.faces[3 * i + 2]);
    if (length(cross(p3 - p1, p2 - p1)) == 0.0) continue;
    for (int k = 0; k < 3; ++k) {
      data.faces[3 * kept + k] = data.faces[3 * i + k];
      if (!data.face_normals.empty()) data.face_normals[3 * kept + k] = data.face_normals[3 * i + k];
      if (!data.face_textures.empty()) data.face_textures[3 * kept + k] = data.face_textures[3 * i + k];
      if (!data.face_uvs.empty()) data.face_uvs[3 * kept + k] = data.face_uvs[3 * i + k];
    }
    ++kept;
  }
  data.faces.resize(3 * kept);
  if (!data.face_normals.empty()) data.face_normals.resize(3 * kept);
  if (!data.face_textures.empty()) data.face_textures.resize(3 * kept);
  if (!data.face_uvs.empty()) data.face_uvs.resize(3 * kept);
  return count - kept;
}

// The first `smooth_count` faces take their normal indices; a face whose three normals are equal (squared
// differences ≤ 1e-10) and every later face is flat.
void assign_face_normals(MeshData& data, std::vector<std::uint32_t> indices) {
  if (indices.empty()) return;
  const std::size_t smooth_count = indices.size() / 3;
  for (std::size_t i = 0; i < smooth_count; ++i) {
    const Vec3 n1 = data.normal(indices[3 * i]), n2 = data.normal(indices[3 * i + 1]),
               n3 = data.normal(indices[3 * i + 2]);
    const Vec3 d1 = n1 - n2, d2 = n1 - n3;
    if (!(dot(d1, d1) > kEpsilon || dot(d2, d2) > kEpsilon))
      indices[3 * i] = indices[3 * i + 1] = indices[3 * i + 2] = MeshData::flat;
  }
  indices.resize(data.faces.size(), MeshData::flat);
  data.face_normals = std::move(indices);
}
}  // namespace

Object ObjectParser::parse_mesh2(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'mesh2'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  MeshData data;
  Mesh mesh;
  for (Token t = next();; t = next()) {
    auto replaced = [&](bool had) {
      if (had) warn(t.loc, "duplicate '" + std::string(t.text) + "' block; the earlier one is ignored");
    };
    if (t.is("vertex_vectors")) { replaced(!data.vertices.empty()); data.vertices = parse_mesh2_vectors(t, false); }
    else if (t.is("normal_vectors")) { replaced(!data.normals.empty()); data.normals = parse_mesh2_vectors(t, true); }
    else if (t.is("uv_vectors")) { replaced(!data.uvs.empty()); data.uvs = parse_mesh2_uv_vectors(t); }
    else if (t.is("texture_list")) {
      const std::size_t n = parse_mesh2_count(t, true);
      for (std::size_t i = 0; i < n; ++i) {
        check_mesh2_item(t, i, n, "texture");
        const Token tex = next();
        if (!tex.is("texture")) fail_expected(tex, "'texture { … }' in mesh2's texture_list");
        mesh.textures.push_back(textures_.parse_texture_block(tex));
        accept(",");
      }
      expect_mesh2_section_end(t, n, "texture");
      break;   // POV-Ray reads the texture_list last, just before face_indices
    } else { unget(t); break; }
  }
  const Token faces = next();
  if (data.vertices.empty()) fail_at(faces, "mesh2 needs vertex_vectors before its face_indices");
  if (!faces.is("face_indices")) fail_expected(faces, "'face_indices' in mesh2");
  const std::size_t vertex_count = data.vertices.size() / 3, normal_count = data.normals.size() / 3;
  parse_mesh2_faces(faces, vertex_count, mesh.textures.size(), data);
  const std::size_t face_count = data.triangle_count();
  const std::size_t uv_count = data.uvs.size() / 2;
  bool uv_indices = false;
  std::optional<std::vector<std::uint32_t>> normal_indices;
  for (Token t = next();; t = next()) {
    if (t.is("uv_indices")) {
      if (uv_indices) fail_at(t, "only one uv_indices section is allowed in mesh2");
      uv_indices = true;
      const Token at = peek();
      if (parse_mesh2_count(t, true) != face_count)
        fail_at(at, "the number of uv_indices must equal the number of faces (" + std::to_string(face_count) + ")");
      data.face_uvs = parse_mesh2_indices(t, face_count, std::max<std::size_t>(uv_count, 1), "uv");
    } else if (t.is("normal_indices")) {
      if (normal_indices) fail_at(t, "only one normal_indices section is allowed in mesh2");
      const Token at = peek();
      const std::size_t n = parse_mesh2_count(t, true);
      if (n > face_count)
        fail_at(at, "more normal_indices than faces (" + std::to_string(face_count) + ") in mesh2");
      normal_indices = parse_mesh2_indices(t, n, normal_count, "normal");
    } else { unget(t); break; }
  }
  while (true) {
    const Token t = next();
    if (!t.is("inside_vector")) { unget(t); break; }
    data.inside_vector = parse_inside_vector();
  }
  if (!uv_indices && uv_count > 1 && uv_count != vertex_count) fail_at(faces, "mesh2 needs a uv_indices section");
  // Without uv_indices, one uv vector per vertex pairs with the vertices; a single one serves every corner
  // (POV-Ray's Parse_Mesh2). With none, every corner is <0, 0>.
  if (uv_count == 0) data.face_uvs.clear();
  else if (!uv_indices) data.face_uvs = uv_count == vertex_count ? data.faces : std::vector<std::uint32_t>(data.faces.size(), 0);
  if (!normal_indices && normal_count > 0) {
    if (normal_count != vertex_count) fail_at(faces, "mesh2 needs a normal_indices section");
    normal_indices = data.faces;   // one normal per vertex: the vertex indices are the normal indices
  }
  if (normal_indices) assign_face_normals(data, std::move(*normal_indices));
  if (const std::size_t dropped = drop_degenerate_faces(data); dropped > 0)
    warn(keyword.loc, plural(dropped, "degenerate face") + " in this mesh2 skipped (POV-Ray never hits them)");
  if (data.faces.empty()) fail_at(keyword, "no triangles in the mesh2");
  mesh.data = std::make_shared<const MeshData>(std::move(data));
  o.shape = std::move(mesh);
  extents().made(o);
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl
