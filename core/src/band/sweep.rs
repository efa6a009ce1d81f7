//! The span sweep: one shape's coverage, summed along each row of the
//! scratch, composed into the band (over, add, or the attenuation that
//! starts a multi-plane shape's over).
//!
//! Per row a running sum of the cover changes (exact integers) gives each
//! pixel the shape's signed coverage; between changes it is constant, so
//! the row is a few runs: the edge pixels, one coverage each, and the
//! interior spans. The fill rule turns the sum into a share `s` of the
//! pixel; a run is composed with its paint set up once (a flat colour, or
//! the Gouraud plane at the run's first pixel: two multiplies per channel)
//! and stepped by one addition per pixel. Per pixel of a run:
//!
//! | op | whole pixel, opaque | part of a pixel |
//! | --- | --- | --- |
//! | over, flat | store | 1 multiply per channel |
//! | over, plane | store | 1 multiply per channel |
//! | add, flat | add | add (the product is per run) |
//! | add, plane | add | 1 multiply per channel |
//! | attenuate | store 0 | 1 multiply per channel |
//!
//! A partial pixel's product `v * k / 2^16` is two 32-bit multiplies (the
//! operand split in two, see [`mul_share`]), within one unit, 1/65536 of
//! a level, of the exact `acc (1 - k) + I k`. The sweep clears what it
//! reads, for the next shape.

use super::tags::{self, MIXED};
use super::BandBuffer;
#[cfg(feature = "text")]
use super::{tags::Palette, ROW_HEAD};
use crate::shade::{Plane, PLANE_FRAC};
use crate::style::{FillRule, Opacity};
use crate::{COVER_BITS, COVER_ONE};

// A plane's fine intensity is exactly an accumulator value: lin12 * 2^16.
const _: () = assert!(PLANE_FRAC == COVER_BITS);

/// Bits of an [`Opacity`].
const ALPHA_BITS: u32 = 12;
/// Largest operand of [`mul_share`]: `(|v| >> 16) * 2^16` stays below 2^31.
const V_LIMIT: i32 = (1 << 29) - 1;

/// What colour a shape's pixels get.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Paint<'p, const C: usize> {
    /// One linear 12-bit colour.
    Flat([u16; C]),
    /// A Gouraud plane of absolute intensity (built over a zero
    /// background).
    Plane(&'p Plane<C>),
    /// A linear or radial gradient (`band/gradient.rs`).
    Gradient(&'p crate::style::Gradient<C>),
    /// An image's texels, filtered (`band/image.rs`).
    Image(&'p dyn super::image::ImageRuns<C>),
}

/// How a shape's coverage meets the band.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ComposeOp {
    /// `acc = acc (1 - s α) + I s α`.
    Over(Opacity),
    /// `acc += (I - bg) s α`.
    Add(Opacity),
    /// `acc = acc (1 - s α)`: the first half of an over whose colour is
    /// then added plane by plane (a Gouraud mesh composed as one shape).
    Attenuate(Opacity),
    /// `acc += I s α`: the second half.
    Accumulate(Opacity),
}

/// How a pixel's winding integral becomes its share of a shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Coverage {
    /// A simple outline of known orientation (`+1` or `-1`, the sign of
    /// its area): the integral times it, linear, so that shapes sharing
    /// an edge add up exactly (what `Blend::Add` needs); the sweep limits
    /// it to `0..=1` px for over, `-1..=1` px for add.
    Signed(i32),
    /// Any outline, by a fill rule.
    Rule(FillRule),
    /// By a fill rule, then sharpened for a 1-bit display
    /// ([`Edges`](crate::style::Edges)).
    Sharpened(FillRule, crate::style::Edges),
}

/// The share of a pixel covered, from its winding integral `c` (coverage
/// units).
#[inline]
fn share(c: i32, coverage: Coverage) -> i32 {
    match coverage {
        Coverage::Signed(o) => c.wrapping_mul(o),
        Coverage::Rule(FillRule::NonZero) => {
            let a = c.unsigned_abs();
            if a >= COVER_ONE as u32 {
                COVER_ONE
            } else {
                a as i32
            }
        }
        Coverage::Rule(FillRule::EvenOdd) => {
            let m = c & (2 * COVER_ONE - 1);
            if m > COVER_ONE {
                2 * COVER_ONE - m
            } else {
                m
            }
        }
        Coverage::Sharpened(rule, edges) => edges.sharpen(share(c, Coverage::Rule(rule))),
    }
}

