//! Gradient fills: a colour that varies over a shape, linearly along an
//! axis or radially around a centre, through up to [`MAX_STOPS`] colour
//! stops, interpolated in **linear light**.
//!
//! A gradient maps every point `P` to a parameter `t`:
//!
//! - **linear** from `p0` to `p1`: the projection of `P - p0` on the axis,
//!   `t = (P - p0)·(p1 - p0) / |p1 - p0|²` (0 at `p0`, 1 at `p1`, constant
//!   across the axis);
//! - **radial** around `centre` with `radius`: `t = |P - centre| / radius`.
//!
//! The stops are offsets `o_0 <= o_1 <= ... ` in `[0, 1]` with linear
//! 12-bit colours `c_i`; between two stops the colour is the linear
//! interpolation `c_i + (c_{i+1} - c_i) (t - o_i) / (o_{i+1} - o_i)` of the
//! light (a black-to-white ramp is half the light half way, which an sRGB
//! display shows at code 188, not 128). Outside the stops the end colours
//! continue (**pad**: `t < o_0` takes `c_0`, `t >= o_last` takes
//! `c_last`). Two stops at the same offset make a hard edge: the later
//! stop's colour from that offset on. A pixel takes the gradient's value
//! at its centre.
//!
//! ## Set-up here, stepping in the sweep
//!
//! [`Gradient::linear`] and [`Gradient::radial`] validate the stops and do
//! every division the gradient needs, once (they are `const fn`: a
//! gradient can be a `const`). What they compute is what the span sweep
//! ([`band`](crate::band)) steps with additions:
//!
//! - **linear**: the exact integer `M = 4096 · (P - p0)·(p1 - p0)` (fine
//!   units) of a pixel centre, compared with the stops' `o_i |p1 - p0|²`,
//!   says which segment a pixel is in, exactly; inside a segment the
//!   colour is a plane `V = r0 + b x + g y` in 1/65536 of a level, rounded
//!   once per coefficient, which a row steps by one addition per pixel and
//!   channel. The plane's error is at most `0.51 (|x| + |y|) + 2` units
//!   of 1/65536 level for pixels within ±4096 px of the origin: under 1/15
//!   level, so after the resolve a pixel is within **0.57 levels** of the
//!   exact value (the accumulator keeps the fraction, rounding once, at
//!   resolve).
//! - **radial**: the distance, quantised to 1/128 px, is tracked exactly
//!   along a row with additions and compares (an incremental integer square
//!   root, see the sweep's `gradient` module); the colour is evaluated at
//!   the middle of the distance's quantum and stepped per quantum. The
//!   centre is rounded to the 1/128-px grid, so the distance a pixel is
//!   coloured at is within `(1 + √2) / 256 < 0.0095` px of the true one
//!   (1/256 px of the distance from the rounded centre), and a pixel is
//!   within **0.55 levels + 0.0095 px × the steepest colour slope**
//!   (levels per pixel of radius) of the exact value: 0.75 levels for
//!   black to white over a radius of 200 px, 1.3 over 50 px (in linear
//!   light: an sRGB code or less near black, invisible elsewhere).
//!
//! Every pixel's colour is a function of the pixel and the gradient only
//! (each run of a row is set up from its own first pixel, exactly), so a
//! shape drawn in bands of any height, or cut in two, gets the same bits.
//!
//! ## Degenerate gradients and ranges
//!
//! - `p0 == p1`, a radius of 0, or a single stop: the **last stop's
//!   colour** everywhere (as SVG paints them).
//! - Points must lie in the fine coordinate range (±2048 px,
//!   [`FinePoint::in_range`]): [`GradientError::Coord`] otherwise. A
//!   negative radius is [`GradientError::Radius`]; any positive `i32`
//!   radius (fine units) works.
//! - Stops: 1 to [`MAX_STOPS`] ([`GradientError::NoStops`],
//!   [`GradientError::TooManyStops`]), offsets never decreasing
//!   ([`GradientError::Unsorted`]); colours above 4095 are clamped.
//!
//! ```
//! use softedge::geom::FinePoint;
//! use softedge::style::{Gradient, Offset, Stop};
//! // Black at x = 0 px to white at x = 240 px, across a 240-px display.
//! const RAMP: Gradient<1> = match Gradient::linear(
//!     FinePoint::from_px(0, 0),
//!     FinePoint::from_px(240, 0),
//!     &[Stop::lin(Offset::ZERO, [0]), Stop::lin(Offset::ONE, [4095])],
//! ) {
//!     Ok(g) => g,
//!     Err(_) => panic!("bad gradient"),
//! };
//! assert_eq!(RAMP.stops().len(), 2);
//! ```

