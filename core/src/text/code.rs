//! The coverage code of rasterized glyphs: what a [`RasterFont`] keeps in
//! flash and a [`GlyphCache`] in RAM, and its decoder.
//!
//! Takes a glyph's coverage, row by row over its box (`width x height`
//! pixels), each pixel quantized to a level `v` in `0..=`[`LEVEL_MAX`]
//! (`v / 29` of a pixel); gives a stream of 5-bit symbols, least
//! significant bit first, packed into bytes:
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `0..=29` | one pixel of level `v` |
//! | `30`, then 3 bits `n` | `n + 2` empty pixels (2..=9) |
//! | `31`, then 3 bits `n` | `n + 2` whole pixels (2..=9) |
//!
//! Runs continue across row ends (the box is one sequence of
//! `width x height` pixels); a decoder reads exactly that many pixels, and
//! pixels past the end of the bytes are empty (so a damaged code draws
//! less, never out of bounds).
//!
//! ## Why 29 levels
//!
//! A level stands for `v / 29` of a pixel. The rasterizer rounds each
//! pixel to within 3/4 of a level (0.026 px) of its coverage, choosing
//! between the two nearest levels so that a glyph keeps its ink (see
//! [`rasterize`](super::rasterize)); with its own error (within 0.0032 of
//! the exact area, see `tests/tests/text_coverage.rs`) every pixel stays
//! within 0.029 of the exact area of the outline, under the 1/32 (0.031)
//! asked of text. Four bits (levels `v / 15`) would err by up to 1/30
//! from quantization alone, nearest rounding included, and could not keep
//! a glyph's ink. At 16 px most inked pixels are
//! partly covered (70 % of those of DejaVu Sans, ASCII and Latin-1) and
//! their levels are spread nearly evenly, so a code of fixed 5-bit symbols
//! is within 20 % of the order-0 entropy of the levels while decoding with
//! a shift and a mask per pixel; runs of empty and whole pixels make large
//! sizes cheap (4.7 bits per pixel of the box at 16 px, 2 at 48 px).
//!
//! A level becomes coverage units through a table
//! ([`LEVEL_COVER`]: `round(v * 2^16 / 29)`, built by a `const fn`): no
//! multiply per pixel.
//!
//! [`RasterFont`]: super::RasterFont
//! [`GlyphCache`]: super::GlyphCache

use core::cell::Cell;

use super::one_bit::MAX_CONTRAST_SHIFT;
use crate::COVER_ONE;

/// The largest level: a whole pixel. Level `v` is `v / LEVEL_MAX` px.
pub const LEVEL_MAX: u8 = 29;
/// The symbol of a run of empty pixels.
const RUN_EMPTY: u32 = 30;
/// The symbol of a run of whole pixels.
const RUN_FULL: u32 = 31;
/// Bits of a symbol and of a run's length.
const SYMBOL_BITS: u32 = 5;
const RUN_BITS: u32 = 3;
/// The shortest and longest run one symbol holds.
const RUN_MIN: u32 = 2;
const RUN_MAX: u32 = RUN_MIN + (1 << RUN_BITS) - 1;

/// Coverage units of each level: `round(v * 2^16 / LEVEL_MAX)`.
pub const LEVEL_COVER: [i32; LEVEL_MAX as usize + 1] = level_cover();

const fn level_cover() -> [i32; LEVEL_MAX as usize + 1] {
    let mut t = [0i32; LEVEL_MAX as usize + 1];
    let mut v = 0;
    while v <= LEVEL_MAX as usize {
        let m = LEVEL_MAX as i32;
        t[v] = (v as i32 * COVER_ONE + m / 2) / m;
        v += 1;
    }
    t
}

/// The level tables with a contrast gain of `2^shift` (`shift` in
/// `0..=MAX_CONTRAST_SHIFT`): `clamp(((c - 1/2) << shift) + 1/2, 0, 1)`
/// of each level's coverage `c`, as [`ContrastBoost`] does to a pixel's
/// value before a 1-bit ditherer, here to the text's own coverage (its
/// edges decided mostly by their side of 1/2, the rest of the frame
/// untouched). Row 0 is [`LEVEL_COVER`].
///
/// [`ContrastBoost`]: super::ContrastBoost
pub const BOOSTED_COVER: [[i32; LEVEL_MAX as usize + 1]; MAX_CONTRAST_SHIFT as usize + 1] =
    boosted_cover();