impl<const C: usize> BandBuffer<'_, C> {
    /// Composes the shape whose edges were just walked into the scratch over
    /// frame rows `y_lo..y_hi` (clipped to the band), and clears the
    /// scratch there.
    #[inline(never)] // kept out of line so profiles can name it
    pub(crate) fn compose(
        &mut self,
        y_lo: i32,
        y_hi: i32,
        rule: Coverage,
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) {
        // One sweep per kind of span, chosen once per shape.
        let bg = self.background;
        let base = |op: ComposeOp| {
            if matches!(op, ComposeOp::Add(_)) {
                bg
            } else {
                [0; C]
            }
        };
        match (op, paint) {
            (ComposeOp::Over(a), Paint::Flat(color)) => {
                let f = color.map(|v| i32::from(v) << COVER_BITS);
                match rule {
                    // The common case, with its own row loop.
                    Coverage::Rule(FillRule::NonZero) | Coverage::Signed(1) if a.is_opaque() => {
                        let signed = rule == Coverage::Signed(1);
                        self.sweep_over_flat(y_lo, y_hi, &f, signed);
                    }
                    _ => self.sweep(y_lo, y_hi, rule, a, true, &OverFlat(f)),
                }
            }
            (ComposeOp::Over(a), Paint::Plane(plane)) => {
                // A Gouraud plane gives every pixel it covers a value of
                // its own: no tag can say it, and a band with one is a
                // mesh's band, cheaper without tags (see `Palette`).
                self.go_dense();
                self.sweep(y_lo, y_hi, rule, a, true, &OverPlane(plane));
            }
            (ComposeOp::Add(a) | ComposeOp::Accumulate(a), Paint::Flat(color)) => {
                let base = base(op);
                let diff = core::array::from_fn(|ch| i32::from(color[ch]) - i32::from(base[ch]));
                self.sweep(y_lo, y_hi, rule, a, false, &AddFlat(diff));
            }
            (ComposeOp::Add(a) | ComposeOp::Accumulate(a), Paint::Plane(plane)) => {
                let bgf = base(op).map(|b| i32::from(b) << COVER_BITS);
                self.sweep(y_lo, y_hi, rule, a, false, &AddPlane(plane, bgf));
            }
            (ComposeOp::Over(a), Paint::Gradient(g)) => {
                self.sweep(y_lo, y_hi, rule, a, true, &GradientRun { g, op, bg });
            }
            (ComposeOp::Add(a) | ComposeOp::Accumulate(a), Paint::Gradient(g)) => {
                self.sweep(y_lo, y_hi, rule, a, false, &GradientRun { g, op, bg });
            }
            (
                ComposeOp::Over(a) | ComposeOp::Add(a) | ComposeOp::Accumulate(a),
                Paint::Image(i),
            ) => {
                let run = super::image::ImageRun { image: *i, op, bg };
                self.sweep(y_lo, y_hi, rule, a, matches!(op, ComposeOp::Over(_)), &run);
            }
            (ComposeOp::Attenuate(a), _) => {
                self.sweep(y_lo, y_hi, rule, a, true, &Attenuate);
            }
        }
    }

    /// [`compose`](Self::compose) of an opaque flat colour over, with the
    /// orientation-signed coverage of a simple outline (`Coverage::Signed(1)`):
    /// what most triangles of most bands are, without the choice of sweep.
    #[inline(never)] // kept out of line so profiles can name it
    pub(crate) fn compose_opaque_flat(&mut self, y_lo: i32, y_hi: i32, color: &[u16; C]) {
        let f = color.map(|v| i32::from(v) << COVER_BITS);
        self.sweep_over_flat(y_lo, y_hi, &f, true);
    }

    /// The sweep of rows `y_lo..y_hi`: per row, the running sum of the
    /// scratch's changes (clearing them) gives each pixel its coverage,
    /// constant between changes ([`sweep_row`]). `convex`: the share is
    /// clamped to `0..=1` px first (over, attenuate).
    #[inline(always)]
    fn sweep<O: RunOp<C>>(
        &mut self,
        y_lo: i32,
        y_hi: i32,
        rule: Coverage,
        alpha: Opacity,
        convex: bool,
        op: &O,
    ) {
        let w = usize::from(self.band.width);
        let x0 = self.band.x0;
        let opaque = alpha.is_opaque();
        let a4096 = i32::from(alpha.to_4096ths());
        // The factor of the pixels from a change on: the share times the
        // opacity (coverage units), WHOLE for whole pixels of an opaque
        // shape, SKIP for a share whose composite rounds to nothing, 0 for
        // no share.
        let factor = |c: i32| -> i32 {
            let s = share(c, rule);
            if s == 0 {
                return 0;
            }
            // A convex combination needs a share within the pixel; add
            // takes at most a whole pixel either way (a mesh whose
            // triangles overlap adds its colour once, as any shape), which
            // keeps every product below in `i32`.
            let s = if convex {
                s.clamp(0, COVER_ONE)
            } else {
                s.clamp(-COVER_ONE, COVER_ONE)
            };
            let k = if opaque {
                if s == COVER_ONE {
                    return WHOLE;
                }
                s
            } else {
                // |s| <= 2^16, a4096 <= 2^12.
                (s * a4096) >> ALPHA_BITS
            };
            if k == 0 {
                SKIP
            } else {
                k
            }
        };
        for (y, mut row) in self.sweep_rows(y_lo, y_hi) {
            let (lo, hi, dense) = (row.lo, row.hi, row.dense);
            let Some(changes) = row.deltas.get_mut(lo..=hi) else {
                continue;
            };
            let x = x0.saturating_add(lo as i32);
            let mut pixels = RowPixels {
                acc: &mut *row.acc,
                tags: (!dense).then_some((&mut *row.tags, row.palette)),
            };
            // A dense band's rows (a Gouraud mesh's) in a loop without
            // the test for tags at every run.
            let (first, last) = if dense {
                sweep_row::<_, _, C, false>(op, changes, &mut pixels, lo, w, (x, y), &factor)
            } else {
                sweep_row::<_, _, C, true>(op, changes, &mut pixels, lo, w, (x, y), &factor)
            };
            if first < last {
                row.mark(lo + first, lo + last);
            }
        }
    }
}

impl<const C: usize> BandBuffer<'_, C> {
    /// [`sweep`](Self::sweep) of an opaque flat colour `f` over, with the
    /// nonzero rule (`signed`: the orientation-signed coverage of a simple
    /// outline, clamped), row by row in [`over_flat_row`].
    // Inlined into its two callers (`compose`, `compose_opaque_flat`): a
    // call of its own cost every shape in every band some 12 instructions.
    #[inline(always)]
    fn sweep_over_flat(&mut self, y_lo: i32, y_hi: i32, f: &[i32; C], signed: bool) {
        let w = usize::from(self.band.width);
        let tag = self.flat_tag(f);
        let dense = self.palette.dense;
        let flat = Flat { f: *f, tag, dense };
        for (_, mut row) in self.sweep_rows(y_lo, y_hi) {
            let (lo, hi) = (row.lo, row.hi);
            let Some(changes) = row.deltas.get_mut(lo..=hi) else {
                continue;
            };
            // The signed case (every flat triangle) in a loop of its own
            // for colours: a register more for the row's state. One
            // channel measures faster with the test in the loop. A dense
            // band has no tags to keep.
            let px = row.acc.get_mut(lo * C..).unwrap_or_default();
            let mut tagged = RowTags {
                words: &mut *row.tags,
                lo,
                tag,
                palette: row.palette,
            };
            let tail = w - lo;
            let f = &flat.f;
            let t = &mut tagged;
            // Unsigned outlines (circles, rings, paths, glyphs) skip their
            // gaps; signed ones (triangles) have few.
            let (first, last) = match (signed && C > 1, dense, signed) {
                (true, false, _) => {
                    over_flat_row::<C, true, true, false>(f, changes, px, tail, true, t)
                }
                (true, true, _) => {
                    over_flat_row::<C, true, false, false>(f, changes, px, tail, true, t)
                }
                (false, false, true) => {
                    over_flat_row::<C, false, true, false>(f, changes, px, tail, true, t)
                }
                (false, true, true) => {
                    over_flat_row::<C, false, false, false>(f, changes, px, tail, true, t)
                }
                (false, false, false) => {
                    over_flat_row::<C, false, true, true>(f, changes, px, tail, false, t)
                }
                (false, true, false) => {
                    over_flat_row::<C, false, false, true>(f, changes, px, tail, false, t)
                }
            };
            if first < last {
                row.mark(lo + first, lo + last);
            }
        }
    }
}

/// Entries of a [`MaskBlend`]'s memo.
#[cfg(feature = "text")]
const MEMO: usize = 64;
/// Palette entries a mask composite leaves free for the flat colours of
/// later shapes.
#[cfg(feature = "text")]
const MEMO_RESERVE: usize = 2;