use crate::color::IntoLinear;
use crate::geom::{FinePoint, FINE_BITS};
use crate::shade::LIN_MAX;
use crate::COVER_BITS;

/// Most stops a [`Gradient`] holds.
pub const MAX_STOPS: usize = 8;

/// Bits of an [`Offset`]: 1/4096 of the gradient's length.
pub(crate) const T_BITS: u32 = 12;

/// Fraction bits of the distance the radial stepper tracks: 1/128 px.
pub(crate) const RADIAL_BITS: u32 = 7;

/// Largest tracked distance of the radial stepper, in its units (1/128
/// px): 32 768 px, beyond any pixel of the coordinate range; stop
/// distances further out are clamped here (never reached).
pub(crate) const RADIAL_LIMIT: i32 = 1 << 22;

/// One level in the plane's fixed point (1/65536 level units).
const ONE_LEVEL: i64 = 1 << COVER_BITS;

/// Where a stop sits along the gradient, in 1/4096 of its length
/// (`Offset::ONE` is 4096): 0 at the start point (or the centre), 1 at
/// the end point (or the radius).
///
/// ```
/// use softedge::style::Offset;
/// assert_eq!(Offset::from_ratio(1, 4).to_4096ths(), 1024);
/// assert_eq!(Offset::from_4096ths(5000), Offset::ONE); // clamped
/// assert_eq!(Offset::from_percent(50), Offset::HALF);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Offset(u16);

impl Offset {
    /// The start (0).
    pub const ZERO: Self = Self(0);
    /// Half way (1/2).
    pub const HALF: Self = Self(Self::SCALE / 2);
    /// The end (1).
    pub const ONE: Self = Self(Self::SCALE);
    const SCALE: u16 = 1 << T_BITS;

    /// From 1/4096 units, clamped to `0..=4096`.
    pub const fn from_4096ths(v: u16) -> Self {
        Self(if v > Self::SCALE { Self::SCALE } else { v })
    }

    /// From a fraction `num / den`, rounded, clamped to `0..=1` (a zero
    /// `den` is 1).
    pub const fn from_ratio(num: u32, den: u32) -> Self {
        if den == 0 || num >= den {
            return Self::ONE;
        }
        let v = (num as u64 * 2 * Self::SCALE as u64 + den as u64) / (2 * den as u64);
        Self(v as u16)
    }

    /// From a percentage (`0..=100`, rounded; larger values are 100 %).
    pub const fn from_percent(p: u8) -> Self {
        Self::from_ratio(p as u32, 100)
    }

    /// The value in 1/4096.
    pub const fn to_4096ths(self) -> u16 {
        self.0
    }
}

/// A colour stop: an offset and the linear colour there.
///
/// ```
/// use softedge::style::{Offset, Stop};
/// // Linear 12-bit channels, usable in a `const`:
/// const WARM: Stop<3> = Stop::lin(Offset::ZERO, [4095, 1500, 0]);
/// assert_eq!(WARM.color, [4095, 1500, 0]);
/// # #[cfg(feature = "embedded-graphics")] {
/// // Or any colour softedge decodes (sRGB embedded-graphics colours too):
/// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
/// let red = Stop::<3>::new(Offset::ONE, Rgb565::RED);
/// assert_eq!(red.color, [4095, 0, 0]);
/// # }
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Stop<const C: usize> {
    /// Where along the gradient.
    pub offset: Offset,
    /// The linear 12-bit colour there (`0..=4095` per channel).
    pub color: [u16; C],
}