const fn boosted_cover() -> [[i32; LEVEL_MAX as usize + 1]; MAX_CONTRAST_SHIFT as usize + 1] {
    let mut t = [[0i32; LEVEL_MAX as usize + 1]; MAX_CONTRAST_SHIFT as usize + 1];
    let mut s = 0;
    while s <= MAX_CONTRAST_SHIFT as usize {
        let mut v = 0;
        while v <= LEVEL_MAX as usize {
            let half = COVER_ONE / 2;
            let b = ((LEVEL_COVER[v] - half) << s) + half;
            t[s][v] = if b < 0 {
                0
            } else if b > COVER_ONE {
                COVER_ONE
            } else {
                b
            };
            v += 1;
        }
        s += 1;
    }
    t
}

/// Where a code's bytes are: flash (`[u8]`) or a cache's cells.
pub trait CodeBytes {
    /// Byte `i`, `None` past the end.
    fn byte(&self, i: usize) -> Option<u8>;
}

impl CodeBytes for [u8] {
    #[inline(always)]
    fn byte(&self, i: usize) -> Option<u8> {
        self.get(i).copied()
    }
}

impl CodeBytes for [Cell<u8>] {
    #[inline(always)]
    fn byte(&self, i: usize) -> Option<u8> {
        self.get(i).map(Cell::get)
    }
}

/// A glyph's mask: its box, relative to the pixel of the pen (the pixel
/// whose left edge the glyph's origin is on, its top edge on the
/// baseline), and its code.
///
/// ```
/// use softedge::text::GlyphMask;
/// // A run of 4 whole pixels: symbol 31, then the length less 2 (3 bits).
/// let dot = GlyphMask::new(1, -2, 2, 2, &[31u8 | (4 - 2) << 5][..]);
/// let mut rows = dot.rows();
/// let mut px = [0i32; 2];
/// rows.fill(&mut px);
/// assert_eq!(px, [65536, 65536]);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct GlyphMask<'a, B: ?Sized = [u8]> {
    /// Columns from the pen's pixel to the box's first.
    pub left: i16,
    /// Rows from the baseline to the box's first (negative above it).
    pub top: i16,
    /// The box's width in pixels.
    pub width: u16,
    /// The box's height in pixels.
    pub height: u16,
    code: &'a B,
}

impl<'a, B: CodeBytes + ?Sized> GlyphMask<'a, B> {
    /// A mask over `code`.
    pub fn new(left: i16, top: i16, width: u16, height: u16, code: &'a B) -> Self {
        Self {
            left,
            top,
            width,
            height,
            code,
        }
    }

    /// A decoder at the first pixel.
    pub fn rows(&self) -> MaskDecoder<'a, B> {
        self.rows_boosted(0)
    }

    /// A decoder at the first pixel whose partly covered pixels get a
    /// contrast gain of `2^shift` (see [`BOOSTED_COVER`]; `shift` limited
    /// to `MAX_CONTRAST_SHIFT`).
    pub fn rows_boosted(&self, shift: u8) -> MaskDecoder<'a, B> {
        let s = usize::from(shift.min(MAX_CONTRAST_SHIFT));
        MaskDecoder {
            code: self.code,
            levels: BOOSTED_COVER.get(s).unwrap_or(&LEVEL_COVER),
            next: 0,
            bits: 0,
            nbits: 0,
            run: 0,
            run_value: 0,
        }
    }

    /// True when the box is empty (a space).
    pub fn is_empty(&self) -> bool {
        self.width == 0 || self.height == 0
    }
}

