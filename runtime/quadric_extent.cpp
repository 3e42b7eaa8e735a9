// POV-Ray 3.7's quadric bounding box (shape/quadrics.cpp: Quadric::Transform, Compute_BBox, Compute_Plane_Min_Max),
// reproduced for min_extent()/max_extent(). The box is kept in float, so the arithmetic below follows POV-Ray's
// order of operations (and its std::max/std::min argument order, which decides the sign of a zero) wherever a last
// bit could reach it.
#include "runtime/quadric_extent.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace povtrace {

namespace {

constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON

using Matrix4 = std::array<std::array<double, 4>, 4>;

// A 4×3 affine matrix with its implied fourth column (0, 0, 0, 1), as POV-Ray's TRANSFORM holds it.
Matrix4 full(const Matrix& m) {
  Matrix4 r{};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) r[i][j] = m.m[i][j];
    r[i][3] = i == 3 ? 1.0 : 0.0;
  }
  return r;
}

// a·b, each entry summed over k = 0..3 in order (POV-Ray's MTimesA and MTimesB compute the same sums).
Matrix4 product(const Matrix4& a, const Matrix4& b) {
  Matrix4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j];
  return r;
}

Matrix4 transpose(const Matrix4& a) {
  Matrix4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i][j] = a[j][i];
  return r;
}

// The inverse of a `matrix` transform as POV-Ray's MInvers evaluates it for an affine matrix. Its linear part comes
// out bit for bit as Matrix::inverse computes it (the same 2×2 minors over the same determinant); the translation
// row differs: MInvers takes each entry as a 3×3 minor over the determinant, the six products summed in the order
// of the rule of Sarrus, where Matrix::inverse carries the translation through the inverted linear part.
Matrix general_inverse(const Matrix& m) {
  Matrix r = m.inverse();
  const auto& a = m.m;
  const double det = m.determinant();
  // Row 3 of the inverse is (-d03, d13, -d23)/D, di3 being the 3×3 minor without row i and the fourth column,
  // its six products in MInvers's order: the three along the diagonals, then the three along the anti-diagonals.
  const double m00 = a[0][0], m01 = a[0][1], m02 = a[0][2];
  const double m10 = a[1][0], m11 = a[1][1], m12 = a[1][2];
  const double m20 = a[2][0], m21 = a[2][1], m22 = a[2][2];
  const double m30 = a[3][0], m31 = a[3][1], m32 = a[3][2];
  const double d03 = m10 * m21 * m32 + m11 * m22 * m30 + m12 * m20 * m31 - m30 * m21 * m12 - m31 * m22 * m10 -
                     m32 * m20 * m11;
  const double d13 = m00 * m21 * m32 + m01 * m22 * m30 + m02 * m20 * m31 - m30 * m21 * m02 - m31 * m22 * m00 -
                     m32 * m20 * m01;
  const double d23 = m00 * m11 * m32 + m01 * m12 * m30 + m02 * m10 * m31 - m30 * m11 * m02 - m31 * m12 * m00 -
                     m32 * m10 * m01;
  r.m[3] = {-d03 / det, d13 / det, -d23 / det};
  return r;
}

}  // namespace

ExtentBox initial_quadric_box() { return ExtentBox::huge(); }

Quadric transformed_quadric(const Quadric& q, const Matrix& m, TransformKind kind) {
  // The special inverses hold only for matrices of their kind's shape; anything else takes the general one.
  const bool no_translation = m.m[3][0] == 0.0 && m.m[3][1] == 0.0 && m.m[3][2] == 0.0;
  bool diagonal = true, identity_linear = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (i != j && m.m[i][j] != 0.0) diagonal = false;
      if (m.m[i][j] != (i == j ? 1.0 : 0.0)) identity_linear = false;
    }
  if ((kind == TransformKind::scale && !(diagonal && no_translation)) ||
      (kind == TransformKind::rotate && !no_translation) ||
      (kind == TransformKind::translate && !identity_linear))
    kind = TransformKind::other;
  Matrix inverse;
  switch (kind) {
    case TransformKind::scale:   // Compute_Scaling_Transform: the reciprocals of the factors
      inverse = Matrix::scaling({1.0 / m.m[0][0], 1.0 / m.m[1][1], 1.0 / m.m[2][2]});
      break;
    case TransformKind::rotate:   // Compute_Rotation_Transform: the transpose of the rotation
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inverse.m[i][j] = m.m[j][i];
      break;
    case TransformKind::translate:   // Compute_Translation_Transform: the negated vector
      inverse = Matrix::translation({-m.m[3][0], -m.m[3][1], -m.m[3][2]});
      break;
    case TransformKind::other:
      inverse = general_inverse(m);
      break;
  }
  return transformed_quadric_by_inverse(q, inverse);
}

