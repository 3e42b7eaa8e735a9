// Vocabulary types shared by the scene description and the renderer: a double-precision 3-vector and an
// affine transform. Header-only, no dependencies, so the description stays plain data.
//
// Convention (POV-Ray's, see ../shared/docs/povray-sdl-and-geometry.md §9): points are row vectors,
// p' = [x y z 1]·M, and composing "A then B" is A·B. Matrix stores the 4×3 affine part m[row][col].
#pragma once

#include <array>
#include <cmath>

namespace povtrace {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  constexpr Vec3& operator+=(Vec3 b) { x += b.x; y += b.y; z += b.z; return *this; }
  constexpr Vec3& operator-=(Vec3 b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
  friend constexpr bool operator==(Vec3, Vec3) = default;
};

constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return a / length(a); }
constexpr Vec3 min(Vec3 a, Vec3 b) { return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z}; }
constexpr Vec3 max(Vec3 a, Vec3 b) { return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z}; }

// Affine transform as a 4×3 matrix (rows 0–2 linear part, row 3 translation).
struct Matrix {
  std::array<std::array<double, 3>, 4> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}}};

  static constexpr Matrix identity() { return {}; }
  static constexpr Matrix translation(Vec3 v) {
    Matrix r;
    r.m[3] = {v.x, v.y, v.z};
    return r;
  }
  static constexpr Matrix scaling(Vec3 v) {
    Matrix r;
    r.m[0][0] = v.x;
    r.m[1][1] = v.y;
    r.m[2][2] = v.z;
    return r;
  }
  // Rotation about one axis (0 = x, 1 = y, 2 = z) by `degrees`, with POV-Ray's sense (§9: rotate y*90 takes
  // +x to −z).
  static Matrix rotation_axis(int axis, double degrees) {
    const double a = degrees * (M_PI / 180.0), c = std::cos(a), s = std::sin(a);
    Matrix r;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    r.m[i][i] = c;
    r.m[i][j] = s;
    r.m[j][i] = -s;
    r.m[j][j] = c;
    return r;
  }
  // rotate <a,b,c>: about x by a, then y by b, then z by c.
  static Matrix rotation(Vec3 degrees) {
    return rotation_axis(0, degrees.x) * rotation_axis(1, degrees.y) * rotation_axis(2, degrees.z);
  }

  // "this, then b" (row-vector convention).
  friend constexpr Matrix operator*(const Matrix& a, const Matrix& b) {
    Matrix r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        if (i == 3) s += b.m[3][j];
        r.m[i][j] = s;
      }
    return r;
  }

  constexpr Vec3 point(Vec3 p) const {
    return {p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0],
            p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1],
            p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2] + m[3][2]};
  }
  constexpr Vec3 vector(Vec3 v) const {
    return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
            v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
  }
  // Transforms a surface normal given *this* as the inverse of the object's transform (n' = M⁻ᵀ n).
  constexpr Vec3 normal_from_inverse(Vec3 n) const {
    return {dot(n, {m[0][0], m[0][1], m[0][2]}), dot(n, {m[1][0], m[1][1], m[1][2]}),
            dot(n, {m[2][0], m[2][1], m[2][2]})};
  }

  constexpr double determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  // Inverse of the affine map; the caller guarantees a non-singular linear part (scale 0 is refused at parse).
  constexpr Matrix inverse() const {
    const double d = determinant();
    Matrix r;
    r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / d;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / d;
    r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / d;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / d;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / d;
    r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / d;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / d;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / d;
    const Vec3 t = r.vector({m[3][0], m[3][1], m[3][2]});
    r.m[3] = {-t.x, -t.y, -t.z};
    return r;
  }
  friend constexpr bool operator==(const Matrix&, const Matrix&) = default;
};

}  // namespace povtrace
