//! Fixed-point vectors and affine transforms (setup side: may multiply and
//! divide, in `i64`).
//!
//! Coordinates are Q16.16 ([`I16F16`]). The documented ranges, enforced by
//! every constructor and every operation (a [`SceneError::OutOfRange`] or
//! [`SceneError::NonPositive`] otherwise, never a wrap):
//!
//! - world and model coordinates: `|c| <= WORLD_LIMIT = 4096` units
//!   (`2^28` in Q16.16 bits);
//! - the linear part of a [`Transform`] (rotation times scale): every entry
//!   `|m| <= MATRIX_LIMIT = 4096` (`2^28` bits); scale factors in
//!   `(0, 4096]`;
//! - the translation: within the world range.
//!
//! A product of an entry and a coordinate is below `2^56`, a row of three
//! plus a translation below `2^58`: `i64` holds every intermediate, and the
//! result is checked against the world range before it is narrowed.
//! Every narrowing `>> 16` rounds to nearest (half up).

use fixed::types::I16F16;

use super::trig::{Angle, ONE};
use super::SceneError;

/// Largest `|coordinate|` of a model or world point, in units.
pub const WORLD_LIMIT: i32 = 4096;
/// Largest `|entry|` of the linear part of a [`Transform`].
pub const MATRIX_LIMIT: i32 = 4096;

pub(crate) const WORLD_LIMIT_BITS: i64 = (WORLD_LIMIT as i64) << 16;
const MATRIX_LIMIT_BITS: i64 = (MATRIX_LIMIT as i64) << 16;

/// Rounds a Q32 product to Q16 (half up).
pub(crate) const fn round16(v: i64) -> i64 {
    (v + (1 << 15)) >> 16
}

/// A point or direction in Q16.16 fixed point.
///
/// ```
/// use softedge::scene3d::Vec3;
/// use fixed::types::I16F16;
/// let v = Vec3::from_int(1, -2, 3);
/// assert_eq!(v.y, I16F16::from_num(-2));
/// assert_eq!(Vec3::from_bits([65536, 0, 32768]), Vec3::new(I16F16::ONE, I16F16::ZERO, I16F16::from_num(0.5)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Vec3 {
    /// x.
    pub x: I16F16,
    /// y.
    pub y: I16F16,
    /// z.
    pub z: I16F16,
}

impl Vec3 {
    /// The origin.
    pub const ZERO: Self = Self::from_bits([0; 3]);

    /// A vector from its components.
    pub const fn new(x: I16F16, y: I16F16, z: I16F16) -> Self {
        Self { x, y, z }
    }

    /// A vector from integer components (saturating at the `I16F16` range,
    /// which is beyond [`WORLD_LIMIT`] anyway).
    pub const fn from_int(x: i32, y: i32, z: i32) -> Self {
        Self::from_bits([sat_int(x), sat_int(y), sat_int(z)])
    }

    /// A vector from raw Q16.16 bits.
    pub const fn from_bits(b: [i32; 3]) -> Self {
        Self {
            x: I16F16::from_bits(b[0]),
            y: I16F16::from_bits(b[1]),
            z: I16F16::from_bits(b[2]),
        }
    }

    /// The raw Q16.16 bits.
    pub const fn to_bits(self) -> [i32; 3] {
        [self.x.to_bits(), self.y.to_bits(), self.z.to_bits()]
    }

    pub(crate) const fn wide(self) -> [i64; 3] {
        let b = self.to_bits();
        [b[0] as i64, b[1] as i64, b[2] as i64]
    }

    /// `Ok(self)` when every component is within [`WORLD_LIMIT`].
    pub const fn check(self) -> Result<Self, SceneError> {
        match narrow_world(self.wide()) {
            Ok(_) => Ok(self),
            Err(e) => Err(e),
        }
    }
}

const fn sat_int(v: i32) -> i32 {
    if v > i16::MAX as i32 {
        i32::MAX
    } else if v < i16::MIN as i32 {
        i32::MIN
    } else {
        v << 16
    }
}

/// Narrows `i64` Q16 components to a [`Vec3`], checking the world range.
pub(crate) const fn narrow_world(v: [i64; 3]) -> Result<Vec3, SceneError> {
    let mut k = 0;
    while k < 3 {
        if v[k] > WORLD_LIMIT_BITS || v[k] < -WORLD_LIMIT_BITS {
            return Err(SceneError::OutOfRange);
        }
        k += 1;
    }
    Ok(Vec3::from_bits([v[0] as i32, v[1] as i32, v[2] as i32]))
}

/// The direction of `v` scaled to length `2^bits` (`bits <= 30`), or `None`
/// for the zero vector. Works for any `|v_i| < 2^62`: `v` is first shifted so
/// its largest component lies in `[2^29, 2^30)`, which keeps `|v|^2 < 2^62`
/// and the division precise to `2^-29`.
pub(crate) fn normalize(v: [i64; 3], bits: u32) -> Option<[i64; 3]> {
    let m = v[0].unsigned_abs() | v[1].unsigned_abs() | v[2].unsigned_abs();
    if m == 0 {
        return None;
    }
    let top = 63 - m.leading_zeros(); // highest set bit of the largest
    let v = if top > 29 {
        let s = top - 29;
        v.map(|c| c >> s)
    } else {
        let s = 29 - top;
        v.map(|c| c << s)
    };
    let len2 = v.iter().map(|c| (c * c) as u64).sum::<u64>();
    let len = len2.isqrt() as i64; // >= 2^29 - 1
                                   // |c| < 2^30 and bits <= 30: c << bits < 2^60.
    Some(v.map(|c| div_round(c << bits, len)))
}