impl<const C: usize> Stop<C> {
    /// A stop of a linear 12-bit colour (channels above 4095 are clamped).
    pub const fn lin(offset: Offset, lin12: [u16; C]) -> Self {
        let mut color = lin12;
        let mut k = 0;
        while k < C {
            if color[k] > LIN_MAX {
                color[k] = LIN_MAX;
            }
            k += 1;
        }
        Self { offset, color }
    }

    /// A stop of any colour softedge takes: an embedded-graphics colour
    /// (sRGB, decoded to linear light), a [`Lin`](crate::color::Lin) or a
    /// linear `[u16; C]`.
    pub fn new(offset: Offset, color: impl IntoLinear<C>) -> Self {
        Self::lin(offset, color.into_linear())
    }
}

/// A gradient's geometry, in fine units (1/1024 px).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum GradientKind {
    /// Along the axis from `from` (offset 0) to `to` (offset 1).
    Linear {
        /// Where offset 0 lies.
        from: FinePoint,
        /// Where offset 1 lies.
        to: FinePoint,
    },
    /// Around `centre` (offset 0) out to `radius` (offset 1).
    Radial {
        /// The centre.
        centre: FinePoint,
        /// The radius, fine units.
        radius: i32,
    },
}

/// Why a gradient could not be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum GradientError {
    /// No stops were given.
    NoStops,
    /// More than [`MAX_STOPS`] stops.
    TooManyStops {
        /// How many were given.
        given: usize,
    },
    /// Stop `index` lies before the stop ahead of it.
    Unsorted {
        /// The first stop out of order.
        index: usize,
    },
    /// A point is outside the fine coordinate range.
    Coord(FinePoint),
    /// The radius is negative.
    Radius {
        /// The radius given, fine units.
        radius: i32,
    },
}

/// A linear or radial gradient of up to [`MAX_STOPS`] stops, `C` channels
/// (1 gray, 3 RGB), with everything the sweep steps computed at
/// construction (see the [module docs](crate::style::gradient)).
///
/// Fill a shape with it by [`Canvas::fill_shape_gradient`]
/// (or [`stroke_shape_gradient`], [`fill_gradient`]).
///
/// The set-up of 8 stops makes a `Gradient<3>` 576 bytes (`Gradient<1>`
/// 280): make it once, not per band; as a `static` (the constructors are
/// `const fn`) it lives in flash.
///
/// [`Canvas::fill_shape_gradient`]: crate::canvas::Canvas::fill_shape_gradient
/// [`stroke_shape_gradient`]: crate::canvas::Canvas::stroke_shape_gradient
/// [`fill_gradient`]: crate::canvas::Canvas::fill_gradient
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::style::{Gradient, GradientError, GradientKind, Offset, Stop};
/// let stops = [
///     Stop::lin(Offset::ZERO, [4095, 4095, 4095]),
///     Stop::lin(Offset::from_percent(60), [4095, 0, 0]),
///     Stop::lin(Offset::ONE, [0, 0, 0]),
/// ];
/// let glow = Gradient::radial(FinePoint::centre_of(120, 120), 80 * 1024, &stops).unwrap();
/// assert!(matches!(glow.kind(), GradientKind::Radial { radius: 81920, .. }));
/// // Offsets must not decrease:
/// let bad = [stops[1], stops[0]];
/// assert_eq!(
///     Gradient::radial(FinePoint::centre_of(0, 0), 1024, &bad).err(),
///     Some(GradientError::Unsorted { index: 1 })
/// );
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gradient<const C: usize> {
    kind: GradientKind,
    stops: [Stop<C>; MAX_STOPS],
    len: u8,
    pub(crate) ramp: Ramp<C>,
}