Quadric transformed_quadric_by_inverse(const Quadric& q, const Matrix& inverse) {
  // The quadric as the row-vector form p·Q·pᵀ, p = [x y z 1], each cross term once, above the diagonal
  // (Quadric_To_Matrix). With p = p'·inverse for a world point p', the world quadric is inverse·Q·inverseᵀ.
  Matrix4 c{};
  c[0][0] = q.square.x;
  c[1][1] = q.square.y;
  c[2][2] = q.square.z;
  c[0][1] = q.mixed.x;
  c[0][2] = q.mixed.y;
  c[1][2] = q.mixed.z;
  c[0][3] = q.linear.x;
  c[1][3] = q.linear.y;
  c[2][3] = q.linear.z;
  c[3][3] = q.constant;
  const Matrix4 inv = full(inverse);
  const Matrix4 r = product(product(inv, c), transpose(inv));   // POV-Ray's order: inverse·Q first
  // Matrix_To_Quadric: the product is no longer triangular; each term is the sum of its symmetric pair.
  Quadric out;
  out.square = {r[0][0], r[1][1], r[2][2]};
  out.mixed = {r[0][1] + r[1][0], r[0][2] + r[2][0], r[1][2] + r[2][1]};
  out.linear = {r[0][3] + r[3][0], r[1][3] + r[3][1], r[2][3] + r[3][2]};
  out.constant = r[3][3];
  return out;
}

namespace {

// The axis rule of Compute_Plane_Min_Max for a plane N·p = d: an axis whose normal is the only non-negligible
// component is bounded on the side the normal points to. POV-Ray does not normalise N here (in the Trans form it
// need not be unit), and with a unit N a negative component bounds from below at -d.
void axis_plane_range(Vec3 normal, double d, Vec3& min, Vec3& max) {
  min = {-kBoundHuge / 2, -kBoundHuge / 2, -kBoundHuge / 2};
  max = {kBoundHuge / 2, kBoundHuge / 2, kBoundHuge / 2};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (std::fabs(normal[i]) < kEpsilon && std::fabs(normal[j]) < kEpsilon) {
      if (normal[k] > 0.0)
        max[k] = d;
      else
        min[k] = -d;
    }
  }
}

}  // namespace

void plane_min_max(Vec3 normal, double distance, const Matrix& world_from_object, Vec3& min, Vec3& max) {
  if (world_from_object == Matrix::identity()) return axis_plane_range(normal, distance, min, max);
  // The world plane: the normal by the inverse transpose, made unit as Plane::Scale does (times the reciprocal of
  // its length), and the distance of the moved point normal·distance along it.
  const Vec3 n = world_from_object.inverse().normal_from_inverse(normal);
  const Vec3 unit = n * (1.0 / length(n));
  const Vec3 on = world_from_object.point(normal * distance);
  axis_plane_range(unit, dot(unit, on), min, max);
}

void plane_min_max_with_trans(Vec3 normal, double distance, const Matrix& trans, Vec3& min, Vec3& max) {
  // MInvTransNormal: each component the dot product of the normal with a row of Trans's linear part.
  const Vec3 n = trans.normal_from_inverse(normal);
  // MInvTransPoint: that vector carried back by Trans's inverse, as a point.
  const Vec3 p = general_inverse(trans).point(n);
  // POV-Ray's Distance is the negated written distance, so its -Distance is `distance`.
  const double d = distance - p.x * n.x - p.y * n.y - p.z * n.z + 1.0;
  axis_plane_range(n, d, min, max);
}

namespace {

// Compute_BBox's first step: coefficients below EPSILON in magnitude count as 0.
double zeroed(double v) { return std::fabs(v) < kEpsilon ? 0.0 : v; }

// The largest of the two radii a cone or hyperboloid along an axis has at the two ends of the clip range.
template <typename RadiusAt>
double wider_end(double lo, double hi, RadiusAt radius_at) {
  return std::max(radius_at(lo), radius_at(hi));
}

}  // namespace