#[cfg(feature = "text")]
impl<const C: usize> BandBuffer<'_, C> {
    /// [`compose`](Self::compose) of an opaque flat colour `color` over,
    /// nonzero rule, for a coverage given by masks (text): as the flat
    /// sweep, except that a partly covered pixel whose value is a palette
    /// colour gets its blend from a memo of the composite (made once per
    /// colour below and share, exactly as the sweep makes it) and, while
    /// the palette has room, the blend's own entry as its tag, so the
    /// flush sends it toned once for the band. A glyph mask has few
    /// shares (its levels), and the pixels below it few colours. A dense
    /// band composes as the flat sweep does.
    #[inline(never)] // kept out of line so profiles can name it
    pub(crate) fn compose_mask_over(&mut self, y_lo: i32, y_hi: i32, color: &[u16; C]) {
        let f = color.map(|v| i32::from(v) << COVER_BITS);
        let tag = self.flat_tag(&f);
        if self.palette.dense || tag == MIXED {
            self.sweep_over_flat(y_lo, y_hi, &f, false);
            return;
        }
        let mut memo = MaskBlend {
            f,
            keys: [u32::MAX; MEMO],
            tags: [0; MEMO],
        };
        let rows = self.rows_in_band(y_lo, y_hi);
        let w = usize::from(self.band.width);
        let n = tags::row_words(w);
        for y in rows {
            let r = (y - self.band.y0) as usize;
            let Some(head) = self
                .heads
                .get_mut(r * ROW_HEAD..r * ROW_HEAD + ROW_HEAD)
                .and_then(|h| h.first_chunk_mut::<ROW_HEAD>())
            else {
                continue;
            };
            let [lo_h, hi_h, dlo, dhi] = head;
            let (l, h) = (
                core::mem::replace(lo_h, i32::MAX),
                core::mem::replace(hi_h, i32::MIN),
            );
            if l > h {
                continue;
            }
            let (lo, hi) = (l.max(0) as usize, (h.max(0) as usize).min(w - 1));
            let (Some(changes), Some(acc), Some(words)) = (
                self.deltas.get_mut(r * w + lo..=r * w + hi),
                self.acc.get_mut(r * w * C..(r + 1) * w * C),
                self.tags.get_mut(r * n..r * n + n),
            ) else {
                continue;
            };
            let mut c: i32 = 0;
            let mut s: i32 = 0;
            let (mut first, mut last) = (usize::MAX, lo);
            let cols = hi + 1 - lo;
            let mut i = 0;
            while i < cols {
                let Some(d) = changes.get_mut(i) else {
                    break;
                };
                if *d != 0 {
                    c = c.wrapping_add(core::mem::take(d));
                    s = c.unsigned_abs().min(COVER_ONE as u32) as i32;
                }
                let x = lo + i;
                i += 1;
                if s == 0 {
                    // Empty pixels to the next change (between glyphs).
                    let rest = changes.get(i..).unwrap_or_default();
                    i += rest.iter().position(|&d| d != 0).unwrap_or(rest.len());
                    continue;
                }
                first = first.min(x);
                if s == COVER_ONE {
                    // Whole pixels to the next change: the colour's tag.
                    let rest = changes.get(i..).unwrap_or_default();
                    let k = rest.iter().position(|&d| d != 0).unwrap_or(rest.len());
                    tags::fill(words, x, x + k + 1, tag);
                    i += k;
                    last = x + k + 1;
                    continue;
                }
                memo.part(&mut self.palette, words, acc, x, s);
                last = x + 1;
            }
            // Coverage left after the last change runs to the band's end
            // (a mask cut by the band's right side).
            if s != 0 {
                first = first.min(hi + 1);
                if s == COVER_ONE {
                    tags::fill(words, hi + 1, w, tag);
                } else {
                    for x in hi + 1..w {
                        memo.part(&mut self.palette, words, acc, x, s);
                    }
                }
                last = w;
            }
            if first < last {
                super::mark_extent(dlo, dhi, first, last);
            }
        }
    }
}

/// A mask composite's colour `f` (accumulator units) and its memo: per
/// slot, the key `share << 8 | tag below` and the tag of the blend.
#[cfg(feature = "text")]
struct MaskBlend<const C: usize> {
    f: [i32; C],
    keys: [u32; MEMO],
    tags: [u8; MEMO],
}

#[cfg(feature = "text")]
impl<const C: usize> MaskBlend<C> {
    /// Pixel `x` of a row (its tag `words`, its accumulator `acc`) covered
    /// by the share `s` (`0 < s < COVER_ONE`): a pixel tagged with a
    /// palette colour gets its blend's entry (from the memo, or made and
    /// kept in `palette` while it leaves [`MEMO_RESERVE`] entries free),
    /// any other its blended value, tagged `MIXED`.
    #[inline(always)]
    fn part(
        &mut self,
        palette: &mut Palette<C>,
        words: &mut [i32],
        acc: &mut [i32],
        x: usize,
        s: i32,
    ) {
        let shift = (x & 3) << 3;
        let (Some(word), Some(p)) = (
            words.get_mut(x >> 2),
            acc.get_mut(x * C..x * C + C)
                .and_then(|p| p.first_chunk_mut::<C>()),
        ) else {
            return;
        };
        let t = (*word >> shift) as u8;
        if t == MIXED || t == tags::SOURCE {
            if t == tags::SOURCE {
                // An image's code: its value, then blended as any other.
                tags::load(p, t, palette.entries());
                *word |= 0xff << shift;
            }
            blend_over(p, &self.f, s);
            return;
        }
        let key = (s as u32) << 8 | u32::from(t);
        let slot = (key.wrapping_mul(0x9e37_79b1) >> 26) as usize & (MEMO - 1);
        if self.keys.get(slot) == Some(&key) {
            let b = self.tags.get(slot).copied().unwrap_or(MIXED);
            if usize::from(b) < palette.len() {
                // The blend's entry is its value (see `band::tags`).
                *word = (*word & !(0xff << shift)) | (i32::from(b) << shift);
                return;
            }
        }
        // The value below is the entry's (the accumulator may hold another),
        // blended in a local (a copy into `p` first was a library move).
        let mut q = palette.entries().get(usize::from(t)).copied().unwrap_or(*p);
        blend_over(&mut q, &self.f, s);
        *p = q;
        let room = palette.len() + MEMO_RESERVE < tags::PALETTE;
        match room.then(|| palette.intern(p)).flatten() {
            Some(b) => {
                if let (Some(k), Some(bt)) = (self.keys.get_mut(slot), self.tags.get_mut(slot)) {
                    (*k, *bt) = (key, b);
                }
                *word = (*word & !(0xff << shift)) | (i32::from(b) << shift);
            }
            None => *word |= 0xff << shift,
        }
    }
}

/// An opaque flat colour `f` (accumulator units) and its tag in the
/// band's palette (`MIXED` when it has none); `dense`: the band keeps no
/// tags (see [`Palette`]).
pub(super) struct Flat<const C: usize> {
    pub(super) f: [i32; C],
    pub(super) tag: u8,
    pub(super) dense: bool,
}

impl<const C: usize> Flat<C> {
    /// Pixels `c0..c1` of a row (its accumulator and tags) wholly covered
    /// by `f`: tagged with its entry, or in a dense band stored.
    pub(super) fn whole(&self, acc: &mut [i32], words: &mut [i32], c0: usize, c1: usize) {
        if self.dense {
            store(acc, c0, c1.saturating_sub(c0), &self.f);
        } else {
            tags::fill(words, c0, c1, self.tag);
        }
    }
}

/// A row's tags as an opaque flat over keeps them: the row's tag words,
/// the column where the pixels given start, the colour's tag and the
/// band's palette (a tagged pixel's value).
pub(super) struct RowTags<'w, const C: usize> {
    words: &'w mut [i32],
    lo: usize,
    tag: u8,
    palette: &'w [[i32; C]],
}