impl<const C: usize> Gradient<C> {
    /// A linear gradient from `from` (offset 0) to `to` (offset 1).
    ///
    /// ```
    /// use softedge::geom::FinePoint;
    /// use softedge::style::{Gradient, Offset, Stop};
    /// let g = Gradient::linear(
    ///     FinePoint::from_px(0, 0),
    ///     FinePoint::from_px(0, 64),
    ///     &[Stop::lin(Offset::ZERO, [0]), Stop::lin(Offset::ONE, [4095])],
    /// );
    /// assert!(g.is_ok());
    /// ```
    pub const fn linear(
        from: FinePoint,
        to: FinePoint,
        stops: &[Stop<C>],
    ) -> Result<Self, GradientError> {
        let (stops, len) = match check_stops(stops) {
            Ok(s) => s,
            Err(e) => return Err(e),
        };
        if !from.in_range() {
            return Err(GradientError::Coord(from));
        }
        if !to.in_range() {
            return Err(GradientError::Coord(to));
        }
        Ok(Self {
            kind: GradientKind::Linear { from, to },
            stops,
            len: len as u8,
            ramp: linear_ramp(from, to, &stops, len),
        })
    }

    /// A radial gradient around `centre` (offset 0) out to `radius` fine
    /// units (offset 1).
    ///
    /// ```
    /// use softedge::geom::FinePoint;
    /// use softedge::style::{Gradient, GradientError, Offset, Stop};
    /// let stops = [Stop::lin(Offset::ZERO, [4095]), Stop::lin(Offset::ONE, [0])];
    /// let c = FinePoint::centre_of(32, 32);
    /// assert!(Gradient::radial(c, 20 * 1024, &stops).is_ok());
    /// assert_eq!(
    ///     Gradient::radial(c, -1, &stops).err(),
    ///     Some(GradientError::Radius { radius: -1 })
    /// );
    /// ```
    pub const fn radial(
        centre: FinePoint,
        radius: i32,
        stops: &[Stop<C>],
    ) -> Result<Self, GradientError> {
        let (stops, len) = match check_stops(stops) {
            Ok(s) => s,
            Err(e) => return Err(e),
        };
        if !centre.in_range() {
            return Err(GradientError::Coord(centre));
        }
        if radius < 0 {
            return Err(GradientError::Radius { radius });
        }
        Ok(Self {
            kind: GradientKind::Radial { centre, radius },
            stops,
            len: len as u8,
            ramp: radial_ramp(centre, radius, &stops, len),
        })
    }

    /// The geometry.
    pub const fn kind(&self) -> GradientKind {
        self.kind
    }

    /// The stops, in order.
    pub fn stops(&self) -> &[Stop<C>] {
        let n = usize::from(self.len).min(MAX_STOPS);
        self.stops.get(..n).unwrap_or(&[])
    }

    /// The one colour of a gradient that paints a single colour
    /// everywhere (degenerate geometry or a single stop).
    pub(crate) fn flat(&self) -> Option<[u16; C]> {
        match self.ramp {
            Ramp::Flat(c) => Some(c),
            _ => None,
        }
    }
}

/// What the sweep steps: the gradient's set-up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) enum Ramp<const C: usize> {
    /// One colour everywhere.
    Flat([u16; C]),
    Linear(LinearRamp<C>),
    Radial(RadialRamp<C>),
}

/// A linear gradient's set-up. Region `r` of a pixel is the number of
/// thresholds `th[i] <= M` (`M = mc + mx x + my y`, the pixel centre's
/// exact projection); region 0 and region `n` are the pads, region `r`
/// between them the segment of stops `r - 1` and `r`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct LinearRamp<const C: usize> {
    /// `M` at the centre of pixel (0, 0): `4096 (centre - p0)·(p1 - p0)`.
    pub(crate) mc: i64,
    /// Change of `M` per pixel right: `4096 · 1024 · dx`.
    pub(crate) mx: i64,
    /// Change of `M` per pixel down.
    pub(crate) my: i64,
    /// `|dx|` in fine units (`|mx| = |dx| << 22`), for the pixel counts.
    pub(crate) dx_abs: u64,
    /// `o_i |p1 - p0|²` (offsets in 1/4096, lengths in fine units).
    pub(crate) th: [i64; MAX_STOPS],
    /// Number of stops (thresholds), `2..=MAX_STOPS`.
    pub(crate) n: usize,
    /// The colour plane of each region, per channel.
    pub(crate) planes: [[LinePlane; C]; MAX_STOPS + 1],
}