/// The pixels of a mask's code, in order (row by row), as coverage units.
#[derive(Debug, Clone)]
pub struct MaskDecoder<'a, B: ?Sized = [u8]> {
    code: &'a B,
    /// Coverage of each level.
    levels: &'static [i32; LEVEL_MAX as usize + 1],
    /// The next byte to read.
    next: usize,
    /// Bits read and not used, `nbits` of them, low first.
    bits: u32,
    nbits: u32,
    /// Pixels left of the current run, and their coverage.
    run: u32,
    run_value: i32,
}

impl<B: CodeBytes + ?Sized> MaskDecoder<'_, B> {
    /// The next run of pixels of one coverage (units of [`COVER_ONE`]): its
    /// value and length, at most `max` (at least 1; `max` 0 is taken as
    /// 1). A single-pixel symbol is a run of one; past the end of the
    /// code, empty pixels.
    #[inline]
    pub fn run(&mut self, max: u32) -> (i32, u32) {
        let max = max.max(1);
        if self.run == 0 {
            let (v, n) = self.next_run();
            self.run_value = v;
            self.run = n;
        }
        let n = self.run.min(max);
        self.run -= n;
        (self.run_value, n)
    }

    /// The next symbol's run, whole: its coverage and length (a pixel, or
    /// 2..=9 of a run; past the end of the code, a long run of empty
    /// pixels). Any run begun by [`run`](Self::run) or
    /// [`fill`](Self::fill) and not finished is given first.
    #[inline(always)]
    pub fn next_run(&mut self) -> (i32, u32) {
        if self.run > 0 {
            let n = core::mem::take(&mut self.run);
            return (self.run_value, n);
        }
        // At most 8 bits a symbol: one byte read when fewer are held.
        if self.nbits < SYMBOL_BITS + RUN_BITS {
            match self.code.byte(self.next) {
                Some(b) => {
                    self.bits |= u32::from(b) << self.nbits;
                    self.nbits += 8;
                    self.next += 1;
                }
                None if self.nbits < SYMBOL_BITS => return (0, u32::MAX),
                None => {}
            }
        }
        let s = self.bits & ((1 << SYMBOL_BITS) - 1);
        if s < RUN_EMPTY {
            self.bits >>= SYMBOL_BITS;
            self.nbits -= SYMBOL_BITS;
            return (self.levels.get(s as usize).copied().unwrap_or(0), 1);
        }
        // A run (a damaged code that ends inside one reads 0 bits).
        let len = ((self.bits >> SYMBOL_BITS) & ((1 << RUN_BITS) - 1)) + RUN_MIN;
        let used = (SYMBOL_BITS + RUN_BITS).min(self.nbits);
        self.bits >>= used;
        self.nbits -= used;
        (if s == RUN_FULL { COVER_ONE } else { 0 }, len)
    }

    /// Adds the next `cells.len() - 1` pixels, one row of a mask, to
    /// `cells` as changes of running coverage: each pixel's difference
    /// from the one before (the first's from 0), and the last one's value
    /// taken back in the last cell (a band's scratch row, see
    /// [`add_mask`](crate::band::BandBuffer)). Per pixel of a single-pixel
    /// symbol: its bits, a table look-up, a subtraction and an addition.
    #[inline]
    pub(crate) fn add_row(&mut self, cells: &mut [i32]) {
        let Some((close, row)) = cells.split_last_mut() else {
            return;
        };
        let mut prev = 0i32;
        let mut i = 0usize;
        let n = row.len();
        // A run begun in the row above goes on.
        if self.run > 0 {
            let k = (self.run as usize).min(n);
            if let Some(d) = row.first_mut() {
                *d = d.wrapping_add(self.run_value);
            }
            prev = self.run_value;
            self.run -= k as u32;
            i = k;
        }
        let (mut bits, mut nbits) = (self.bits, self.nbits);
        while i < n {
            if nbits < SYMBOL_BITS + RUN_BITS {
                match self.code.byte(self.next) {
                    Some(b) => {
                        bits |= u32::from(b) << nbits;
                        nbits += 8;
                        self.next += 1;
                    }
                    None if nbits < SYMBOL_BITS => {
                        // Past the end: empty pixels.
                        if let Some(d) = row.get_mut(i) {
                            *d = d.wrapping_sub(prev);
                        }
                        prev = 0;
                        break;
                    }
                    None => {}
                }
            }
            let s = bits & ((1 << SYMBOL_BITS) - 1);
            let (v, len) = if s < RUN_EMPTY {
                bits >>= SYMBOL_BITS;
                nbits -= SYMBOL_BITS;
                (self.levels.get(s as usize).copied().unwrap_or(0), 1)
            } else {
                let len = ((bits >> SYMBOL_BITS) & ((1 << RUN_BITS) - 1)) + RUN_MIN;
                let used = (SYMBOL_BITS + RUN_BITS).min(nbits);
                bits >>= used;
                nbits -= used;
                (if s == RUN_FULL { COVER_ONE } else { 0 }, len as usize)
            };
            if let Some(d) = row.get_mut(i) {
                *d = d.wrapping_add(v.wrapping_sub(prev));
            }
            prev = v;
            i += len;
            if i > n {
                // The run goes on in the next row.
                self.run = (i - n) as u32;
                self.run_value = v;
            }
        }
        (self.bits, self.nbits) = (bits, nbits);
        *close = close.wrapping_sub(prev);
    }

    /// Passes over the next `n` pixels.
    #[inline]
    pub fn skip(&mut self, n: u32) {
        let mut left = n;
        while left > 0 {
            left -= self.run(left).1;
        }
    }

    /// Fills `out` with the next `out.len()` pixels' coverage (units of
    /// [`COVER_ONE`]).
    #[inline]
    pub fn fill(&mut self, out: &mut [i32]) {
        let n = out.len();
        let mut i = 0;
        while i < n {
            // The current run first.
            if self.run > 0 {
                let k = (self.run as usize).min(n - i);
                if let Some(s) = out.get_mut(i..i + k) {
                    s.fill(self.run_value);
                }
                self.run -= k as u32;
                i += k;
                continue;
            }
            // At most 8 bits a symbol: one byte read when fewer are held.
            if self.nbits < SYMBOL_BITS + RUN_BITS {
                match self.code.byte(self.next) {
                    Some(b) => {
                        self.bits |= u32::from(b) << self.nbits;
                        self.nbits += 8;
                        self.next += 1;
                    }
                    None if self.nbits < SYMBOL_BITS => {
                        // Past the end: empty pixels.
                        if let Some(s) = out.get_mut(i..) {
                            s.fill(0);
                        }
                        return;
                    }
                    None => {}
                }
            }
            let s = self.bits & ((1 << SYMBOL_BITS) - 1);
            if s < RUN_EMPTY {
                if let Some(p) = out.get_mut(i) {
                    *p = self.levels.get(s as usize).copied().unwrap_or(0);
                }
                self.bits >>= SYMBOL_BITS;
                self.nbits -= SYMBOL_BITS;
                i += 1;
            } else {
                // A run (a damaged code that ends inside one reads 0 bits).
                let len = ((self.bits >> SYMBOL_BITS) & ((1 << RUN_BITS) - 1)) + RUN_MIN;
                let used = (SYMBOL_BITS + RUN_BITS).min(self.nbits);
                self.bits >>= used;
                self.nbits -= used;
                self.run_value = if s == RUN_FULL { COVER_ONE } else { 0 };
                self.run = len;
            }
        }
    }
}

