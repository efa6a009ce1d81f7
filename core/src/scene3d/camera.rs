//! The camera: world points to camera space, camera space to sub-pixel
//! screen positions and depth (setup side: multiplies and divides).
//!
//! Camera space is `(x, y, d)`: `x` to the right, `y` up, `d` the distance
//! in front of the eye along the view direction. The basis is right-handed
//! (`right = forward x up`), kept as unit vectors in Q30 so that it adds no
//! error visible at the 1/16 px grid; camera coordinates are Q16.16, below
//! `2^30` in bits (a point and the eye are both within `±WORLD_LIMIT`).
//!
//! ## Projection (the image centre lies on the camera axis)
//!
//! - orthographic: `x_px = W/2 + s x`, `y_px = H/2 - s y`, with `s` pixels
//!   per world unit, `0 < s <= MAX_PX_PER_UNIT`;
//! - perspective: `x_px = W/2 + f x / d`, `y_px = H/2 - f y / d`, with the
//!   focal length `f = (H/2) / tan(fov_y / 2)` pixels, `0 < fov_y < 180`
//!   degrees and `f <= MAX_FOCAL_PX`; the half angle is `fov_y.0 / 2`
//!   units, rounded down.
//!
//! Positions are rounded to 1/16 px; a vertex outside `±COORD_LIMIT_PX`
//! makes its triangle be dropped (counted in
//! [`ProjectStats::off_range`](super::ProjectStats)).
//!
//! ## Depth (`u16`, larger is nearer: the seed-004 convention)
//!
//! Depth maps `[near, far]` onto `65535..=0` so that it is linear in screen
//! space (what the hidden-surface stage interpolates with an add-only DDA):
//!
//! - orthographic: `z = 65535 (far - d) / (far - near)`;
//! - perspective: `z = 65535 (near / d) (far - d) / (far - near)`, i.e. the
//!   usual affine function of `1 / d`.
//!
//! Both are monotonic (never increasing) in `d`; points beyond `far` get 0.

use fixed::types::I16F16;

use super::math::{cross, div_round, normalize, Vec3};
use super::trig::Angle;
use super::SceneError;
use crate::band::MAX_WIDTH;
use crate::geom::{SubPoint, COORD_LIMIT_SUB};

/// Largest orthographic scale, pixels per world unit.
pub const MAX_PX_PER_UNIT: i32 = 2048;
/// Largest perspective focal length, pixels.
pub const MAX_FOCAL_PX: i32 = 16384;
/// Smallest `sin` of the angle between `up` and the view direction
/// accepted, `2^-10` (about 0.056 degrees).
pub const MIN_UP_SIN_SHIFT: u32 = 10;

/// How camera space becomes the image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Projection {
    /// Parallel projection.
    Orthographic {
        /// Pixels per world unit.
        px_per_unit: I16F16,
    },
    /// Central projection.
    Perspective {
        /// Vertical field of view.
        fov_y: Angle,
    },
}

/// A camera: where it stands, where it looks, and how it projects.
///
/// ```
/// use softedge::scene3d::{Camera, Vec3};
/// use fixed::types::I16F16;
/// let cam = Camera::orthographic(Vec3::from_int(0, 0, 10), Vec3::ZERO, Vec3::from_int(0, 1, 0), I16F16::from_num(20));
/// let view = cam.view(64, 48).unwrap();
/// // The target lands on the image centre, 1/16 px units.
/// let (p, _depth) = view.project_point(Vec3::ZERO).unwrap();
/// assert_eq!((p.x, p.y), (32 * 16, 24 * 16));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Camera {
    /// The eye (centre of projection).
    pub eye: Vec3,
    /// A point on the camera axis.
    pub target: Vec3,
    /// A direction that appears upwards (need not be perpendicular to the
    /// view direction, but not parallel to it).
    pub up: Vec3,
    /// Orthographic or perspective.
    pub projection: Projection,
    /// Distance of the near clipping plane in front of the eye (`> 0`).
    pub near: I16F16,
    /// Distance mapped to depth 0 (`> near`).
    pub far: I16F16,
}