/// `V(x, y) = r0 + b x + g y` in 1/65536 level units, exact modulo 2^32
/// (see [`linear_ramp`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct LinePlane {
    pub(crate) r0: i32,
    pub(crate) b: i32,
    pub(crate) g: i32,
}

/// A radial gradient's set-up, in units of 1/128 px. Region `r` of a
/// tracked distance `D` is the number of thresholds `th[i] <= D`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct RadialRamp<const C: usize> {
    /// The centre on the 1/128-px grid.
    pub(crate) cx: i32,
    pub(crate) cy: i32,
    /// The first `D` of each stop's region.
    pub(crate) th: [i32; MAX_STOPS],
    /// Number of stops, `2..=MAX_STOPS`.
    pub(crate) n: usize,
    /// The colour of each region, per channel.
    pub(crate) pieces: [[RadialPiece; C]; MAX_STOPS + 1],
}

/// The colour of one region of a radial gradient as a function of `D`:
/// `a` at the region's first `D` (`th[r - 1]`), rising by `mhp / 2^32`
/// levels per unit of `D`; `m` is the slope rounded to 1/65536 level
/// (exact modulo 2^32). The pads have `mhp = m = 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct RadialPiece {
    pub(crate) a: i32,
    pub(crate) m: i32,
    pub(crate) mhp: i64,
}

/// The stops copied into a fixed array, colours clamped, or why not.
const fn check_stops<const C: usize>(
    stops: &[Stop<C>],
) -> Result<([Stop<C>; MAX_STOPS], usize), GradientError> {
    let len = stops.len();
    if len == 0 {
        return Err(GradientError::NoStops);
    }
    if len > MAX_STOPS {
        return Err(GradientError::TooManyStops { given: len });
    }
    let mut out = [Stop {
        offset: Offset::ZERO,
        color: [0; C],
    }; MAX_STOPS];
    let mut i = 0;
    while i < len && i < MAX_STOPS {
        let s = &stops[i];
        if i > 0 && s.offset.0 < out[i - 1].offset.0 {
            return Err(GradientError::Unsorted { index: i });
        }
        out[i] = Stop::lin(s.offset, s.color);
        i += 1;
    }
    Ok((out, len))
}

/// `(floor(n / d), n - d floor(n / d))` for `d > 0`; `(0, 0)` otherwise.
const fn divmod_floor(n: i64, d: i64) -> (i64, i64) {
    match (n.checked_div_euclid(d), n.checked_rem_euclid(d)) {
        (Some(q), Some(r)) if d > 0 => (q, r),
        _ => (0, 0),
    }
}

/// `round(n / d)` (halves up) for `d > 0`, `|n| < 2^62`; 0 otherwise.
const fn div_round(n: i64, d: i64) -> i64 {
    divmod_floor(n + (d >> 1), d).0
}

/// About `floor(r · 2^32 / d)` for `0 <= r < d`: exact when `d < 2^31`,
/// otherwise both are first shifted right until `d` has 31 bits (a
/// relative error below 2^-30). Deterministic, in `0..=2^32`.
const fn frac32(r: i64, d: i64) -> i64 {
    if d <= 0 || r < 0 {
        return 0;
    }
    let bits = 64 - d.leading_zeros();
    let sh = bits.saturating_sub(31);
    match ((r >> sh) << 32).checked_div(d >> sh) {
        Some(q) => q,
        None => 0,
    }
}

/// `round(dc · f / 2^bits)` for a colour difference `|dc| < 2^12` and a
/// fraction `0 <= f <= 2^32` (the product is below 2^44).
const fn scale(dc: i64, f: i64, bits: u32) -> i64 {
    (dc * f + (1 << (bits - 1))) >> bits
}

/// The plane of one colour everywhere.
const fn flat_plane(c: u16) -> LinePlane {
    LinePlane {
        r0: (c as i32) << COVER_BITS,
        b: 0,
        g: 0,
    }
}