/// Writes a code, pixel level by pixel level, through `put` (one byte at
/// a time; `put` returns false when it has no room, and the code is then
/// incomplete: [`MaskEncoder::finish`] says so).
#[derive(Debug)]
pub struct MaskEncoder<F: FnMut(u8) -> bool> {
    put: F,
    bits: u32,
    nbits: u32,
    /// The pending run: its level (0 or `LEVEL_MAX`) and length.
    run_level: u8,
    run: u32,
    bytes: usize,
    full: bool,
}

impl<F: FnMut(u8) -> bool> MaskEncoder<F> {
    /// An encoder writing through `put`.
    pub fn new(put: F) -> Self {
        Self {
            put,
            bits: 0,
            nbits: 0,
            run_level: 0,
            run: 0,
            bytes: 0,
            full: false,
        }
    }

    /// The next pixel's level (`0..=LEVEL_MAX`; beyond, clamped).
    pub fn pixel(&mut self, level: u8) {
        let level = level.min(LEVEL_MAX);
        if self.run > 0 && level == self.run_level {
            self.run += 1;
            if self.run == RUN_MAX {
                self.end_run();
            }
            return;
        }
        self.end_run();
        if level == 0 || level == LEVEL_MAX {
            self.run_level = level;
            self.run = 1;
        } else {
            self.symbol(u32::from(level), SYMBOL_BITS);
        }
    }