impl Camera {
    /// Default near plane: 1/16 unit.
    pub const NEAR: I16F16 = I16F16::from_bits(1 << 12);
    /// Default far distance: 16384 units (beyond any two points of the world
    /// range, `2 * WORLD_LIMIT * sqrt(3)` apart).
    pub const FAR: I16F16 = I16F16::from_bits(16384 << 16);

    /// An orthographic camera with the default near and far distances.
    pub const fn orthographic(eye: Vec3, target: Vec3, up: Vec3, px_per_unit: I16F16) -> Self {
        Self {
            eye,
            target,
            up,
            projection: Projection::Orthographic { px_per_unit },
            near: Self::NEAR,
            far: Self::FAR,
        }
    }

    /// A perspective camera with the default near and far distances.
    pub const fn perspective(eye: Vec3, target: Vec3, up: Vec3, fov_y: Angle) -> Self {
        Self {
            eye,
            target,
            up,
            projection: Projection::Perspective { fov_y },
            near: Self::NEAR,
            far: Self::FAR,
        }
    }

    /// Prepares the camera for a frame of `width x height` pixels
    /// (each `1..=2048`).
    ///
    /// Errors: [`SceneError::EyeAtTarget`], [`SceneError::UpParallel`] (also
    /// for a zero `up`), [`SceneError::OutOfRange`] (eye or target outside
    /// the world range, frame size, scale), [`SceneError::NonPositive`]
    /// (scale, near, `far <= near`), [`SceneError::FieldOfView`].
    pub fn view(&self, width: u16, height: u16) -> Result<View, SceneError> {
        let eye = self.eye.check()?.wide();
        let target = self.target.check()?.wide();
        if width == 0 || height == 0 || width > MAX_WIDTH || height > MAX_WIDTH {
            return Err(SceneError::OutOfRange);
        }
        let near = i64::from(self.near.to_bits());
        let far = i64::from(self.far.to_bits());
        if near <= 0 || far <= near {
            return Err(SceneError::NonPositive);
        }
        let fwd = [0, 1, 2].map(|k| target[k] - eye[k]);
        let forward = normalize(fwd, 30).ok_or(SceneError::EyeAtTarget)?;
        let up = normalize(self.up.wide(), 30).ok_or(SceneError::UpParallel)?;
        // |forward x up| = sin(angle) * 2^60.
        let r = cross(forward, up);
        let big = r.iter().fold(0u64, |m, c| m | c.unsigned_abs());
        if big < 1 << (60 - MIN_UP_SIN_SHIFT) {
            return Err(SceneError::UpParallel);
        }
        let right = normalize(r, 30).ok_or(SceneError::UpParallel)?;
        let up = normalize(cross(right, forward), 30).ok_or(SceneError::UpParallel)?;
        let kind = match self.projection {
            Projection::Orthographic { px_per_unit } => {
                let s = i64::from(px_per_unit.to_bits());
                if s <= 0 {
                    return Err(SceneError::NonPositive);
                }
                if s > i64::from(MAX_PX_PER_UNIT) << 16 {
                    return Err(SceneError::OutOfRange);
                }
                Kind::Orthographic { scale: s }
            }
            Projection::Perspective { fov_y } => {
                if fov_y.0 == 0 || fov_y.0 >= 1 << 15 {
                    return Err(SceneError::FieldOfView);
                }
                let half = Angle(fov_y.0 / 2);
                // f = (H / 2) cos / sin, Q16: H * 2^15 * cos / sin < 2^42.
                let num = i64::from(height) * (1 << 15) * i64::from(half.cos_q16());
                let den = i64::from(half.sin_q16());
                if den <= 0 {
                    return Err(SceneError::FieldOfView);
                }
                let f = div_round(num, den);
                if f <= 0 || f > i64::from(MAX_FOCAL_PX) << 16 {
                    return Err(SceneError::FieldOfView);
                }
                Kind::Perspective { focal: f }
            }
        };
        Ok(View {
            basis: [right, up, forward],
            eye,
            centre: [i64::from(width) * 8, i64::from(height) * 8],
            kind,
            near,
            far,
        })
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// Pixels per unit, Q16.
    Orthographic { scale: i64 },
    /// Focal length in pixels, Q16.
    Perspective { focal: i64 },
}

/// A camera prepared for one frame size ([`Camera::view`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct View {
    /// Right, up, forward: unit vectors, Q30.
    basis: [[i64; 3]; 3],
    /// Q16.
    eye: [i64; 3],
    /// Image centre, 1/16 px.
    centre: [i64; 2],
    kind: Kind,
    /// Q16.
    near: i64,
    /// Q16.
    far: i64,
}

