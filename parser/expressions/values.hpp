// The values an SDL identifier can hold (povray-sdl-and-geometry.md §3, §4 Parse_RValue). Identifiers are
// typed by what was last stored in them; the interpreter branches on that type.
#pragma once

#include <limits>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/description.hpp"
#include "parser/lexing/lexer.hpp"
#include "runtime/splines.hpp"

namespace povtrace::sdl {

// Up to five doubles plus a term count (1 float, 2 uv, 3 vector, 4 4-D, 5 colour), §5 "Terms and promotion".
struct Numeric {
  std::array<double, 5> v{};
  int terms = 1;
  bool colour = false;   // produced by a colour form (rgb…, colour id): a 5-term value

  static Numeric scalar(double x) { Numeric n; n.v[0] = x; return n; }
  static Numeric vector(Vec3 p) { Numeric n; n.v = {p.x, p.y, p.z, 0, 0}; n.terms = 3; return n; }
  static Numeric from_colour(const Colour& c) {
    Numeric n; n.v = {c.r, c.g, c.b, c.f, c.t}; n.terms = 5; n.colour = true; return n;
  }
  Vec3 as_vec3() const { return {v[0], v[1], v[2]}; }
  // POV-Ray stores colours in single precision (a declared rgb 0.1 reads back as 0.100000001490) while floats
  // and vectors stay double: colour values are rounded to float wherever they are stored. Beyond float's range
  // they saturate at the largest float: POV-Ray's become infinite, and shading then makes NaN pixels of them
  // (ambient 0 times infinity; found by the render fuzzer with rgb 1e59).
  Numeric stored() const {
    if (!colour) return *this;
    Numeric n = *this;
    for (double& c : n.v) c = single_saturating(c);
    return n;
  }
  static double single_saturating(double c) {
    constexpr double top = std::numeric_limits<float>::max();
    return static_cast<float>(c < -top ? -top : (c > top ? top : c));
  }
  Colour as_colour() const { return {v[0], v[1], v[2], v[3], v[4]}; }
};

// Either a geometric object or a light source: `object { L }` works for both, as in POV-Ray.
using SceneItem = std::variant<Object, Light>;

struct MacroDefinition {
  const SourceFile* file = nullptr;
  FileTokens* tokens = nullptr;     // file's tokens
  std::size_t body = 0;             // index of the first token after the parameter list's ')'
  std::vector<std::string> parameters;
  std::vector<std::uint32_t> parameter_ids;   // their SymbolTable::NameIds: a call binds without hashing
  SourceLoc loc;
};

// A macro parameter bound to a caller's variable: reads and writes go through to it (§4 #macro).
// No name text: the id is always known where an alias is made (the name is bound, so interned), and a macro
// call makes one per alias argument.
struct Alias {
  std::size_t table = 0;            // symbol table level holding the variable
  std::uint32_t id = 0;             // the name's SymbolTable::NameId
};

// material { texture interior } as a declared value.
struct MaterialValue {
  std::shared_ptr<const Texture> texture;
  std::shared_ptr<const Texture> interior_texture;
  std::optional<Interior> interior;
};

// A declared value povtrace parses but does not use yet (a colour_map, a media, a sky_sphere, …): its
// keyword and the feature it would need when it reaches the scene.
struct OpaqueValue {
  std::string keyword;
  UnsupportedFeature feature;
};

// A declared density { } (a pigment whose maps are density maps), used as `density { D … }`.
struct DensityValue {
  Pigment density;
};

// A declared color_map, pigment_map or texture_map (`#declare M = color_map { … }`), used as `color_map { M }`.
struct BlendMapValue {
  bool pigments = false;   // pigment_map
  bool textures = false;   // texture_map: the entries are in `texture_entries`
  bool densities = false;  // density_map: the entries' pigments are densities
  std::vector<MapEntry> entries;
  std::vector<TextureMapEntry> texture_entries;
};

// A large value held behind a shared pointer and immutable once made, so that a Value stays small: the symbol
// table holds one Value per name (100,000 declared vectors must not each carry room for a pigment), and copying a
// declared pigment, camera or macro shares it instead of copying it.
template <class T> class Boxed {
 public:
  Boxed(T value) : p_(std::make_shared<const T>(std::move(value))) {}   // NOLINT: implicit, as T converted
  const T& operator*() const { return *p_; }
  const T* operator->() const { return p_.get(); }

 private:
  std::shared_ptr<const T> p_;
};

struct ArrayValue;   // array[N]… (below: it holds Values)
struct UserFile;     // a file opened by #fopen (file_io.cpp)
struct FunctionValue;   // function { … } (function_value.hpp)

using Value = std::variant<Numeric, std::string, std::shared_ptr<const SceneItem>, std::shared_ptr<const Texture>,
                           Boxed<Pigment>, Boxed<Finish>, Boxed<Interior>, Boxed<Camera>, Boxed<MacroDefinition>,
                           Alias, Boxed<Matrix>, Boxed<OpaqueValue>, Boxed<MaterialValue>,
                           std::shared_ptr<ArrayValue>, std::shared_ptr<UserFile>,
                           std::shared_ptr<const FunctionValue>, Boxed<SkySphere>, BlendMapValue, Boxed<Normal>,
                           Boxed<SplineValue>, Boxed<Media>, Boxed<DensityValue>>;

// array[N][M]… (§3): 1 to 5 dimensions, elements in row-major order. An element is defined once assigned; the
// first value stored fixes the element type of the whole array. Arrays are values: #declare B = A copies
// (deep_copy), element assignment changes the array in place.
struct ArrayValue {
  std::vector<std::size_t> sizes;
  std::vector<std::optional<Value>> elements;
  std::string type;   // array_type_of() of the stored values; empty while none is stored

  std::shared_ptr<ArrayValue> deep_copy() const;
};

// The value an array element token stands for (Token::element): `A[i][j]` resolved where it is read.
struct TokenValue {
  Value value;
};

// The type an array element must keep (§3): the numeric types by term count (float, 2-D vector, vector,
// 4-D vector, colour), "object" for objects and lights, otherwise value_type_name.
std::string array_type_of(const Value& v);

// A human-readable name of a value's type for error messages ("float", "object", "texture", ...).
std::string value_type_name(const Value& v);

}  // namespace povtrace::sdl