/// `round(a / b)` for `b > 0` (halves away from zero).
pub(crate) const fn div_round(a: i64, b: i64) -> i64 {
    // Callers divide by positive lengths; a zero divisor gives 0 rather
    // than a panic path (firmware builds must link without one).
    if b <= 0 {
        return 0;
    }
    if a >= 0 {
        (a + b / 2) / b
    } else {
        -((-a + b / 2) / b)
    }
}

/// `a x b` of two Q-format vectors, in the product format (`|a_i b_j| < 2^62`
/// is the caller's duty).
pub(crate) const fn cross(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// An affine transform `p -> M p + t` (3x4 matrix), entries in Q16.16.
///
/// Build one from [`rotation_x`](Self::rotation_x) etc. and chain them with
/// [`then`](Self::then): `a.then(&b)` applies `a` first.
///
/// ```
/// use softedge::scene3d::{Angle, Transform, Vec3};
/// let t = Transform::rotation_z(Angle::from_degrees(90))
///     .then(&Transform::translation(Vec3::from_int(10, 0, 0)).unwrap())
///     .unwrap();
/// assert_eq!(t.apply(Vec3::from_int(1, 0, 0)), Ok(Vec3::from_int(10, 1, 0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Transform {
    /// Linear part, rows, Q16.16 bits.
    m: [[i32; 3]; 3],
    /// Translation, Q16.16 bits.
    t: [i32; 3],
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Transform {
    /// The identity.
    pub const IDENTITY: Self = Self {
        m: [[ONE, 0, 0], [0, ONE, 0], [0, 0, ONE]],
        t: [0; 3],
    };

    /// A translation by `v` (within the world range).
    pub const fn translation(v: Vec3) -> Result<Self, SceneError> {
        match v.check() {
            Ok(v) => Ok(Self {
                m: Self::IDENTITY.m,
                t: v.to_bits(),
            }),
            Err(e) => Err(e),
        }
    }

    /// A uniform scale by `s`, `0 < s <= MATRIX_LIMIT`.
    pub const fn scale(s: I16F16) -> Result<Self, SceneError> {
        Self::scale_xyz(Vec3::new(s, s, s))
    }

    /// A scale by `s.x`, `s.y`, `s.z` along the axes, each in
    /// `(0, MATRIX_LIMIT]` (a mirror would turn meshes inside out).
    pub const fn scale_xyz(s: Vec3) -> Result<Self, SceneError> {
        let b = s.to_bits();
        let mut k = 0;
        while k < 3 {
            if b[k] <= 0 {
                return Err(SceneError::NonPositive);
            }
            if b[k] as i64 > MATRIX_LIMIT_BITS {
                return Err(SceneError::OutOfRange);
            }
            k += 1;
        }
        Ok(Self {
            m: [[b[0], 0, 0], [0, b[1], 0], [0, 0, b[2]]],
            t: [0; 3],
        })
    }

    /// A rotation by `a` about the x axis (y towards z).
    pub const fn rotation_x(a: Angle) -> Self {
        let (s, c) = (a.sin_q16(), a.cos_q16());
        Self {
            m: [[ONE, 0, 0], [0, c, -s], [0, s, c]],
            t: [0; 3],
        }
    }

    /// A rotation by `a` about the y axis (z towards x).
    pub const fn rotation_y(a: Angle) -> Self {
        let (s, c) = (a.sin_q16(), a.cos_q16());
        Self {
            m: [[c, 0, s], [0, ONE, 0], [-s, 0, c]],
            t: [0; 3],
        }
    }

    /// A rotation by `a` about the z axis (x towards y).
    pub const fn rotation_z(a: Angle) -> Self {
        let (s, c) = (a.sin_q16(), a.cos_q16());
        Self {
            m: [[c, -s, 0], [s, c, 0], [0, 0, ONE]],
            t: [0; 3],
        }
    }

    /// `self` followed by `next` (the matrix product `next * self`), or
    /// [`SceneError::OutOfRange`] when an entry leaves its range.
    pub fn then(&self, next: &Transform) -> Result<Self, SceneError> {
        let mut m = [[0i32; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                let v = round16(
                    (0..3)
                        .map(|k| i64::from(next.m[i][k]) * i64::from(self.m[k][j]))
                        .sum(),
                );
                if v.abs() > MATRIX_LIMIT_BITS {
                    return Err(SceneError::OutOfRange);
                }
                m[i][j] = v as i32;
            }
        }
        let moved = next.apply_bits(self.t.map(i64::from));
        let t = narrow_world(moved)?.to_bits();
        Ok(Self { m, t })
    }

    /// `M p + t`, or [`SceneError::OutOfRange`] outside the world range.
    pub fn apply(&self, p: Vec3) -> Result<Vec3, SceneError> {
        narrow_world(self.apply_bits(p.wide()))
    }

    /// `M p + t` in `i64` Q16 bits (`|p_i| <= 2^28`: result below `2^58`).
    pub(crate) fn apply_bits(&self, p: [i64; 3]) -> [i64; 3] {
        let mut out = [0i64; 3];
        for (o, (row, t)) in out.iter_mut().zip(self.m.iter().zip(self.t)) {
            let dot: i64 = row.iter().zip(p).map(|(&m, c)| i64::from(m) * c).sum();
            *o = round16(dot) + i64::from(t);
        }
        out
    }

    /// The matrix that maps normals: the cofactor matrix of `M`
    /// (`det(M) * M^-T`, right for any non-uniform scale), scaled so its
    /// largest entry has 30 bits. Directions only: its results are
    /// normalised. `None` when all cofactors vanish (rank below 2).
    pub(crate) fn normal_matrix(&self) -> Option<NormalMatrix> {
        let a = self.m.map(|r| r.map(i64::from));
        let mut c = [[0i64; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
                let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
                // Cyclic indices give the signed cofactor directly.
                c[i][j] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];
            }
        }
        // Entries below 2^28 bits: cofactors below 2^57. With positive scale
        // factors det(M) > 0, so the cofactors keep the normals' sense.
        let m = c.iter().flatten().fold(0u64, |m, v| m | v.unsigned_abs());
        if m == 0 {
            return None;
        }
        let top = 63 - m.leading_zeros();
        let shift = top.saturating_sub(29);
        Some(NormalMatrix {
            m: c.map(|r| r.map(|v| v >> shift)),
        })
    }
}