impl<const C: usize> RowTags<'_, C> {
    /// Row pixel `c`'s value into its accumulator `p` (from its entry when
    /// it is tagged with one), and its tag `MIXED`: it is about to be
    /// blended.
    #[inline(always)]
    fn take(&mut self, p: &mut [i32; C], c: usize) {
        tags::take(p, self.words, self.palette, c);
    }
}

/// One row of an opaque flat over (see [`sweep_row`]): the share of a
/// pixel is its coverage clamped to `0..=1` px (`SIGNED` or `signed`: the
/// first fixed at compile time) or its size clamped to 1 px (nonzero);
/// whole pixels are stored (a tight loop to the next change), partial ones
/// blended; with `TAGS`, whole pixels are tagged with the colour's tag and
/// the others `MIXED` (see `band::tags`). `changes` are the row's from its
/// column `tags.lo` on, `px` the row's pixels from there to the band's end
/// (`tail` of them). The drawn extent it returns (relative to `tags.lo`) is
/// a superset of the pixels drawn, found without a test per change: from
/// the row's first change (where a simple outline's share starts) to its
/// last, or to the band's end when coverage is left; a pixel marked but not
/// drawn holds what it held, and the flush gives it the same colour (a row
/// whose changes cancel out is marked too, at the cost of resolving it).
#[inline(never)]
fn over_flat_row<const C: usize, const SIGNED: bool, const TAGS: bool, const GAPS: bool>(
    f: &[i32; C],
    changes: &mut [i32],
    px: &mut [i32],
    tail: usize,
    signed: bool,
    tags: &mut RowTags<'_, C>,
) -> (usize, usize) {
    let n = changes.len();
    let mut c: i32 = 0;
    // The share of the pixels from the last change on.
    let mut s: i32 = 0;
    let mut i = 0;
    while i < n {
        let Some(d) = changes.get_mut(i) else {
            break;
        };
        let dv = *d;
        if dv != 0 {
            *d = 0;
            c = c.wrapping_add(dv);
            s = if SIGNED || signed {
                c.clamp(0, COVER_ONE)
            } else {
                c.unsigned_abs().min(COVER_ONE as u32) as i32
            };
        }
        let at = i;
        i += 1;
        if s == COVER_ONE {
            // The run's whole pixels: to the next change (found first, a
            // tight loop), then stored from a slice of exactly that many
            // pixels, stepped a chunk at a time (a loop bounded by the
            // pixels left would make the compiler divide their count by
            // C, a library call on the Cortex-M0), and tagged.
            // With a tag the run's pixels are only tagged (the tag is
            // their value; see `band::tags`), else stored.
            if GAPS {
                // Long runs (a disc's interior): four changes at a time,
                // two pixels at a time.
                let k = next_change(changes, i) - i;
                if !TAGS || tags.tag == MIXED {
                    store_long(px, at, k + 1, f);
                }
                if TAGS {
                    tags::fill(tags.words, tags.lo + at, tags.lo + at + k + 1, tags.tag);
                }
                i += k;
                continue;
            }
            let rest = changes.get(i..).unwrap_or_default();
            let k = rest.iter().position(|&d| d != 0).unwrap_or(rest.len());
            if !TAGS || tags.tag == MIXED {
                store(px, at, k + 1, f);
            }
            if TAGS {
                tags::fill(tags.words, tags.lo + at, tags.lo + at + k + 1, tags.tag);
            }
            i += k;
        } else if s != 0 {
            if let Some(p) = px
                .get_mut(at * C..at * C + C)
                .and_then(|p| p.first_chunk_mut::<C>())
            {
                if TAGS {
                    tags.take(p, tags.lo + at);
                }
                blend_over(p, f, s);
            }
        } else if GAPS {
            // No coverage (a ring's middle, between a glyph's strokes): to
            // the next change in a tight loop. Not for the signed rows of
            // flat triangles, whose gaps are rare and short.
            i = next_change(changes, i);
        }
    }
    if s != 0 {
        // Coverage left after the last change runs to the band's end.
        if s == COVER_ONE {
            if !TAGS || tags.tag == MIXED {
                store(px, n, tail.saturating_sub(n), f);
            }
            if TAGS {
                tags::fill(tags.words, tags.lo + n, tags.lo + tail, tags.tag);
            }
        } else {
            let mut rest = px.get_mut(n * C..tail * C).unwrap_or_default();
            let mut c = tags.lo + n;
            while let Some((p, more)) = core::mem::take(&mut rest).split_first_chunk_mut::<C>() {
                if TAGS {
                    tags.take(p, c);
                }
                blend_over(p, f, s);
                (rest, c) = (more, c + 1);
            }
        }
        (0, n.max(tail))
    } else {
        // The last pixel of the row's changes has no share: its change
        // ended the coverage, or it has none and the share before it was
        // none.
        (0, n.saturating_sub(1))
    }
}

/// The first change of `changes` from `i` on, or its length (out of
/// line: the row loop keeps its registers).
#[inline(never)]
fn next_change(changes: &[i32], i: usize) -> usize {
    let rest = changes.get(i..).unwrap_or_default();
    // Four at a time (one test of their union), then one by one.
    let mut k = 0;
    for four in rest.chunks_exact(4) {
        if let [a, b, c, d] = *four {
            if a | b | c | d != 0 {
                break;
            }
        }
        k += 4;
    }
    let tail = rest.get(k..).unwrap_or_default();
    i + k + tail.iter().position(|&d| d != 0).unwrap_or(tail.len())
}

/// `f` into the `k` pixels of `px` from pixel `a` on.
#[inline(always)]
fn store<const C: usize>(px: &mut [i32], a: usize, k: usize, f: &[i32; C]) {
    let at = a * C;
    let mut run = px.get_mut(at..at + k * C).unwrap_or_default();
    while let Some((p, rest)) = core::mem::take(&mut run).split_first_chunk_mut::<C>() {
        *p = *f;
        run = rest;
    }
}

/// [`store`] for the long runs of unsigned outlines (a disc's interior):
/// three channels two pixels a step, six words, which a Cortex-M0 stores
/// with one store-multiple. (Not for triangles: their short runs measure
/// slower with it.)
#[inline(always)]
fn store_long<const C: usize>(px: &mut [i32], a: usize, k: usize, f: &[i32; C]) {
    let at = a * C;
    let mut run = px.get_mut(at..at + k * C).unwrap_or_default();
    if C == 3 {
        let c = |i: usize| f.get(i).copied().unwrap_or(0);
        let two = [c(0), c(1), c(2), c(0), c(1), c(2)];
        // (The length first: a failed split would leave `run` taken.)
        while run.len() >= 6 {
            if let Some((p, rest)) = core::mem::take(&mut run).split_first_chunk_mut::<6>() {
                *p = two;
                run = rest;
            }
        }
    }
    while let Some((p, rest)) = core::mem::take(&mut run).split_first_chunk_mut::<C>() {
        *p = *f;
        run = rest;
    }
}

/// A partly covered pixel of an opaque flat over (out of line: the row
/// loop keeps its registers).
#[inline(never)]
fn blend_over<const C: usize>(p: &mut [i32; C], f: &[i32; C], k: i32) {
    OverFlat(*f).part(p, k, &());
}

