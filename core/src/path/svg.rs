//! SVG path data: the `d` attribute of `<path>`, parsed into a
//! [`PathSink`] without floating point.
//!
//! Takes a string of path data (SVG 2, section 9.3: the commands
//! `M m L l H h V v C c S s Q q T t A a Z z`, absolute and relative,
//! implicit repetition of the last command, numbers with signs, decimals
//! and exponents, flags written with or without separators); gives the
//! sink `move_to` / `line_to` / `quad_to` / `cubic_to` / `close` calls in
//! fine units (1 user unit = 1 px = 1024 fine units). `S` and `T` reflect
//! the previous control point; `A` is converted from SVG's endpoint form to
//! the centre form (SVG 2 appendix B.2.4: radii scaled up when too small,
//! `rx = 0` or `ry = 0` a straight line, equal end points nothing) and
//! described as cubic Béziers ([`arc`](super::arc)).
//!
//! ## Numbers
//!
//! A number's decimal digits and exponent are read exactly (the first 19
//! significant digits; later ones are dropped, which can matter only for a
//! tie 19 digits down) and rounded once to the nearest fine unit, ties
//! away from zero: `0.0009765625` is
//! exactly one fine unit. A number beyond `+-`[`NUMBER_LIMIT`] px, an
//! end or control point beyond the coordinate range (`+-2048` px), or an
//! arc any point of whose description (its cubics' control and end points)
//! lies beyond it, is an error, never an overflow: a path that parses
//! without error is drawn with no point out of range.
//!
//! ## Errors
//!
//! The first error stops the parser; it reports the byte position and
//! what was wrong ([`SvgError`]). The sink has then received the path up
//! to the command before the error, which is what SVG renders (SVG 2,
//! "error handling in path data"). [`SvgPath::new`] checks a string once,
//! so that a scene can be described again and again without errors.

use crate::geom::{FinePoint, PathSink, FINE_LIMIT};

use super::arc::{arc_cubics, EllipseFrame};
use super::trig::{atan2, cos_sin, round_shift, TURN};
use super::vector::{Pt, Unit};
use super::Degrees;

/// The largest number accepted in path data: 8192 (px, or degrees).
pub const NUMBER_LIMIT: i32 = 8192;

/// What was wrong with path data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SvgErrorKind {
    /// A character that starts no command (or a number where no command
    /// is active).
    ExpectedCommand,
    /// The path does not begin with `M` or `m`.
    MissingMoveTo,
    /// A command's argument is missing or malformed.
    ExpectedNumber,
    /// An arc's flag is not `0` or `1`.
    ExpectedFlag,
    /// A number beyond `+-NUMBER_LIMIT`.
    NumberOutOfRange,
    /// An end or control point beyond the coordinate range.
    PointOutOfRange,
    /// An arc (`A`) whose end points are in range but whose curve is not:
    /// a point of the cubics it is described with lies beyond the
    /// coordinate range (SVG scales small radii up, never large ones
    /// down, so an arc of large radii can reach far out).
    ArcOutOfRange,
}

/// An error in path data: where (a byte offset into the string) and what.
///
/// ```
/// use softedge::path::svg::{SvgErrorKind, SvgPath};
/// let e = SvgPath::new("M 0 0 L 3000 0").unwrap_err();
/// assert_eq!((e.position, e.kind), (8, SvgErrorKind::PointOutOfRange));
/// assert_eq!(format!("{e}"), "path data, byte 8: point beyond the coordinate range of +-2048 px");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SvgError {
    /// Byte offset of the offending character or number.
    pub position: usize,
    /// What is wrong there.
    pub kind: SvgErrorKind,
}