/// Maps model normals to world normals (see [`Transform::normal_matrix`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct NormalMatrix {
    m: [[i64; 3]; 3],
}

impl NormalMatrix {
    /// The world direction of the model normal `n` (any length up to
    /// `2^17`), unit length in Q30; `None` for a zero normal.
    pub(crate) fn apply(&self, n: [i64; 3]) -> Option<[i64; 3]> {
        // |m| < 2^30, |n| <= 2^17: each product < 2^47.
        let v = self
            .m
            .map(|row| row.iter().zip(n).map(|(&m, c)| m * c).sum::<i64>());
        normalize(v, 30)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_then_inverse_rotation_is_identity_within_rounding() {
        let a = Angle::from_degrees(37);
        let t = Transform::rotation_y(a)
            .then(&Transform::rotation_y(Angle(0u16.wrapping_sub(a.0))))
            .unwrap();
        let p = t.apply(Vec3::from_int(100, -50, 7)).unwrap().to_bits();
        let want = Vec3::from_int(100, -50, 7).to_bits();
        for k in 0..3 {
            assert!((p[k] - want[k]).abs() <= 150, "{p:?} {want:?}");
        }
    }

    #[test]
    fn out_of_world_range_is_an_error_not_a_wrap() {
        let t = Transform::scale(I16F16::from_num(4096)).unwrap();
        assert_eq!(
            t.apply(Vec3::from_int(2, 0, 0)),
            Err(SceneError::OutOfRange)
        );
        assert_eq!(
            Transform::scale(I16F16::from_num(4097)),
            Err(SceneError::OutOfRange)
        );
        assert_eq!(Transform::scale(I16F16::ZERO), Err(SceneError::NonPositive));
        assert_eq!(
            t.then(&t),
            Err(SceneError::OutOfRange),
            "4096^2 is beyond the matrix range"
        );
        assert_eq!(
            Transform::translation(Vec3::from_int(4097, 0, 0)),
            Err(SceneError::OutOfRange)
        );
    }

    #[test]
    fn normalize_gives_unit_length_for_tiny_and_huge_vectors() {
        for v in [
            [1i64, 0, 0],
            [3, 4, 0],
            [1 << 61, -(1 << 61), 1 << 60],
            [-1, -1, -1],
        ] {
            let n = normalize(v, 30).unwrap();
            let len = n.iter().map(|&c| (c as f64).powi(2)).sum::<f64>().sqrt();
            assert!(
                (len / (1u64 << 30) as f64 - 1.0).abs() < 1e-8,
                "{v:?} {n:?}"
            );
        }
        assert_eq!(normalize([0; 3], 30), None);
    }

    #[test]
    fn normal_matrix_is_inverse_transpose_direction_for_non_uniform_scale() {
        // Plane x + y = c under scale (2, 1, 1): normal (1,1,0) -> (1/2, 1, 0).
        let t = Transform::scale_xyz(Vec3::from_int(2, 1, 1)).unwrap();
        let n = t
            .normal_matrix()
            .unwrap()
            .apply([1 << 16, 1 << 16, 0])
            .unwrap();
        let f = n.map(|c| c as f64 / (1u64 << 30) as f64);
        let want = [1.0 / 5f64.sqrt(), 2.0 / 5f64.sqrt(), 0.0];
        for k in 0..3 {
            assert!((f[k] - want[k]).abs() < 1e-6);
        }
    }
}