impl View {
    /// Camera coordinates `(x, y, d)` of a world point given in Q16 bits
    /// within the world range; Q16 results below `2^30`.
    pub(crate) fn camera_coords(&self, p: [i64; 3]) -> [i32; 3] {
        let rel = [0, 1, 2].map(|k| p[k] - self.eye[k]);
        // |rel| < 2^29 per component, basis < 2^30: sums below 2^61.
        self.basis.map(|b| {
            let dot: i64 = b.iter().zip(rel).map(|(&u, c)| u * c).sum();
            ((dot + (1 << 29)) >> 30) as i32
        })
    }

    /// The near distance, Q16 bits.
    pub(crate) fn near(&self) -> i64 {
        self.near
    }

    /// The far distance, Q16 bits.
    pub(crate) fn far(&self) -> i64 {
        self.far
    }

    /// Screen position (1/16 px) and depth of a camera-space point with
    /// `d >= near`; `None` when the position is outside `±COORD_LIMIT_PX`.
    pub(crate) fn project_camera(&self, c: [i64; 3]) -> Option<(SubPoint, u16)> {
        let [x, y, d] = c;
        let (dx, dy, depth) = match self.kind {
            Kind::Orthographic { scale } => {
                // |x| < 2^30, scale <= 2^27: products < 2^57; Q32 px -> Q4.
                let dx = div_round(x * scale, 1 << 28);
                let dy = div_round(y * scale, 1 << 28);
                let z = div_round(65535 * (self.far - d).max(0), self.far - self.near);
                (dx, dy, z)
            }
            Kind::Perspective { focal } => {
                if d < self.near {
                    return None;
                }
                // |x| < 2^30, focal <= 2^30: products < 2^60; d << 12 < 2^42.
                let den = d << 12;
                let dx = div_round(x * focal, den);
                let dy = div_round(y * focal, den);
                let a = div_round(self.near << 16, d);
                let b = div_round((self.far - d).max(0) << 16, self.far - self.near);
                (dx, dy, (a * b * 65535) >> 32)
            }
        };
        let sx = self.centre[0] + dx;
        let sy = self.centre[1] - dy;
        let lim = i64::from(COORD_LIMIT_SUB);
        if sx.abs() > lim || sy.abs() > lim {
            return None;
        }
        Some((
            SubPoint::new(sx as i32, sy as i32),
            depth.clamp(0, 65535) as u16,
        ))
    }

    /// Screen position and depth of a world point (for tests and tools):
    /// `None` in front of the near plane or outside the coordinate range.
    pub fn project_point(&self, p: Vec3) -> Option<(SubPoint, u16)> {
        let c = self.camera_coords(p.check().ok()?.wide()).map(i64::from);
        if c[2] < self.near {
            return None;
        }
        self.project_camera(c)
    }

    /// The unit view direction (eye to target) in Q16.16.
    pub fn forward(&self) -> Vec3 {
        Vec3::from_bits(self.basis[2].map(|c| ((c + (1 << 13)) >> 14) as i32))
    }
}