impl core::fmt::Display for SvgError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let what = match self.kind {
            SvgErrorKind::ExpectedCommand => "expected a path command",
            SvgErrorKind::MissingMoveTo => "path data must begin with M or m",
            SvgErrorKind::ExpectedNumber => "expected a number",
            SvgErrorKind::ExpectedFlag => "expected an arc flag, 0 or 1",
            SvgErrorKind::NumberOutOfRange => "number beyond +-8192",
            SvgErrorKind::PointOutOfRange => "point beyond the coordinate range of +-2048 px",
            SvgErrorKind::ArcOutOfRange => "arc reaching beyond the coordinate range of +-2048 px",
        };
        write!(f, "path data, byte {}: {}", self.position, what)
    }
}

/// Parses path data into `sink` (see the module doc).
///
/// ```
/// use softedge::geom::{FinePoint, PathSink};
/// use softedge::path::svg::parse_path_data;
///
/// #[derive(Default)]
/// struct Calls(usize);
/// impl PathSink for Calls {
///     fn move_to(&mut self, _: FinePoint) { self.0 += 1 }
///     fn line_to(&mut self, _: FinePoint) { self.0 += 1 }
///     fn quad_to(&mut self, _: FinePoint, _: FinePoint) { self.0 += 1 }
///     fn cubic_to(&mut self, _: FinePoint, _: FinePoint, _: FinePoint) { self.0 += 1 }
///     fn close(&mut self) { self.0 += 1 }
/// }
/// let mut calls = Calls::default();
/// parse_path_data("M10 10 h 5 v5 l-5-5 z", &mut calls).unwrap();
/// assert_eq!(calls.0, 5);
/// let err = parse_path_data("M10 10 L 5", &mut calls).unwrap_err();
/// assert_eq!(err.position, 10);
/// ```
pub fn parse_path_data<P: PathSink + ?Sized>(d: &str, sink: &mut P) -> Result<(), SvgError> {
    Parser::new(d.as_bytes(), true).run(sink)
}

/// Path data checked once: [`describe`](super::Shape::describe) it as often
/// as needed.
///
/// ```
/// use softedge::path::svg::SvgPath;
/// assert!(SvgPath::new("M0 0 C 10 0 10 10 0 10 Z").is_ok());
/// assert!(SvgPath::new("M0 0 L 9999 0").is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SvgPath<'a> {
    d: &'a str,
}

impl<'a> SvgPath<'a> {
    /// Checks `d`; the error is the first one in it.
    pub fn new(d: &'a str) -> Result<Self, SvgError> {
        parse_path_data(d, &mut NullSink)?;
        Ok(Self { d })
    }

    /// The path data.
    pub fn data(&self) -> &'a str {
        self.d
    }
}

impl super::Shape for SvgPath<'_> {
    fn key(&self) -> Option<super::ShapeKey> {
        super::ShapeKey::described(super::shape::DescribedKind::Svg, self)
    }

    fn key_reads_points(&self) -> bool {
        true
    }

    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        // Checked in `new` (arcs included): this cannot fail, and the
        // arcs need not be described twice to check them again.
        let _ = Parser::new(self.d.as_bytes(), false).run(sink);
    }
}

/// A sink that notes whether any point it is given lies beyond the
/// coordinate range (for checking arcs: what a canvas would reject).
#[derive(Default)]
struct RangeCheck {
    beyond: bool,
}

impl RangeCheck {
    fn add(&mut self, p: FinePoint) {
        self.beyond |= !p.in_range();
    }
}

impl PathSink for RangeCheck {
    fn move_to(&mut self, p: FinePoint) {
        self.add(p);
    }
    fn line_to(&mut self, p: FinePoint) {
        self.add(p);
    }
    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        self.add(c);
        self.add(p);
    }
    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        self.add(c1);
        self.add(c2);
        self.add(p);
    }
    fn close(&mut self) {}
}

/// A sink that ignores everything (for checking).
struct NullSink;

impl PathSink for NullSink {
    fn move_to(&mut self, _: FinePoint) {}
    fn line_to(&mut self, _: FinePoint) {}
    fn quad_to(&mut self, _: FinePoint, _: FinePoint) {}
    fn cubic_to(&mut self, _: FinePoint, _: FinePoint, _: FinePoint) {}
    fn close(&mut self) {}
}