/// Factors that mark whole pixels of an opaque shape, and a share whose
/// composite rounds to nothing (drawn, unchanged).
pub(super) const WHOLE: i32 = i32::MAX;
pub(super) const SKIP: i32 = i32::MIN;

/// A band row's pixels as a sweep composes them: the accumulator of the
/// whole row, and (unless the band is dense) its tags and the palette.
pub(super) struct RowPixels<'r, const C: usize> {
    pub(super) acc: &'r mut [i32],
    pub(super) tags: Option<(&'r mut [i32], &'r [[i32; C]])>,
}

impl<const C: usize> RowPixels<'_, C> {
    /// The accumulator of pixels `c0..c1`, to be changed, tagged `MIXED`;
    /// with `read`, holding their values (a tagged pixel's from its entry;
    /// see `band::tags`).
    /// `TAGS`: the band keeps tags (known to the row loop; `tags` is then
    /// `Some`).
    #[inline(always)]
    pub(super) fn take<const TAGS: bool>(
        &mut self,
        c0: usize,
        c1: usize,
        read: bool,
    ) -> &mut [i32] {
        if let (true, Some((words, palette))) = (TAGS, &mut self.tags) {
            if c1 == c0 + 1 {
                // One pixel (an edge's runs are mostly one pixel each):
                // its tag read and set here, no call (not `tags::take`:
                // a `MIXED` pixel is left alone, 1.3 % of the Gouraud
                // screen on the Cortex-M0).
                let t = tags::get(words, c0);
                if t != MIXED {
                    if let (true, Some(p)) = (
                        read,
                        self.acc
                            .get_mut(c0 * C..c1 * C)
                            .and_then(|p| p.first_chunk_mut::<C>()),
                    ) {
                        tags::load(p, t, palette);
                    }
                    tags::set_mixed(words, c0);
                }
            } else {
                if read {
                    tags::materialise(self.acc, words, palette, c0, c1);
                }
                tags::fill(words, c0, c1, MIXED);
            }
        }
        self.acc.get_mut(c0 * C..c1 * C).unwrap_or_default()
    }

    /// Tags pixels `c0..c1` [`SOURCE`](tags::SOURCE): their accumulators
    /// were given Rgb565 codes (see `band::tags`).
    #[inline(always)]
    fn mark_codes(&mut self, c0: usize, c1: usize) {
        if let Some((words, _)) = &mut self.tags {
            tags::fill(words, c0, c1, tags::SOURCE);
        }
    }
}

/// One row of a sweep: `changes` (the row's from its first change at
/// column `lo` on, cleared here) and the row's pixels, `w` of them, the
/// one at `lo` frame pixel `(x, y)`. Each pixel's coverage is the running
/// sum; at each change the factor is found once (`factor`: [`WHOLE`],
/// [`SKIP`], 0 for no share, or the composite's factor), and the run of
/// pixels up to the next change composed with it; coverage left after the
/// last change carries on to the band's end. Returns the drawn extent
/// (relative to `lo`): from the first pixel with a share to the end of the
/// last run with one. Out of line, so that its loops keep their values in
/// registers.
#[inline(never)]
fn sweep_row<O: RunOp<C>, F: Fn(i32) -> i32, const C: usize, const TAGS: bool>(
    op: &O,
    changes: &mut [i32],
    pixels: &mut RowPixels<'_, C>,
    lo: usize,
    w: usize,
    (x, y): (i32, i32),
    factor: &F,
) -> (usize, usize) {
    let n = changes.len();
    let tail = w - lo;
    let mut c: i32 = 0;
    let (mut first, mut last) = (usize::MAX, 0);
    let mut i = 0;
    while let Some(d) = changes.get_mut(i) {
        c = c.wrapping_add(core::mem::take(d));
        // The run: to the next change, or to the band's end if coverage
        // remains after the last one.
        let mut j = i + 1;
        while let Some(0) = changes.get(j) {
            j += 1;
        }
        let end = if j >= n && c != 0 { tail } else { j };
        let k = factor(c);
        if k != 0 {
            if first == usize::MAX {
                first = i;
            }
            last = end;
            if k != SKIP {
                let run = pixels.take::<TAGS>(lo + i, lo + end, op.reads(k));
                if op.run(run, k, (x.wrapping_add(i as i32), y), TAGS) {
                    pixels.mark_codes(lo + i, lo + end);
                }
            }
        }
        i = j;
    }
    (first, last)
}

/// A run of pixels of factor `k` (see [`sweep_row`]), the first at frame
/// pixel `(x, y)`.
#[inline(always)]
fn compose_run<O: SpanOp<C>, const C: usize>(op: &O, px: &mut [i32], k: i32, (x, y): (i32, i32)) {
    let mut cur = op.cursor(x, y);
    let mut px = px;
    if k == WHOLE {
        while let Some((p, rest)) = core::mem::take(&mut px).split_first_chunk_mut::<C>() {
            op.whole(p, &cur);
            op.step(&mut cur);
            px = rest;
        }
    } else if k != SKIP {
        while let Some((p, rest)) = core::mem::take(&mut px).split_first_chunk_mut::<C>() {
            op.part(p, k, &cur);
            op.step(&mut cur);
            px = rest;
        }
    }
}

/// How one kind of span composes a run of pixels of factor `k` (see
/// [`sweep_row`]), the first at frame pixel `(x, y)`: pixel by pixel for
/// every [`SpanOp`], by its own stepping for a gradient.
pub(super) trait RunOp<const C: usize> {
    /// Composes the run. `codes`: the band keeps tags, so a run of whole
    /// pixels may be given Rgb565 codes (see `band::tags`); true when it
    /// was (the caller tags it so).
    fn run(&self, px: &mut [i32], k: i32, at: (i32, i32), codes: bool) -> bool;

    /// False when a run of factor `k` replaces its pixels without reading
    /// them (an opaque image's whole pixels): their values need not be
    /// taken from their tags first (see `band::tags`).
    #[inline(always)]
    fn reads(&self, _k: i32) -> bool {
        true
    }
}

impl<O: SpanOp<C>, const C: usize> RunOp<C> for O {
    #[inline(always)]
    fn run(&self, px: &mut [i32], k: i32, at: (i32, i32), _: bool) -> bool {
        compose_run(self, px, k, at);
        false
    }

    #[inline(always)]
    fn reads(&self, k: i32) -> bool {
        !(O::WHOLE_REPLACES && k == WHOLE)
    }
}

/// A gradient's runs, composed in `band/gradient.rs` (its ramps step
/// per sub-run, not per pixel).
struct GradientRun<'g, const C: usize> {
    g: &'g crate::style::Gradient<C>,
    op: ComposeOp,
    bg: [u16; C],
}

impl<const C: usize> RunOp<C> for GradientRun<'_, C> {
    #[inline(always)]
    fn run(&self, px: &mut [i32], k: i32, (x, y): (i32, i32), _: bool) -> bool {
        if k == SKIP {
            return false;
        }
        let whole = k == WHOLE;
        let k = if whole { COVER_ONE } else { k };
        super::gradient::compose(px, k, whole, x, y, self.g, self.op, self.bg);
        false
    }
}