    /// Ends the code; gives the bytes written, or `None` when `put` ran
    /// out of room.
    pub fn finish(mut self) -> Option<usize> {
        self.end_run();
        if self.nbits > 0 {
            let b = self.bits as u8;
            self.byte(b);
        }
        (!self.full).then_some(self.bytes)
    }

    fn end_run(&mut self) {
        match self.run {
            0 => {}
            1 => self.symbol(u32::from(self.run_level), SYMBOL_BITS),
            n => {
                let s = if self.run_level == 0 {
                    RUN_EMPTY
                } else {
                    RUN_FULL
                };
                self.symbol(s | (n - RUN_MIN) << SYMBOL_BITS, SYMBOL_BITS + RUN_BITS);
            }
        }
        self.run = 0;
    }

    fn symbol(&mut self, v: u32, n: u32) {
        self.bits |= v << self.nbits;
        self.nbits += n;
        while self.nbits >= 8 {
            let b = self.bits as u8;
            self.byte(b);
            self.bits >>= 8;
            self.nbits -= 8;
        }
    }

    fn byte(&mut self, b: u8) {
        if !self.full && (self.put)(b) {
            self.bytes += 1;
        } else {
            self.full = true;
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    fn encode(levels: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut e = MaskEncoder::new(|b| {
            out.push(b);
            true
        });
        for &l in levels {
            e.pixel(l);
        }
        let n = e.finish().unwrap();
        assert_eq!(n, out.len());
        out
    }

    #[test]
    fn levels_are_the_rounded_fractions() {
        for (v, &c) in LEVEL_COVER.iter().enumerate() {
            let exact = v as f64 * 65536.0 / 29.0;
            assert!((f64::from(c) - exact).abs() <= 0.5, "{v}");
        }
        assert_eq!(LEVEL_COVER[0], 0);
        assert_eq!(LEVEL_COVER[usize::from(LEVEL_MAX)], COVER_ONE);
    }

    #[test]
    fn random_codes_decode_to_their_levels_in_any_pieces() {
        let mut rng = crate::path::testing::Lcg(0x0033_c0de);
        for case in 0..2000 {
            let n = rng.below(80) as usize;
            let levels: Vec<u8> = (0..n)
                .map(|_| match rng.below(5) {
                    0 | 1 => 0,
                    2 => LEVEL_MAX,
                    _ => rng.below(u64::from(LEVEL_MAX) + 1) as u8,
                })
                .collect();
            let code = encode(&levels);
            // Pieces of random lengths, then pixels past the end (empty).
            let mask = GlyphMask::new(0, 0, n as u16, 1, &code[..]);
            let mut dec = mask.rows();
            let mut got = Vec::new();
            while got.len() < n + 12 {
                let k = 1 + rng.below(9) as usize;
                let mut buf = std::vec![-1i32; k];
                dec.fill(&mut buf);
                got.extend(buf);
            }
            for (i, &g) in got.iter().enumerate() {
                let want = levels.get(i).map_or(0, |&l| LEVEL_COVER[usize::from(l)]);
                assert_eq!(g, want, "case {case}, pixel {i}: {levels:?}");
            }
            // The same from cells.
            let cells: Vec<Cell<u8>> = code.iter().copied().map(Cell::new).collect();
            let mut dec = GlyphMask::new(0, 0, n as u16, 1, &cells[..]).rows();
            let mut buf = std::vec![0i32; n];
            dec.fill(&mut buf);
            assert!(buf
                .iter()
                .zip(&levels)
                .all(|(&g, &l)| g == LEVEL_COVER[usize::from(l)]));
        }
    }

    #[test]
    fn runs_and_skips_give_the_same_pixels_as_fill() {
        let mut rng = crate::path::testing::Lcg(0x0033_5c1b);
        for case in 0..1000 {
            let levels: Vec<u8> = (0..rng.below(60))
                .map(|_| match rng.below(4) {
                    0 | 1 => 0,
                    2 => LEVEL_MAX,
                    _ => rng.below(u64::from(LEVEL_MAX) + 1) as u8,
                })
                .collect();
            let code = encode(&levels);
            let n = levels.len() + 5;
            let mut want = std::vec![0i32; n];
            GlyphMask::new(0, 0, n as u16, 1, &code[..])
                .rows()
                .fill(&mut want);
            let mut dec = GlyphMask::new(0, 0, n as u16, 1, &code[..]).rows();
            let mut got = Vec::new();
            while got.len() < n {
                let left = (n - got.len()) as u32;
                if rng.below(4) == 0 {
                    let k = 1 + rng.below(u64::from(left)) as u32;
                    dec.skip(k);
                    got.extend(want[got.len()..got.len() + k as usize].iter().copied());
                } else {
                    let (v, k) = dec.run(1 + rng.below(u64::from(left)) as u32);
                    assert!(k >= 1 && k <= left, "case {case}");
                    got.extend(core::iter::repeat_n(v, k as usize));
                }
            }
            assert_eq!(got, want, "case {case}: {levels:?}");
        }
    }

    #[test]
    fn rows_added_as_changes_sum_to_the_pixels() {
        let mut rng = crate::path::testing::Lcg(0x0033_a0d0);
        for case in 0..1000 {
            let (w, h) = (1 + rng.below(12) as usize, 1 + rng.below(6) as usize);
            let levels: Vec<u8> = (0..w * h - rng.below(3).min(w as u64 * h as u64 - 1) as usize)
                .map(|_| match rng.below(4) {
                    0 | 1 => 0,
                    2 => LEVEL_MAX,
                    _ => rng.below(u64::from(LEVEL_MAX) + 1) as u8,
                })
                .collect();
            let code = encode(&levels);
            let mut want = std::vec![0i32; w * h];
            GlyphMask::new(0, 0, w as u16, h as u16, &code[..])
                .rows()
                .fill(&mut want);
            let mut dec = GlyphMask::new(0, 0, w as u16, h as u16, &code[..]).rows();
            for j in 0..h {
                if rng.below(4) == 0 {
                    dec.skip(w as u32);
                    continue;
                }
                let mut cells = std::vec![0i32; w + 1];
                dec.add_row(&mut cells);
                let mut sum = 0;
                for (i, &d) in cells.iter().enumerate() {
                    sum += d;
                    let px = if i < w { want[j * w + i] } else { 0 };
                    assert_eq!(sum, px, "case {case}, row {j}, pixel {i}: {levels:?}");
                }
            }
        }
    }

    #[test]
    fn runs_make_empty_and_whole_stretches_short() {
        // 9 empty, 9 whole: two 8-bit run symbols.
        let mut levels = std::vec![0u8; 9];
        levels.extend([LEVEL_MAX; 9]);
        assert_eq!(encode(&levels).len(), 2);
        // A full encoder reports it.
        let mut room = 1;
        let mut e = MaskEncoder::new(|_| {
            room -= 1;
            room >= 0
        });
        for l in [3u8, 4, 5, 6] {
            e.pixel(l);
        }
        assert_eq!(e.finish(), None);
    }

    #[test]
    fn damaged_codes_decode_without_panics() {
        let mut rng = crate::path::testing::Lcg(0x0033_bad0);
        for _ in 0..2000 {
            let code: Vec<u8> = (0..rng.below(12)).map(|_| rng.below(256) as u8).collect();
            let mut dec = GlyphMask::new(0, 0, 64, 4, &code[..]).rows();
            let mut buf = [0i32; 256];
            dec.fill(&mut buf);
            assert!(buf.iter().all(|&v| (0..=COVER_ONE).contains(&v)));
        }
    }
}