/// The kind of the previous segment, for `S` and `T`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Prev {
    Other,
    Cubic(Pt),
    Quad(Pt),
}

struct Parser<'a> {
    s: &'a [u8],
    pos: usize,
    current: Pt,
    start: Pt,
    prev: Prev,
    /// A `close` was the last thing: the next drawing command restarts at
    /// `start` with a `move_to`.
    closed: bool,
    /// Arcs are described once into a [`RangeCheck`] before the sink sees
    /// them (off for a path already checked).
    check_arcs: bool,
}

fn err(position: usize, kind: SvgErrorKind) -> SvgError {
    SvgError { position, kind }
}

fn is_wsp(c: u8) -> bool {
    matches!(c, b' ' | b'\t' | b'\n' | b'\r' | b'\x0c')
}

/// Limit of a number in fine units.
const LIMIT_FINE: i64 = NUMBER_LIMIT as i64 * 1024;

impl<'a> Parser<'a> {
    fn new(s: &'a [u8], check_arcs: bool) -> Self {
        Self {
            s,
            pos: 0,
            current: Pt::default(),
            start: Pt::default(),
            prev: Prev::Other,
            closed: false,
            check_arcs,
        }
    }

    fn peek(&self) -> Option<u8> {
        self.s.get(self.pos).copied()
    }

    fn skip_wsp(&mut self) {
        while self.peek().is_some_and(is_wsp) {
            self.pos += 1;
        }
    }

    /// Skips `wsp* ,? wsp*`.
    fn skip_comma_wsp(&mut self) {
        self.skip_wsp();
        if self.peek() == Some(b',') {
            self.pos += 1;
            self.skip_wsp();
        }
    }

    /// True when a number can start here.
    fn at_number(&self) -> bool {
        matches!(self.peek(), Some(b'0'..=b'9' | b'+' | b'-' | b'.'))
    }

    fn run<P: PathSink + ?Sized>(&mut self, sink: &mut P) -> Result<(), SvgError> {
        self.skip_wsp();
        let mut cmd: Option<u8> = None;
        let mut first = true;
        // Every pass consumes at least one byte or returns: bounded by the
        // length of the string.
        loop {
            self.skip_wsp();
            let Some(c) = self.peek() else {
                return Ok(());
            };
            let here = self.pos;
            let letter = if c.is_ascii_alphabetic() {
                self.pos += 1;
                c
            } else if self.at_number() {
                // Implicit repetition: M becomes L, m becomes l.
                match cmd {
                    Some(b'M') => b'L',
                    Some(b'm') => b'l',
                    Some(b'Z' | b'z') | None => {
                        return Err(err(here, SvgErrorKind::ExpectedCommand))
                    }
                    Some(k) => k,
                }
            } else {
                return Err(err(here, SvgErrorKind::ExpectedCommand));
            };
            if first && !matches!(letter, b'M' | b'm') {
                return Err(err(here, SvgErrorKind::MissingMoveTo));
            }
            first = false;
            self.command(letter, here, sink)?;
            cmd = Some(letter);
            self.skip_comma_wsp();
        }
    }

    fn number(&mut self) -> Result<i64, SvgError> {
        self.skip_wsp();
        let at = self.pos;
        match parse_number(self.s, self.pos) {
            Some((v, next)) => {
                self.pos = next;
                if v.abs() > LIMIT_FINE {
                    return Err(err(at, SvgErrorKind::NumberOutOfRange));
                }
                Ok(v)
            }
            None => Err(err(at, SvgErrorKind::ExpectedNumber)),
        }
    }

    /// A number followed by the optional separator.
    fn arg(&mut self) -> Result<i64, SvgError> {
        let v = self.number()?;
        self.skip_comma_wsp();
        Ok(v)
    }

    fn flag(&mut self) -> Result<bool, SvgError> {
        self.skip_wsp();
        let at = self.pos;
        let v = match self.peek() {
            Some(b'0') => false,
            Some(b'1') => true,
            _ => return Err(err(at, SvgErrorKind::ExpectedFlag)),
        };
        self.pos += 1;
        self.skip_comma_wsp();
        Ok(v)
    }