QuadricBox quadric_box(const Quadric& current, Vec3 clip_min, Vec3 clip_max, const ExtentBox& old) {
  // Compute_BBox names the coefficients of the symmetric form A x² + E y² + H z² + 2B xy + 2C xz + 2F yz +
  // 2D x + 2G y + 2I z + J; here square[k] plays A, E, H and half_linear[k] D, G, I.
  double square[3] = {zeroed(current.square.x), zeroed(current.square.y), zeroed(current.square.z)};
  const double half_mixed[3] = {zeroed(current.mixed.x / 2.0), zeroed(current.mixed.y / 2.0),
                                zeroed(current.mixed.z / 2.0)};
  double half_linear[3] = {zeroed(current.linear.x / 2.0), zeroed(current.linear.y / 2.0),
                           zeroed(current.linear.z / 2.0)};
  double constant = zeroed(current.constant);

  // A quadric with a cross term is not in the axis-aligned normal form the cases below need (bringing it there
  // means diagonalising its matrix, which POV-Ray does not do): the clip range itself is the box, if smaller.
  if (half_mixed[0] != 0.0 || half_mixed[1] != 0.0 || half_mixed[2] != 0.0) {
    const double clip_volume =
        (clip_max.x - clip_min.x) * (clip_max.y - clip_min.y) * (clip_max.z - clip_min.z);
    return {clip_volume < old.volume() ? ExtentBox::from_min_max(clip_min, clip_max) : old, false};
  }

  // Linear terms: move the quadric so that they vanish along each axis with a square term (its centre there);
  // along an axis with a linear term only (a paraboloid's axis) to where the surface meets the axis. The
  // constant follows the move; the clip range moves the other way, and the box comes back at the end.
  Vec3 shift{0.0, 0.0, 0.0};
  if (half_linear[0] != 0.0 || half_linear[1] != 0.0 || half_linear[2] != 0.0) {
    for (int k = 0; k < 3; ++k) {
      if (square[k] != 0.0)
        shift[k] = -half_linear[k] / square[k];
      else if (half_linear[k] != 0.0)
        shift[k] = constant / (2.0 * half_linear[k]);
      else
        shift[k] = 0.0;
    }
    for (int k = 0; k < 3; ++k) half_linear[k] += square[k] * shift[k];
    constant -= shift.x * (square[0] * shift.x + 2.0 * half_linear[0]) +
                shift.y * (square[1] * shift.y + 2.0 * half_linear[1]) +
                shift.z * (square[2] * shift.z + 2.0 * half_linear[2]);
  }
  clip_min -= shift;
  clip_max -= shift;

  // The sign of the whole equation is free; the cases below take A (the x² term) non-negative.
  if (square[0] < 0.0) {
    for (int k = 0; k < 3; ++k) {
      square[k] = -square[k];
      half_linear[k] = -half_linear[k];
    }
    constant = -constant;
  }

  Vec3 lo{-kBoundHuge / 2, -kBoundHuge / 2, -kBoundHuge / 2}, hi{kBoundHuge / 2, kBoundHuge / 2, kBoundHuge / 2};
  const double a = square[0], e = square[1], h = square[2], j = constant;

  // Ellipsoid x²/a² + y²/b² + z²/c² = 1 and the cylinders along x, y, z (that axis's square term 0): the
  // semi-axes √(-J/coefficient) on every axis with a square term.
  const bool ellipsoid = a > 0.0 && e > 0.0 && h > 0.0 && j < 0.0;
  const bool cylinder = j < 0.0 && ((a == 0.0 && e > 0.0 && h > 0.0) || (a > 0.0 && e == 0.0 && h > 0.0) ||
                                    (a > 0.0 && e > 0.0 && h == 0.0));
  if (ellipsoid || cylinder)
    for (int k = 0; k < 3; ++k)
      if (square[k] != 0.0) {
        const double semi = std::sqrt(-j / square[k]);
        lo[k] = -semi;
        hi[k] = semi;
      }

  // Cones (J = 0) and one-sheet hyperboloids along an axis: that axis's square term has the opposite sign to the
  // other two (with A non-negative: x when E and H are negative, y when only E is, z when only H is). The other
  // axes are bounded by the wider of the cross-sections at the two ends of the clip range along it.
  int axis = -1;
  if (a > 0.0 && e < 0.0 && h < 0.0) axis = 0;
  if (a > 0.0 && e < 0.0 && h > 0.0) axis = 1;
  if (a > 0.0 && e > 0.0 && h < 0.0) axis = 2;
  if (axis >= 0) {
    const double odd = square[axis];
    if (j == 0.0) {
      // The cone's semi-axes at unit distance: √(1/|coefficient|) each, the radius at t along the axis
      // |t·r_other/r_axis|.
      const double r_axis = std::sqrt(1.0 / std::fabs(odd));
      for (int k = 0; k < 3; ++k) {
        if (k == axis) continue;
        const double r_k = std::sqrt(1.0 / std::fabs(square[k]));
        const double r = wider_end(clip_min[axis], clip_max[axis],
                                   [&](double t) { return std::fabs(t * r_k / r_axis); });
        lo[k] = -r;
        hi[k] = r;
      }
    } else if ((j > 0.0) == (odd > 0.0)) {
      // One sheet: the cross-section at t satisfies |coefficient_k|·r² = 1 + |odd|·t². POV-Ray takes 1 for |J| here
      // (right for the normalised form with J = ±1 only), so a hyperboloid with another constant gets the radii
      // of x²/a² ... = 1 scaled as if J were ±1.
      for (int k = 0; k < 3; ++k) {
        if (k == axis) continue;
        const double coefficient = std::fabs(square[k]);
        const double r = wider_end(clip_min[axis], clip_max[axis], [&](double t) {
          const double d = 1.0 + std::fabs(odd) * (t * t);
          return std::sqrt(d / coefficient);
        });
        lo[k] = -r;
        hi[k] = r;
      }
    }
  }

  // Paraboloids along an axis: no square term there, a linear term, the other two square terms of one sign,
  // J = 0 (after the move, the vertex at the origin). 2·l·t = -(the other terms), so t has the sign opposite to
  // l·(the other coefficients): the range along the axis is cut at 0 on the far side, and the cross-section is
  // widest at one end of what remains, radius √|2·l·t/coefficient|.
  for (int k = 0; k < 3; ++k) {
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    const double l = half_linear[k];
    if (!(square[k] == 0.0 && l != 0.0 && square[u] * square[v] > 0.0 && j == 0.0)) continue;
    // Which side: POV-Ray tests l·E for x, and the sign of l alone for y and z (A is positive there); the same.
    const double side = k == 0 ? l * square[1] : l;
    // POV-Ray bounds the axis with max(0, t) and min(0, t) for x and y but max(t, 0) and min(t, 0) for z, which
    // keeps a -0 differently (std::max and std::min return their first argument on a tie).
    auto clamp_up = [&](double t) { return k == 2 ? std::max(t, 0.0) : std::max(0.0, t); };
    auto clamp_down = [&](double t) { return k == 2 ? std::min(t, 0.0) : std::min(0.0, t); };
    const double t_lo = side < 0 ? clamp_up(clip_min[k]) : clip_min[k];
    const double t_hi = side > 0 ? clamp_down(clip_max[k]) : clip_max[k];
    for (const int w : {u, v}) {
      const double coefficient = square[w];
      const double r = std::max(std::sqrt(std::fabs(2.0 * l * t_lo / coefficient)),
                                std::sqrt(std::fabs(2.0 * l * t_hi / coefficient)));
      lo[w] = -r;
      hi[w] = r;
    }
    if (side < 0) lo[k] = clamp_up(clip_min[k]);
    if (side > 0) hi[k] = clamp_down(clip_max[k]);
  }

  // The shape's box within the clip range (kept as it falls: an empty range gives negative lengths).
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::max(lo[k], clip_min[k]);
    hi[k] = std::min(hi[k], clip_max[k]);
  }
  const double volume = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
  if (!(volume < old.volume())) return {old, false};
  ExtentBox box = ExtentBox::from_min_max(lo + shift, hi + shift);
  return {box.wider_than_critical() ? ExtentBox::huge() : box, true};
}

QuadricBox parsed_quadric_box(const Quadric& written) {
  return quadric_box(written, {-kBoundHuge, -kBoundHuge, -kBoundHuge}, {kBoundHuge, kBoundHuge, kBoundHuge},
                     initial_quadric_box());
}

}  // namespace povtrace