/// The set-up of a linear gradient (`1 <= len <= MAX_STOPS`, valid stops).
///
/// Pixel `(x, y)`'s centre is `(1024 x + 512, 1024 y + 512)` fine units;
/// with `d = p1 - p0`, `N = (centre - p0)·d` is exact in `i64` (`|N| <
/// 2^46` for points and pixels within ±4096 px) and so is `M = 4096 N`
/// (below 2^58), compared with `th_i = O_i |d|²` (`O_i` the offset in
/// 1/4096, below 2^57). In the segment of stops `a` and `b`, with
/// `den = (O_b - O_a) |d|²`, the exact colour is
/// `2^16 (c_a + (c_b - c_a) (M - th_a) / den)`, a plane in `(x, y)` whose
/// coefficients `b = 2^16 Δc · 4096 · 1024 d_x / den`, `g` (the same with
/// `d_y`) and `r0` (the value at pixel (0, 0)) are computed as an integer
/// quotient and a 32-bit fraction of it ([`frac32`]): each within `0.51`
/// units of its exact value. The integer parts can be huge (a segment
/// thinner than a pixel) but only their values modulo 2^32 are kept: the
/// plane's value at any pixel *inside the segment* is a colour within
/// range, so its value modulo 2^32, which the wrapping `i32` arithmetic of
/// the sweep computes, is the value itself.
const fn linear_ramp<const C: usize>(
    from: FinePoint,
    to: FinePoint,
    stops: &[Stop<C>; MAX_STOPS],
    len: usize,
) -> Ramp<C> {
    let n = if len > MAX_STOPS { MAX_STOPS } else { len };
    let last = stops[n.saturating_sub(1) % MAX_STOPS].color;
    let dx = to.x as i64 - from.x as i64;
    let dy = to.y as i64 - from.y as i64;
    let l2 = dx * dx + dy * dy;
    if l2 == 0 || n < 2 {
        return Ramp::Flat(last);
    }
    let half = 1i64 << (FINE_BITS - 1);
    let mc = ((half - from.x as i64) * dx + (half - from.y as i64) * dy) << T_BITS;
    let step = FINE_BITS + T_BITS;
    let mut th = [0i64; MAX_STOPS];
    let mut i = 0;
    while i < n {
        th[i] = stops[i].offset.0 as i64 * l2;
        i += 1;
    }
    let mut planes = [[LinePlane { r0: 0, b: 0, g: 0 }; C]; MAX_STOPS + 1];
    let mut ch = 0;
    while ch < C {
        planes[0][ch] = flat_plane(stops[0].color[ch]);
        planes[n][ch] = flat_plane(last[ch]);
        ch += 1;
    }
    // The plane coefficients' common factors, 2^16 · 4096 · 1024 · d / den.
    let up = COVER_BITS + step;
    let mut r = 1;
    while r < n {
        let (a, b) = (&stops[r - 1], &stops[r]);
        let d_o = b.offset.0 as i64 - a.offset.0 as i64;
        let den = d_o * l2;
        let (qx, rx) = divmod_floor(dx << up, den);
        let (qy, ry) = divmod_floor(dy << up, den);
        let (qz, rz) = divmod_floor(mc - th[r - 1], den);
        let (fx, fy, fz) = (frac32(rx, den), frac32(ry, den), frac32(rz, den));
        let mut ch = 0;
        while ch < C {
            planes[r][ch] = if d_o == 0 {
                // A hard edge: no pixel is ever in this region.
                flat_plane(b.color[ch])
            } else {
                let dc = b.color[ch] as i64 - a.color[ch] as i64;
                LinePlane {
                    b: dc.wrapping_mul(qx).wrapping_add(scale(dc, fx, 32)) as i32,
                    g: dc.wrapping_mul(qy).wrapping_add(scale(dc, fy, 32)) as i32,
                    r0: ((a.color[ch] as i64) << COVER_BITS)
                        .wrapping_add(dc.wrapping_mul(qz).wrapping_mul(ONE_LEVEL))
                        .wrapping_add(scale(dc, fz, 32 - COVER_BITS))
                        as i32,
                }
            };
            ch += 1;
        }
        r += 1;
    }
    Ramp::Linear(LinearRamp {
        mc,
        mx: dx << step,
        my: dy << step,
        dx_abs: dx.unsigned_abs(),
        th,
        n,
        planes,
    })
}