    /// A point argument: `(x, y)`, relative to the current point for
    /// lower-case commands; checked against the coordinate range.
    fn point(&mut self, rel: bool) -> Result<Pt, SvgError> {
        self.skip_wsp();
        let at = self.pos;
        let x = self.arg()?;
        let y = self.arg()?;
        let p = if rel {
            Pt::new(self.current.x + x, self.current.y + y)
        } else {
            Pt::new(x, y)
        };
        check(p, at)
    }

    /// Before a drawing command: after a `close`, the next subpath starts
    /// at the closed one's start.
    fn reopen<P: PathSink + ?Sized>(&mut self, sink: &mut P) {
        if self.closed {
            sink.move_to(self.start.to_fine());
            self.closed = false;
        }
    }

    fn command<P: PathSink + ?Sized>(
        &mut self,
        letter: u8,
        here: usize,
        sink: &mut P,
    ) -> Result<(), SvgError> {
        let rel = letter.is_ascii_lowercase();
        match letter.to_ascii_uppercase() {
            b'M' => {
                let p = self.point(rel)?;
                sink.move_to(p.to_fine());
                self.current = p;
                self.start = p;
                self.closed = false;
                self.prev = Prev::Other;
            }
            b'Z' => {
                sink.close();
                self.current = self.start;
                self.closed = true;
                self.prev = Prev::Other;
            }
            b'L' => {
                let p = self.point(rel)?;
                self.reopen(sink);
                sink.line_to(p.to_fine());
                self.current = p;
                self.prev = Prev::Other;
            }
            b'H' | b'V' => {
                self.skip_wsp();
                let at = self.pos;
                let v = self.arg()?;
                let p = match (letter.to_ascii_uppercase(), rel) {
                    (b'H', true) => Pt::new(self.current.x + v, self.current.y),
                    (b'H', false) => Pt::new(v, self.current.y),
                    (_, true) => Pt::new(self.current.x, self.current.y + v),
                    (_, false) => Pt::new(self.current.x, v),
                };
                let p = check(p, at)?;
                self.reopen(sink);
                sink.line_to(p.to_fine());
                self.current = p;
                self.prev = Prev::Other;
            }
            b'C' | b'S' => {
                let c1 = if letter.eq_ignore_ascii_case(&b'C') {
                    self.point(rel)?
                } else {
                    match self.prev {
                        Prev::Cubic(c) => reflect(c, self.current),
                        _ => self.current,
                    }
                };
                let c2 = self.point(rel)?;
                let p = self.point(rel)?;
                check(c1, here)?;
                self.reopen(sink);
                sink.cubic_to(c1.to_fine(), c2.to_fine(), p.to_fine());
                self.current = p;
                self.prev = Prev::Cubic(c2);
            }
            b'Q' | b'T' => {
                let c = if letter.eq_ignore_ascii_case(&b'Q') {
                    self.point(rel)?
                } else {
                    match self.prev {
                        Prev::Quad(c) => reflect(c, self.current),
                        _ => self.current,
                    }
                };
                let p = self.point(rel)?;
                check(c, here)?;
                self.reopen(sink);
                sink.quad_to(c.to_fine(), p.to_fine());
                self.current = p;
                self.prev = Prev::Quad(c);
            }
            b'A' => {
                let rx = self.arg()?.abs();
                let ry = self.arg()?.abs();
                let rot = self.arg()?;
                let large = self.flag()?;
                let sweep = self.flag()?;
                let p = self.point(rel)?;
                if self.check_arcs {
                    let mut range = RangeCheck::default();
                    arc_to(&mut range, self.current, p, rx, ry, rot, large, sweep);
                    if range.beyond {
                        return Err(err(here, SvgErrorKind::ArcOutOfRange));
                    }
                }
                self.reopen(sink);
                arc_to(sink, self.current, p, rx, ry, rot, large, sweep);
                self.current = p;
                self.prev = Prev::Other;
            }
            _ => return Err(err(here, SvgErrorKind::ExpectedCommand)),
        }
        Ok(())
    }
}