/// How one kind of span composes a pixel (`C` values), chosen once per
/// shape; `Cursor` is what it steps along a row (a Gouraud plane's value).
trait SpanOp<const C: usize> {
    type Cursor;
    /// [`whole`](Self::whole) replaces the pixel without reading it (an
    /// over's): a run of whole pixels need not hold their values first.
    const WHOLE_REPLACES: bool = false;
    /// The cursor at frame pixel `(x, y)` (row set-up).
    fn cursor(&self, x: i32, y: i32) -> Self::Cursor;
    /// One pixel to the right.
    fn step(&self, cur: &mut Self::Cursor);
    /// A whole pixel of an opaque shape.
    fn whole(&self, p: &mut [i32; C], cur: &Self::Cursor);
    /// A pixel covered by the factor `k` (coverage units, signed for add).
    fn part(&self, p: &mut [i32; C], k: i32, cur: &Self::Cursor);
}

/// `acc = acc (1 - k) + I k`, one colour (`I` in accumulator units).
struct OverFlat<const C: usize>([i32; C]);

impl<const C: usize> SpanOp<C> for OverFlat<C> {
    type Cursor = ();
    const WHOLE_REPLACES: bool = true;
    #[inline(always)]
    fn cursor(&self, _: i32, _: i32) {}
    #[inline(always)]
    fn step(&self, _: &mut ()) {}
    #[inline(always)]
    fn whole(&self, p: &mut [i32; C], _: &()) {
        *p = self.0;
    }
    #[inline(always)]
    fn part(&self, p: &mut [i32; C], k: i32, _: &()) {
        let f = &self.0;
        // Both in 0..2^28 (every over composite of intensities is): the
        // difference needs no limiting; else the general product.
        if p.iter().fold(0, |m, &v| m | v) as u32 >> 28 == 0 {
            for ch in 0..C {
                p[ch] += mul_share_unlimited(f[ch] - p[ch], k);
            }
        } else {
            for ch in 0..C {
                p[ch] += mul_share(f[ch] - p[ch], k);
            }
        }
    }
}

/// `acc = acc (1 - k) + I k`, a Gouraud plane.
struct OverPlane<'p, const C: usize>(&'p Plane<C>);

impl<const C: usize> SpanOp<C> for OverPlane<'_, C> {
    type Cursor = [i32; C];
    const WHOLE_REPLACES: bool = true;
    #[inline(always)]
    fn cursor(&self, x: i32, y: i32) -> [i32; C] {
        plane_at(self.0, x, y)
    }
    #[inline(always)]
    fn step(&self, v: &mut [i32; C]) {
        for ch in 0..C {
            v[ch] = v[ch].wrapping_add(self.0.gx[ch]);
        }
    }
    #[inline(always)]
    fn whole(&self, p: &mut [i32; C], v: &[i32; C]) {
        *p = *v;
    }
    #[inline(always)]
    fn part(&self, p: &mut [i32; C], k: i32, v: &[i32; C]) {
        for ch in 0..C {
            p[ch] += mul_share(v[ch] - p[ch], k);
        }
    }
}

/// `acc += (I - base) k`, one colour: the per-channel difference in
/// linear 12-bit units, so `(I - base) k` is one exact product (below
/// `2^12 * 2^16`).
struct AddFlat<const C: usize>([i32; C]);

impl<const C: usize> SpanOp<C> for AddFlat<C> {
    type Cursor = ();
    #[inline(always)]
    fn cursor(&self, _: i32, _: i32) {}
    #[inline(always)]
    fn step(&self, _: &mut ()) {}
    #[inline(always)]
    fn whole(&self, p: &mut [i32; C], _: &()) {
        self.part(p, COVER_ONE, &());
    }
    #[inline(always)]
    fn part(&self, p: &mut [i32; C], k: i32, _: &()) {
        for ch in 0..C {
            p[ch] = p[ch].saturating_add(self.0[ch] * k);
        }
    }
}

/// `acc += (I - base) k`, a Gouraud plane and the base in accumulator
/// units.
struct AddPlane<'p, const C: usize>(&'p Plane<C>, [i32; C]);

impl<const C: usize> SpanOp<C> for AddPlane<'_, C> {
    type Cursor = [i32; C];
    #[inline(always)]
    fn cursor(&self, x: i32, y: i32) -> [i32; C] {
        plane_at(self.0, x, y)
    }
    #[inline(always)]
    fn step(&self, v: &mut [i32; C]) {
        for ch in 0..C {
            v[ch] = v[ch].wrapping_add(self.0.gx[ch]);
        }
    }
    #[inline(always)]
    fn whole(&self, p: &mut [i32; C], v: &[i32; C]) {
        for ch in 0..C {
            p[ch] = p[ch].saturating_add(v[ch] - self.1[ch]);
        }
    }
    #[inline(always)]
    fn part(&self, p: &mut [i32; C], k: i32, v: &[i32; C]) {
        for ch in 0..C {
            p[ch] = p[ch].saturating_add(mul_share(v[ch] - self.1[ch], k));
        }
    }
}

/// `acc = acc (1 - k)`.
struct Attenuate;

impl<const C: usize> SpanOp<C> for Attenuate {
    type Cursor = ();
    #[inline(always)]
    fn cursor(&self, _: i32, _: i32) {}
    #[inline(always)]
    fn step(&self, _: &mut ()) {}
    #[inline(always)]
    fn whole(&self, p: &mut [i32; C], _: &()) {
        *p = [0; C];
    }
    #[inline(always)]
    fn part(&self, p: &mut [i32; C], k: i32, _: &()) {
        for v in p.iter_mut() {
            *v -= mul_share(*v, k);
        }
    }
}

/// `floor(v * k / 2^16)` exactly, for a share `|k| <= 2^16`, in 32-bit
/// multiplies:
/// `v` is split at bit 16, so each product stays within 32 bits (`v` is
/// limited to `±2^29` first, two full scales beyond any intensity).
#[inline]
pub(super) fn mul_share(v: i32, k: i32) -> i32 {
    if k == COVER_ONE {
        return v;
    }
    // |v| <= V_LIMIT passes unchanged (one test); beyond, limited.
    let v = if v.unsigned_abs() <= V_LIMIT as u32 {
        v
    } else {
        v.clamp(-V_LIMIT, V_LIMIT)
    };
    mul_share_unlimited(v, k)
}

/// [`mul_share`] for `|v| <= 2^29 - 1`, `|k| <= 2^16`: `v` split at bit
/// 16, `v = h 2^16 + l` with `0 <= l < 2^16`, so `v k / 2^16 = h k + l k /
/// 2^16`, where `|h k| <= 2^29` and `l k < 2^32` unsigned (`0 <= k <=
/// 2^16`; a negative share is the product of the negated operands): two
/// multiplies and a shift, the floor exact.
#[inline]
fn mul_share_unlimited(v: i32, k: i32) -> i32 {
    let (v, k) = if k < 0 { (-v, -k) } else { (v, k) };
    let l = (v as u32 & ((1 << COVER_BITS) - 1)) * k as u32;
    (v >> COVER_BITS) * k + (l >> COVER_BITS) as i32
}