/// The set-up of a radial gradient (`1 <= len <= MAX_STOPS`, valid stops,
/// `radius >= 0`).
///
/// The sweep tracks `D = floor(128 · d)` for the distance `d` (px) from
/// the centre rounded to the 1/128-px grid, and colours a pixel at the
/// middle of its quantum, `(D + 1/2) / 128` px: `t = (2D + 1) · 4 / R` with
/// `R` in fine units. A stop at offset `O` (1/4096) starts at the first `D`
/// with `(2D + 1) W >= R O`, `W = 2^14`. In the segment of stops `a`, `b`
/// (`den = R (O_b - O_a)`, below 2^44), the colour is
/// `2^16 c_a + 2^16 Δc ((2D + 1) W - R O_a) / den`: its value `a` at the
/// segment's first `D` is rounded once (numerator below 2^44), and its
/// slope per unit of `D`, `2^16 Δc · 2W / den`, is kept with 16 more
/// fraction bits in `mhp` (numerator below 2^60).
const fn radial_ramp<const C: usize>(
    centre: FinePoint,
    radius: i32,
    stops: &[Stop<C>; MAX_STOPS],
    len: usize,
) -> Ramp<C> {
    let n = if len > MAX_STOPS { MAX_STOPS } else { len };
    let last = stops[n.saturating_sub(1) % MAX_STOPS].color;
    if radius <= 0 || n < 2 {
        return Ramp::Flat(last);
    }
    let shift = FINE_BITS - RADIAL_BITS;
    let r = radius as i64;
    // (D + 1/2) units of 1/128 px are (2D + 1) 2^(10 - 7 - 1) fine units;
    // times 4096 for offsets in 1/4096: (2D + 1) W.
    let w_bits = FINE_BITS - RADIAL_BITS - 1 + T_BITS;
    let w: i64 = 1 << w_bits;
    // The slope per unit of D in 2^-32 levels: 2^32 Δc 2W / den.
    let slope_bits = 2 * COVER_BITS + 1 + w_bits;
    let mut th = [0i32; MAX_STOPS];
    let mut i = 0;
    while i < n {
        let p = r * stops[i].offset.0 as i64;
        let d = if p <= w {
            0
        } else {
            divmod_floor(p - w + 2 * w - 1, 2 * w).0
        };
        th[i] = if d > RADIAL_LIMIT as i64 {
            RADIAL_LIMIT
        } else {
            d as i32
        };
        i += 1;
    }
    let mut pieces = [[RadialPiece { a: 0, m: 0, mhp: 0 }; C]; MAX_STOPS + 1];
    let mut ch = 0;
    while ch < C {
        pieces[0][ch].a = (stops[0].color[ch] as i32) << COVER_BITS;
        pieces[n][ch].a = (last[ch] as i32) << COVER_BITS;
        ch += 1;
    }
    let mut k = 1;
    while k < n {
        let (a, b) = (&stops[k - 1], &stops[k]);
        let d_o = b.offset.0 as i64 - a.offset.0 as i64;
        let den = r * d_o;
        let d0 = th[k - 1] as i64;
        // How far past stop a the segment's first D is coloured: 0..2W.
        let num = (2 * d0 + 1) * w - r * a.offset.0 as i64;
        let reachable = d_o > 0 && d0 < RADIAL_LIMIT as i64;
        let mut ch = 0;
        while ch < C {
            let ca = (a.color[ch] as i32) << COVER_BITS;
            pieces[k][ch] = if reachable {
                let dc = b.color[ch] as i64 - a.color[ch] as i64;
                let mhp = div_round(dc << slope_bits, den);
                RadialPiece {
                    a: ca + div_round(dc * num * ONE_LEVEL, den) as i32,
                    m: ((mhp + (1 << (COVER_BITS - 1))) >> COVER_BITS) as i32,
                    mhp,
                }
            } else {
                RadialPiece {
                    a: (b.color[ch] as i32) << COVER_BITS,
                    m: 0,
                    mhp: 0,
                }
            };
            ch += 1;
        }
        k += 1;
    }
    Ramp::Radial(RadialRamp {
        cx: (centre.x + (1 << (shift - 1))) >> shift,
        cy: (centre.y + (1 << (shift - 1))) >> shift,
        th,
        n,
        pieces,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two(c0: u16, c1: u16) -> [Stop<1>; 2] {
        [Stop::lin(Offset::ZERO, [c0]), Stop::lin(Offset::ONE, [c1])]
    }

    #[test]
    fn offsets_round_and_clamp() {
        assert_eq!(Offset::from_ratio(1, 3).to_4096ths(), 1365);
        assert_eq!(Offset::from_ratio(2, 3).to_4096ths(), 2731);
        assert_eq!(Offset::from_ratio(3, 0), Offset::ONE);
        assert_eq!(Offset::from_percent(200), Offset::ONE);
        assert_eq!(Offset::from_percent(0), Offset::ZERO);
    }

    #[test]
    fn bad_stop_lists_are_errors() {
        let p = FinePoint::from_px(0, 0);
        let q = FinePoint::from_px(10, 0);
        assert_eq!(
            Gradient::<1>::linear(p, q, &[]).err(),
            Some(GradientError::NoStops)
        );
        let nine = [Stop::lin(Offset::ZERO, [0]); 9];
        assert_eq!(
            Gradient::linear(p, q, &nine).err(),
            Some(GradientError::TooManyStops { given: 9 })
        );
        let mut s = [Stop::lin(Offset::ZERO, [0]); 3];
        s[1].offset = Offset::HALF;
        assert_eq!(
            Gradient::linear(p, q, &s).err(),
            Some(GradientError::Unsorted { index: 2 })
        );
        let far = FinePoint::from_px(5000, 0);
        assert_eq!(
            Gradient::linear(p, far, &two(0, 1)).err(),
            Some(GradientError::Coord(far))
        );
        assert!(Gradient::linear(p, q, &[Stop::lin(Offset::ZERO, [9999])]).is_ok());
    }

    #[test]
    fn degenerate_gradients_are_the_last_colour() {
        let p = FinePoint::from_px(3, 3);
        let g = Gradient::linear(p, p, &two(100, 200)).unwrap();
        assert_eq!(g.flat(), Some([200]));
        let g = Gradient::radial(p, 0, &two(100, 200)).unwrap();
        assert_eq!(g.flat(), Some([200]));
        let g = Gradient::radial(p, 50, &[Stop::lin(Offset::HALF, [7000])]).unwrap();
        assert_eq!(g.flat(), Some([4095]));
        assert_eq!(
            Gradient::linear(p, FinePoint::from_px(4, 4), &two(0, 1))
                .unwrap()
                .flat(),
            None
        );
    }

    #[test]
    fn fractions_are_floors_where_exact() {
        assert_eq!(frac32(1, 3), (1i64 << 32) / 3);
        assert_eq!(frac32(0, 7), 0);
        let d = (1i64 << 57) + 12345;
        let f = frac32(d / 2, d);
        assert!((f - (1 << 31)).abs() <= 2, "{f}");
        assert_eq!(divmod_floor(-7, 2), (-4, 1));
        assert_eq!(div_round(5, 2), 3);
        assert_eq!(div_round(-5, 2), -2);
    }

    #[test]
    fn linear_plane_is_the_exact_colour_at_pixel_centres() {
        // 0 at x = 0 px to 4095 at x = 100 px: the centre of pixel x is
        // at t = (x + 1/2) / 100.
        let g = Gradient::linear(
            FinePoint::from_px(0, 0),
            FinePoint::from_px(100, 0),
            &two(0, 4095),
        )
        .unwrap();
        let Ramp::Linear(l) = g.ramp else {
            panic!("linear")
        };
        let p = l.planes[1][0];
        for x in 0..100 {
            let v = i64::from(p.r0) + i64::from(p.b) * x + i64::from(p.g) * 7;
            let exact = (x as f64 + 0.5) / 100.0 * 4095.0 * 65536.0;
            assert!((v as f64 - exact).abs() < 64.0, "{x}: {v} vs {exact}");
        }
    }
}