/// `p` if it lies in the coordinate range, else the error at `at`.
fn check(p: Pt, at: usize) -> Result<Pt, SvgError> {
    let l = i64::from(FINE_LIMIT);
    if p.x.abs() <= l && p.y.abs() <= l {
        Ok(p)
    } else {
        Err(err(at, SvgErrorKind::PointOutOfRange))
    }
}

/// The reflection of `c` about `p`.
fn reflect(c: Pt, p: Pt) -> Pt {
    Pt::new(2 * p.x - c.x, 2 * p.y - c.y)
}

/// Parses a number at `pos` into fine units, rounded to nearest (ties
/// away from zero); `None` if none starts there. Returns the value
/// (saturated far beyond any limit) and the position after it.
pub(crate) fn parse_number(s: &[u8], mut pos: usize) -> Option<(i64, usize)> {
    let at = |i: usize| s.get(i).copied();
    let negative = match at(pos) {
        Some(b'-') => {
            pos += 1;
            true
        }
        Some(b'+') => {
            pos += 1;
            false
        }
        _ => false,
    };
    let mut mantissa: u64 = 0;
    let mut digits = 0u32; // significant digits kept
    let mut exp10: i64 = 0;
    let mut any = false;
    while let Some(c @ b'0'..=b'9') = at(pos) {
        any = true;
        keep_digit(c, &mut mantissa, &mut digits, &mut exp10, false);
        pos += 1;
    }
    let dot_digit = at(pos + 1).is_some_and(|c| c.is_ascii_digit());
    if at(pos) == Some(b'.') && (any || dot_digit) {
        pos += 1;
        while let Some(c @ b'0'..=b'9') = at(pos) {
            any = true;
            keep_digit(c, &mut mantissa, &mut digits, &mut exp10, true);
            pos += 1;
        }
    }
    if !any {
        return None;
    }
    // An exponent only when digits follow (else the 'e' is not ours).
    if matches!(at(pos), Some(b'e' | b'E')) {
        let mut q = pos + 1;
        let eneg = match at(q) {
            Some(b'-') => {
                q += 1;
                true
            }
            Some(b'+') => {
                q += 1;
                false
            }
            _ => false,
        };
        if at(q).is_some_and(|c| c.is_ascii_digit()) {
            let mut e: i64 = 0;
            while let Some(c @ b'0'..=b'9') = at(q) {
                e = (e * 10 + i64::from(c - b'0')).min(100_000);
                q += 1;
            }
            exp10 += if eneg { -e } else { e };
            pos = q;
        }
    }
    let v = to_fine(mantissa, exp10);
    Some((if negative { -v } else { v }, pos))
}

/// Adds a decimal digit to the mantissa (19 significant digits kept).
fn keep_digit(c: u8, m: &mut u64, digits: &mut u32, exp10: &mut i64, fraction: bool) {
    let d = u64::from(c - b'0');
    if *digits < 19 {
        if *m == 0 && d == 0 {
            // A leading zero: not significant.
            if fraction {
                *exp10 -= 1;
            }
            return;
        }
        *m = *m * 10 + d;
        *digits += 1;
        if fraction {
            *exp10 -= 1;
        }
    } else if !fraction {
        *exp10 += 1;
    }
}

/// `round(m 10^e 1024)`, ties away from zero; saturates at `i64::MAX / 2`.
fn to_fine(m: u64, e: i64) -> i64 {
    const SAT: i64 = i64::MAX / 2;
    if m == 0 {
        return 0;
    }
    let m = u128::from(m) * 1024; // < 2^74
    if e >= 0 {
        if e > 30 {
            return SAT;
        }
        let p = 10u128.pow(e as u32);
        return m.checked_mul(p).map_or(SAT, |v| v.min(SAT as u128) as i64);
    }
    if e < -38 {
        return 0;
    }
    let p = 10u128.pow((-e) as u32);
    let (q, r) = (m / p, m % p);
    // Round half away from zero (the sign is applied by the caller).
    let up = 2 * r >= p;
    (q + u128::from(up)).min(SAT as u128) as i64
}