/// The plane at frame pixel `(x, y)`, in accumulator units (span set-up:
/// two 32-bit multiplies per channel).
///
/// Evaluated modulo `2^32`: the plane is composed only where its shape
/// covers part of a pixel, and there `|I| < 2 * 4096` levels, `2^29` in
/// accumulator units ([`shade`](crate::shade)'s range), so the wrapped
/// value is the exact one, and so is each step of `gx` to the next pixel of
/// a run (`|gx| <= 4095 * 2^16`).
#[inline]
fn plane_at<const C: usize>(plane: &Plane<C>, x: i32, y: i32) -> [i32; C] {
    let (di, dj) = (x.wrapping_sub(plane.i0), y.wrapping_sub(plane.j0));
    core::array::from_fn(|ch| {
        plane.at0[ch]
            .wrapping_add(plane.gx[ch].wrapping_mul(di))
            .wrapping_add(plane.gy[ch].wrapping_mul(dj))
    })
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn fill_rules_fold_the_winding_integral() {
        let one = COVER_ONE;
        let (nz, eo) = (
            Coverage::Rule(FillRule::NonZero),
            Coverage::Rule(FillRule::EvenOdd),
        );
        assert_eq!(share(one / 2, nz), one / 2);
        assert_eq!(share(-one / 2, nz), one / 2);
        assert_eq!(share(2 * one, nz), one);
        assert_eq!(share(2 * one, eo), 0);
        assert_eq!(share(3 * one / 2, eo), one / 2);
        assert_eq!(share(-one, eo), one);
        assert_eq!(share(-one / 4, eo), one / 4);
        // Signed: linear, so that a seam's two sides add up exactly.
        assert_eq!(share(-3, Coverage::Signed(1)), -3);
        assert_eq!(share(-one - 3, Coverage::Signed(-1)), one + 3);
    }

    #[test]
    fn over_at_half_coverage_is_the_linear_midpoint() {
        let (mut acc, mut cover) = ([0i32; 4], [0i32; 14]);
        let band = crate::band::Band::new(2, 0, 2);
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([1000]);
        buf.add_area(0, 0, COVER_ONE / 2);
        buf.compose(
            0,
            1,
            Coverage::Rule(FillRule::NonZero),
            &Paint::Flat([3000]),
            ComposeOp::Over(Opacity::OPAQUE),
        );
        assert_eq!(buf.lin12(0, 0), Some([2000]));
        assert_eq!(buf.lin12(1, 0), Some([1000]));
    }

    #[test]
    fn share_products_are_floors_of_the_exact_product() {
        for v in [
            -(1 << 29) + 1,
            -123_456_789,
            -1,
            0,
            1,
            77_777,
            (1 << 29) - 1,
        ] {
            for k in [0, 1, 2, 4095, 32768, 65535, 65536, -65536, -65535, -3] {
                let exact = (i64::from(v) * i64::from(k)).div_euclid(1 << 16);
                assert_eq!(i64::from(mul_share(v, k)), exact, "{v} * {k}");
            }
        }
        // And a walk over both operands' whole ranges, the low halves of
        // `v` at their extremes included.
        let mut rng = crate::path::testing::Lcg(0x51a2_e0f5);
        for case in 0..200_000u32 {
            let v = (rng.below(1 << 30) as i32) - (1 << 29);
            let v = match case % 4 {
                0 => v | 0xffff,
                1 => v & !0xffff,
                _ => v,
            };
            let k = (rng.below((1 << 17) + 1) as i32) - (1 << 16);
            let exact = (i64::from(v) * i64::from(k)).div_euclid(1 << 16);
            let exact = exact.clamp(-(1 << 31), (1 << 31) - 1);
            let v_lim = v.clamp(-V_LIMIT, V_LIMIT);
            let exact_lim = (i64::from(v_lim) * i64::from(k)).div_euclid(1 << 16);
            assert_eq!(i64::from(mul_share(v, k)), exact_lim, "{v} * {k}");
            if v == v_lim {
                assert_eq!(i64::from(mul_share(v, k)), exact, "{v} * {k}");
            }
        }
    }

    /// Two pixels a step stores what one a step stores, for every start
    /// and length (odd ones leave a pixel for the last step).
    #[test]
    fn long_stores_are_stores() {
        for a in 0..5 {
            for k in 0..12 {
                let f = [7, -8, 9];
                let mut one = std::vec![1i32; 3 * 20];
                let mut two = one.clone();
                store(&mut one, a, k, &f);
                store_long(&mut two, a, k, &f);
                assert_eq!(one, two, "from {a}, {k} pixels");
                assert_eq!(one.iter().filter(|&&v| v == -8).count(), k);
            }
        }
    }

    /// `over_flat_row` against a reference written out here (running
    /// coverage, its share, `p + floor((f - p) s / 2^16)` in 64 bits): the
    /// values it leaves (a pixel tagged with an entry has that entry's
    /// value, whatever its accumulator holds), the changes it clears, and
    /// a drawn extent that holds every pixel it changed (the flush
    /// resolves only those). Rows start with pixels tagged with random
    /// palette entries (their accumulators holding other values) or
    /// `MIXED` with random values; the colour has a tag or (palette full)
    /// none; the band keeps tags or is dense.
    #[test]
    fn over_flat_rows_match_the_reference_and_mark_every_drawn_pixel() {
        const C: usize = 3;
        let mut rng = crate::path::testing::Lcg(0x5eed_0f1a);
        for case in 0..4000 {
            let lo = rng.below(6) as usize;
            let n = 1 + rng.below(24) as usize;
            let w = lo + n + rng.below(6) as usize;
            let signed = rng.below(2) == 0;
            let dense = rng.below(4) == 0;
            let mut changes: std::vec::Vec<i32> = (0..n)
                .map(|_| match rng.below(4) {
                    0 => 0,
                    1 => COVER_ONE,
                    2 => -COVER_ONE,
                    _ => rng.below(4 * COVER_ONE as u64) as i32 - 2 * COVER_ONE,
                })
                .collect();
            // Mostly rows whose changes sum to nothing, as a closed
            // outline's do; sometimes coverage left to the band's end.
            if rng.below(3) != 0 {
                let sum: i32 = changes[..n - 1].iter().sum();
                changes[n - 1] = -sum;
            }
            let lvl = |rng: &mut crate::path::testing::Lcg| {
                rng.below(4096) as i32 * COVER_ONE + rng.below(1 << 16) as i32
            };
            // A palette of 1 to PALETTE entries (full: the colour has no
            // tag).
            let entries = 1 + rng.below(tags::PALETTE as u64) as usize;
            let mut palette = tags::Palette::<C>::new(core::array::from_fn(|_| lvl(&mut rng)));
            for _ in 1..entries {
                palette.intern(&core::array::from_fn(|_| lvl(&mut rng)));
            }
            let mut acc: std::vec::Vec<i32> = (0..w * C).map(|_| lvl(&mut rng)).collect();
            let mut words = std::vec![tags::MIXED_WORD; tags::row_words(w)];
            if !dense {
                for x in 0..w {
                    if rng.below(2) == 0 {
                        let t = rng.below(palette.len() as u64) as u8;
                        tags::set(&mut words, x, t);
                    }
                }
            }
            // The pixels' values: a tagged one's its entry's.
            let values = |acc: &[i32], words: &[i32], palette: &tags::Palette<C>| {
                let mut v = acc.to_vec();
                for x in 0..w {
                    if let Some(e) = palette.value(tags::get(words, x)) {
                        v[x * C..x * C + C].copy_from_slice(e);
                    }
                }
                v
            };
            let before = values(&acc, &words, &palette);
            let f: [i32; C] = core::array::from_fn(|_| rng.below(4096) as i32 * COVER_ONE);
            // The reference.
            let mut want = before.clone();
            let mut c = 0i64;
            for x in lo..w {
                c += i64::from(changes.get(x - lo).copied().unwrap_or(0));
                let s = if signed {
                    c.clamp(0, i64::from(COVER_ONE))
                } else {
                    c.abs().min(i64::from(COVER_ONE))
                };
                for ch in 0..C {
                    let p = i64::from(want[x * C + ch]);
                    let v = p + ((i64::from(f[ch]) - p) * s).div_euclid(1 << 16);
                    want[x * C + ch] = v as i32;
                }
            }
            let tag = if dense {
                MIXED
            } else {
                palette.intern(&f).unwrap_or(MIXED)
            };
            let mut ch_buf = changes.clone();
            let entries = palette.entries().to_vec();
            let mut t = RowTags {
                words: &mut words,
                lo,
                tag,
                palette: &entries,
            };
            let px = &mut acc[lo * C..];
            let tail = w - lo;
            // Unsigned rows with and without the gap skip.
            let gaps = case % 2 == 0;
            let (first, last) = match (signed, dense, gaps) {
                (true, false, _) => {
                    over_flat_row::<C, true, true, false>(&f, &mut ch_buf, px, tail, true, &mut t)
                }
                (true, true, _) => {
                    over_flat_row::<C, true, false, false>(&f, &mut ch_buf, px, tail, true, &mut t)
                }
                (false, false, false) => {
                    over_flat_row::<C, false, true, false>(&f, &mut ch_buf, px, tail, false, &mut t)
                }
                (false, true, false) => over_flat_row::<C, false, false, false>(
                    &f,
                    &mut ch_buf,
                    px,
                    tail,
                    false,
                    &mut t,
                ),
                (false, false, true) => {
                    over_flat_row::<C, false, true, true>(&f, &mut ch_buf, px, tail, false, &mut t)
                }
                (false, true, true) => {
                    over_flat_row::<C, false, false, true>(&f, &mut ch_buf, px, tail, false, &mut t)
                }
            };
            let after = values(&acc, &words, &palette);
            assert_eq!(after, want, "case {case}: {changes:?}");
            assert!(ch_buf.iter().all(|&d| d == 0), "case {case}");
            for x in 0..w {
                if after[x * C..x * C + C] != before[x * C..x * C + C] {
                    assert!(
                        lo + first <= x && x < lo + last,
                        "case {case}: pixel {x} drawn outside {first}..{last} (+{lo})"
                    );
                }
            }
        }
    }

    /// A mask composite through the memo ([`BandBuffer::compose_mask_over`])
    /// leaves the very values the flat sweep leaves (the reference: the
    /// general `compose`, over, nonzero, opaque), on bands of random flat
    /// spans (palette colours, some past the palette's size) and masks of
    /// a few levels and of any share, overlapping, cut by the band's sides;
    /// every tag stays true (a tagged pixel holds its entry's value), and
    /// the drawn extents hold every changed pixel.
    #[test]
    #[cfg(feature = "text")]
    fn mask_composites_through_the_memo_match_the_flat_sweep() {
        const C: usize = 3;
        let mut rng = crate::path::testing::Lcg(0x3e3a_0001);
        for case in 0..300 {
            let (w, rows) = (8 + rng.below(40) as u16, 1 + rng.below(6) as u16);
            let band = crate::band::Band::new(w, 10, rows);
            let mut a = std::vec![0i32; BandBuffer::<C>::acc_len(w, rows)];
            let mut b = a.clone();
            let mut ca = std::vec![0i32; BandBuffer::<C>::cover_len(w, rows)];
            let mut cb = ca.clone();
            let mut memo_buf = BandBuffer::<C>::new(&mut a, &mut ca, band).unwrap();
            let mut flat_buf = BandBuffer::<C>::new(&mut b, &mut cb, band).unwrap();
            let bg = [rng.below(4096) as u16, rng.below(4096) as u16, 7];
            memo_buf.clear(bg);
            flat_buf.clear(bg);
            let colours = 1 + rng.below(40);
            for _ in 0..rng.below(12) {
                let y = 10 + rng.below(u64::from(rows)) as i32;
                let x0 = rng.below(u64::from(w)) as i32 - 2;
                let x1 = x0 + rng.below(20) as i32;
                let k = rng.below(colours) as u16;
                let col = [k * 97 % 4096, k * 31 % 4096, 4095 - k];
                memo_buf.store_span(x0, x1, y, col);
                flat_buf.store_span(x0, x1, y, col);
            }
            let few = rng.below(2) == 0;
            let levels: std::vec::Vec<i32> = (0..5)
                .map(|_| rng.below(COVER_ONE as u64 + 1) as i32)
                .collect();
            for _ in 0..1 + rng.below(4) {
                let y = 9 + rng.below(u64::from(rows) + 2) as i32;
                let x = rng.below(u64::from(w) + 8) as i32 - 4;
                let covers: std::vec::Vec<i32> = (0..rng.below(30))
                    .map(|_| {
                        if few {
                            levels[rng.below(5) as usize]
                        } else {
                            match rng.below(3) {
                                0 => 0,
                                1 => COVER_ONE,
                                _ => rng.below(COVER_ONE as u64) as i32,
                            }
                        }
                    })
                    .collect();
                memo_buf.add_mask_row(x, y, &covers);
                flat_buf.add_mask_row(x, y, &covers);
            }
            let color = [rng.below(4096) as u16, rng.below(4096) as u16, 4095];
            memo_buf.compose_mask_over(0, 100, &color);
            let rule = Coverage::Rule(FillRule::NonZero);
            flat_buf.compose(
                0,
                100,
                rule,
                &Paint::Flat(color),
                ComposeOp::Over(Opacity::OPAQUE),
            );
            for y in 10..10 + i32::from(rows) {
                for x in 0..i32::from(w) {
                    assert_eq!(
                        memo_buf.raw(x, y),
                        flat_buf.raw(x, y),
                        "case {case}: ({x}, {y})"
                    );
                }
            }
            let n = tags::row_words(usize::from(w));
            for r in 0..usize::from(rows) {
                for x in 0..usize::from(w) {
                    let t = tags::get(&memo_buf.tags[r * n..r * n + n], x);
                    if let Some(v) = memo_buf.palette.value(t) {
                        let raw = memo_buf.raw(x as i32, 10 + r as i32).unwrap();
                        assert_eq!(&raw, v, "case {case}: pixel ({x}, {r})'s tag {t}");
                    }
                }
            }
            assert!(
                memo_buf.deltas.iter().all(|&d| d == 0),
                "case {case}: changes left"
            );
        }
    }
}