/// `floor(num 2^bits / den)` by long division (bounded: `bits` steps),
/// for `num, den < 2^126`; 0 for `den == 0`.
fn div_shift(num: u128, den: u128, bits: u32) -> u128 {
    if den == 0 {
        return 0;
    }
    let mut q = num / den;
    let mut r = num % den;
    for _ in 0..bits {
        q = q.saturating_mul(2);
        r *= 2;
        if r >= den {
            r -= den;
            q = q.saturating_add(1);
        }
    }
    q
}

/// An elliptic arc from `p1` to `p2` (SVG's endpoint form) as cubics.
#[allow(clippy::too_many_arguments)]
fn arc_to<P: PathSink + ?Sized>(
    sink: &mut P,
    p1: Pt,
    p2: Pt,
    rx: i64,
    ry: i64,
    rot_fine_deg: i64,
    large: bool,
    sweep: bool,
) {
    if p1 == p2 {
        return;
    }
    if rx == 0 || ry == 0 {
        sink.line_to(p2.to_fine());
        return;
    }
    // The rotation: the number was read in 1/1024 degree; Degrees keeps
    // 1/65536.
    let rot = Degrees::from_bits(
        (rot_fine_deg * 64).clamp(-i64::from(i32::MAX), i64::from(i32::MAX)) as i32,
    );
    let (c, s) = cos_sin(rot.binary() as u32);
    // Step 1: the half chord in the ellipse's frame, Q8 (1/256 fine).
    let (dx, dy) = (p1.x - p2.x, p1.y - p2.y);
    let x1 = round_shift(c * dx + s * dy, 23); // (..)/2 in Q8: >> (30 + 1 - 8)
    let y1 = round_shift(-s * dx + c * dy, 23);
    let (mut a, mut b) = (rx << 8, ry << 8);
    // Step 2: radii scaled up when they cannot span the chord.
    let (x1s, y1s) = (
        i128::from(x1) * i128::from(x1),
        i128::from(y1) * i128::from(y1),
    );
    let (a2, b2) = (i128::from(a) * i128::from(a), i128::from(b) * i128::from(b));
    let n = x1s * b2 + y1s * a2; // Lambda a^2 b^2
    let d = a2 * b2;
    let centre_offset = if n >= d {
        // a' = sqrt(x1^2 + y1^2 a^2 / b^2), b' = a' b / a.
        let na = ((x1s + y1s * a2 / b2.max(1)).unsigned_abs()).isqrt() as i64;
        b = (i128::from(na) * i128::from(b) / i128::from(a.max(1))) as i64;
        a = na.max(1);
        (0i64, 0i64)
    } else {
        // Step 3: sq = sqrt((d - n) / n), Q30; its sign by the flags.
        let ratio = div_shift((d - n).unsigned_abs(), n.unsigned_abs().max(1), 60);
        let sq = ratio.isqrt() as i128; // Q30
        let sq = if large == sweep { -sq } else { sq };
        let cx = super::trig::div_round(sq * i128::from(a) * i128::from(y1), i128::from(b) << 30);
        let cy = super::trig::div_round(-sq * i128::from(b) * i128::from(x1), i128::from(a) << 30);
        (cx as i64, cy as i64)
    };
    let (cxp, cyp) = centre_offset;
    // Step 4: the centre in the plane, Q8.
    let mid = Pt::new((p1.x + p2.x) << 7, (p1.y + p2.y) << 7);
    let centre = Pt::new(
        mid.x + round_shift(c * cxp - s * cyp, 30),
        mid.y + round_shift(s * cxp + c * cyp, 30),
    );
    // Step 5: the angles of the two ends on the unit circle.
    let ang = |ux: i64, uy: i64| -> i64 {
        // Direction of ((ux)/a, (uy)/b): multiply across instead.
        let vx = i128::from(ux) * i128::from(b);
        let vy = i128::from(uy) * i128::from(a);
        let (vx, vy) = shrink(vx, vy);
        i64::from(atan2(vy, vx))
    };
    let t1 = ang(x1 - cxp, y1 - cyp);
    let t2 = ang(-x1 - cxp, -y1 - cyp);
    let mut dt = (t2 - t1).rem_euclid(TURN);
    if !sweep && dt > 0 {
        dt -= TURN;
    }
    let frame = EllipseFrame::with_q8(centre, a, b, Unit { x: c, y: s });
    arc_cubics(&frame, t1, dt, Some(p2), sink);
}

/// Both scaled down by a power of two into `i64`.
fn shrink(mut x: i128, mut y: i128) -> (i64, i64) {
    while x.unsigned_abs() >= 1 << 62 || y.unsigned_abs() >= 1 << 62 {
        x >>= 1;
        y >>= 1;
    }
    (x as i64, y as i64)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(s: &str) -> Option<(i64, usize)> {
        parse_number(s.as_bytes(), 0)
    }

    #[test]
    fn numbers_round_to_the_nearest_fine_unit() {
        assert_eq!(num("1"), Some((1024, 1)));
        assert_eq!(num("-2.5"), Some((-2560, 4)));
        assert_eq!(num(".5"), Some((512, 2)));
        assert_eq!(num("5."), Some((5120, 2)));
        assert_eq!(num("1e3"), Some((1_024_000, 3)));
        assert_eq!(num("1E-3"), Some((1, 4))); // 1.024 rounds to 1
        assert_eq!(num("0.0009765625"), Some((1, 12)));
        assert_eq!(num("0.00048828125"), Some((1, 13))); // half: away from zero
        assert_eq!(num("-0.00048828125"), Some((-1, 14)));
        assert_eq!(num("1e"), Some((1024, 1))); // the 'e' is not part of it
        assert_eq!(num("1.5.5"), Some((1536, 3)));
        assert_eq!(num("."), None);
        assert_eq!(num("-"), None);
        assert_eq!(num("00000000000000000000000000001"), Some((1024, 29)));
        assert_eq!(num("1e999999999"), Some((i64::MAX / 2, 11)));
        assert_eq!(num("1e-999999999").map(|v| v.0), Some(0));
    }

    #[test]
    fn long_division_is_exact() {
        assert_eq!(div_shift(1, 3, 60), (1u128 << 60) / 3);
        assert_eq!(div_shift(5, 0, 60), 0);
        assert_eq!(div_shift(u128::MAX >> 3, (u128::MAX >> 3) - 1, 4), 16);
    }

    #[test]
    fn first_command_must_be_a_move() {
        let e = parse_path_data("  L 1 2", &mut NullSink).unwrap_err();
        assert_eq!(e, err(2, SvgErrorKind::MissingMoveTo));
        assert!(parse_path_data("", &mut NullSink).is_ok());
        assert!(parse_path_data(" \n", &mut NullSink).is_ok());
    }

    #[test]
    fn errors_carry_position_and_kind() {
        let cases = [
            ("M 0 0 X", 6, SvgErrorKind::ExpectedCommand),
            ("M 0 0 L 1", 9, SvgErrorKind::ExpectedNumber),
            ("M 0 0 A 1 1 0 2 0 5 5", 14, SvgErrorKind::ExpectedFlag),
            ("M 0 0 L 9000 0", 8, SvgErrorKind::NumberOutOfRange),
            ("M 0 0 L 2049 0", 8, SvgErrorKind::PointOutOfRange),
            ("M 2000 0 l 100 0", 11, SvgErrorKind::PointOutOfRange),
            ("M 0 0 Z 5", 8, SvgErrorKind::ExpectedCommand),
        ];
        for (d, at, kind) in cases {
            assert_eq!(parse_path_data(d, &mut NullSink), Err(err(at, kind)), "{d}");
        }
    }
}
