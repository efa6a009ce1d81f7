//! Pixel tags and the band's palette: which pixels the flush can tone
//! once per band instead of once per pixel.
//!
//! In a user interface most pixels of a band end up wholly covered by one
//! opaque flat colour (the background, a panel, a disc's inside): their
//! value is exactly that colour's `lin12 * 2^16` per channel. Beside its
//! accumulator, every pixel keeps a one-byte *tag*: the index of its value
//! in the band's [`Palette`] (at most [`PALETTE`] exact accumulator values
//! per band, the background first), or [`MIXED`] when its value is
//! anything else (an edge, a translucent composite, a Gouraud plane). So
//! the flush gives a tagged pixel its entry's colour, toned once for the
//! band, and resolves only the `MIXED` ones.
//!
//! The tag is the truth: a pixel tagged with an entry has that entry's
//! value, whatever its accumulator holds (an opaque flat span only fills
//! tags, a byte a pixel, four a word: no accumulator store on the way in,
//! no reset on the way out); only a `MIXED` pixel's accumulator is its
//! value. Whoever reads a tagged pixel's value takes the entry's (a blend
//! at an edge, a gradient over a panel: [`materialise`] before the
//! composite), and tags what it changes `MIXED`. A *dense* band (see
//! [`Palette`]) has every tag `MIXED`: its accumulator is every pixel's
//! value. Nothing is rounded differently: the bits of every frame are
//! those of the values.
//!
//! One more tag, [`SOURCE`], says a pixel's value without an entry: its
//! accumulator's first word holds an Rgb565 code (an unscaled Rgb565
//! image's whole pixel, stored as it was read), its value that code
//! decoded by the sRGB tables ([`decode`]); the flush of a profile that
//! tones every Rgb565 colour back to itself sends the code as it is
//! (`Profile::keeps_rgb565`). Only a three-channel band that keeps tags
//! has such pixels; whoever reads a pixel's value reads them through
//! [`value`], [`take`] or [`materialise`].
//!
//! Tags are packed four to an `i32` word of the caller's `cover` slice,
//! little end first (pixel `c` of a row in word `c / 4`, bits
//! `8 (c % 4) ..`), each band row starting a word.

/// Entries of a band's palette.
pub(crate) const PALETTE: usize = 32;
/// The tag of a pixel whose accumulator holds its value.
pub(crate) const MIXED: u8 = 0xff;
/// A word of four `MIXED` tags.
pub(crate) const MIXED_WORD: i32 = -1;
/// The tag of a pixel whose accumulator's first word is an Rgb565 code
/// (`r << 11 | g << 5 | b`, sRGB), its value that colour ([`decode`]).
pub(crate) const SOURCE: u8 = 0xfe;
/// A word of four `SOURCE` tags.
pub(crate) const SOURCE_WORD: i32 = splat(SOURCE);

/// The value (accumulator units, `C` channels) of the Rgb565 code in
/// `code`'s low 16 bits: each channel decoded by the sRGB tables, as an
/// opaque texel of an Rgb565 image is (`image::format`).
#[inline(always)]
pub(crate) fn decode<const C: usize>(code: i32) -> [i32; C] {
    use crate::color::srgb::{SRGB5_TO_LIN12, SRGB6_TO_LIN12};
    let c = code as u32;
    let lin = [
        SRGB5_TO_LIN12[(c >> 11 & 31) as usize],
        SRGB6_TO_LIN12[(c >> 5 & 63) as usize],
        SRGB5_TO_LIN12[(c & 31) as usize],
    ];
    core::array::from_fn(|ch| i32::from(lin[ch.min(2)]) << crate::COVER_BITS)
}

/// The pixels `px` (`C` words each, a [`SOURCE`] code in each one's
/// first) given their values. Out of line, so that the loops over tags,
/// which seldom meet a code, keep their registers (the Cortex-M0's 2 000
/// small triangles: 52.38 M inline, 52.33 M so).
#[inline(never)]
fn decode_codes<const C: usize>(px: &mut [i32]) {
    let mut px = px;
    while let Some((p, rest)) = core::mem::take(&mut px).split_first_chunk_mut::<C>() {
        *p = decode(p.first().copied().unwrap_or(0));
        px = rest;
    }
}

/// Gives a pixel tagged `t`, its accumulator `p`, its value there: its
/// entry's, or its code's ([`SOURCE`]); a `MIXED` one has it already.
#[inline(always)]
pub(crate) fn load<const C: usize>(p: &mut [i32; C], t: u8, entries: &[[i32; C]]) {
    if let Some(v) = entries.get(usize::from(t)) {
        *p = *v;
    } else if t == SOURCE {
        decode_codes::<C>(p);
    }
}

/// The value of a pixel tagged `t` whose accumulator is `px`: its
/// entry's, its code's ([`SOURCE`]), or `px` (`MIXED`).
#[inline(always)]
pub(crate) fn value<const C: usize>(px: &[i32; C], t: u8, entries: &[[i32; C]]) -> [i32; C] {
    let mut v = *px;
    load(&mut v, t, entries);
    v
}

/// Words of tags per band row of `w` pixels.
#[inline]
pub(crate) const fn row_words(w: usize) -> usize {
    w.div_ceil(4)
}

/// A word of four tags `t`.
#[inline]
pub(crate) const fn splat(t: u8) -> i32 {
    (t as u32).wrapping_mul(0x0101_0101) as i32
}

/// The tag of pixel `c` of a row's tag words (`MIXED` past the row).
#[inline(always)]
pub(crate) fn get(words: &[i32], c: usize) -> u8 {
    words
        .get(c >> 2)
        .map_or(MIXED, |&w| (w >> ((c & 3) << 3)) as u8)
}

/// Gives pixels `c0..c1` of a row (its accumulator `acc`, `C` values a
/// pixel, and tag `words`) that are tagged with a palette entry the
/// entry's value (`entries`) in the accumulator, so that a composite may
/// read it there; their tags are left as they are. Word by word: a run of
/// words of one tag (a background under an image, a band going dense) is
/// taken whole, its entry loaded once and stored pixel after pixel (a
/// gray's one word by a fill of words), a run of `MIXED` words passed
/// over; the pixels of a word of mixed tags, and of the partial words at
/// the range's ends, one by one.
#[inline(never)]
pub(crate) fn materialise<const C: usize>(
    acc: &mut [i32],
    words: &[i32],
    entries: &[[i32; C]],
    c0: usize,
    c1: usize,
) {
    let c1 = c1.min(words.len() * 4).min(acc.len() / C.max(1));
    if c0 >= c1 {
        return;
    }
    // One pixel from its tag.
    let one = |acc: &mut [i32], c: usize, t: u8| {
        if let Some(px) = acc
            .get_mut(c * C..c * C + C)
            .and_then(|p| p.first_chunk_mut::<C>())
        {
            load(px, t, entries);
        }
    };
    // Whole words `k0..k1`; the pixels before and after one by one.
    let (k0, k1) = (c0.div_ceil(4), c1 / 4);
    if k0 >= k1 {
        for c in c0..c1 {
            one(acc, c, get(words, c));
        }
        return;
    }
    for c in c0..k0 * 4 {
        one(acc, c, get(words, c));
    }
    let mut k = k0;
    while let Some(&word) = words.get(k).filter(|_| k < k1) {
        let t = word as u8;
        if word != splat(t) {
            if let Some(px) = acc.get_mut(k * 4 * C..(k + 1) * 4 * C) {
                for (p, b) in px.chunks_exact_mut(C).zip(word.to_le_bytes()) {
                    if let Some(v) = entries.get(usize::from(b)) {
                        p.copy_from_slice(v);
                    } else if b == SOURCE {
                        decode_codes::<C>(p);
                    }
                }
            }
            k += 1;
            continue;
        }
        // A run of words of tag `t`.
        let mut e = k + 1;
        while e < k1 && words.get(e) == Some(&word) {
            e += 1;
        }
        if let (Some(&v), Some(mut px)) = (
            entries.get(usize::from(t)),
            acc.get_mut(k * 4 * C..e * 4 * C),
        ) {
            if v.iter().all(|&x| Some(&x) == v.first()) {
                // A gray (black, white): one word throughout.
                crate::arith::fill(px, v.first().copied().unwrap_or(0));
            } else {
                while let Some((p, rest)) = core::mem::take(&mut px).split_first_chunk_mut::<C>() {
                    *p = v;
                    px = rest;
                }
            }
        } else if t == SOURCE {
            decode_codes::<C>(acc.get_mut(k * 4 * C..e * 4 * C).unwrap_or_default());
        }
        k = e;
    }
    for c in k1 * 4..c1 {
        one(acc, c, get(words, c));
    }
}

/// Pixel `c` of a row (its accumulator `px`, its tag `words`) about to be
/// changed by a composite: its value into `px` (its entry's when it is
/// tagged with one, see [`materialise`]), its tag `MIXED`.
#[inline(always)]
pub(crate) fn take<const C: usize>(
    px: &mut [i32; C],
    words: &mut [i32],
    entries: &[[i32; C]],
    c: usize,
) {
    load(px, get(words, c), entries);
    set_mixed(words, c);
}

/// Sets pixel `c`'s tag to `MIXED` (an or between a load and a store).
#[inline(always)]
pub(crate) fn set_mixed(words: &mut [i32], c: usize) {
    if let Some(w) = words.get_mut(c >> 2) {
        *w |= 0xff << ((c & 3) << 3);
    }
}

/// Sets pixel `c`'s tag to `t`.
#[cfg(test)]
pub(crate) fn set(words: &mut [i32], c: usize, t: u8) {
    if let Some(w) = words.get_mut(c >> 2) {
        let s = (c & 3) << 3;
        *w = (*w & !(0xff << s)) | (i32::from(t) << s);
    }
}

/// Sets the tags of pixels `c0..c1` to `t`: the partial words at the ends
/// by masks, the words between by stores (a loop of its own: a short run's
/// few words do not pay a library fill's call). Out of line: once per run.
#[inline(never)]
pub(crate) fn fill(words: &mut [i32], c0: usize, c1: usize, t: u8) {
    let c1 = c1.min(words.len() * 4);
    if c0 >= c1 {
        return;
    }
    let v = splat(t);
    let (w0, w1) = (c0 >> 2, (c1 - 1) >> 2);
    // Bits of the first and last words that the range holds.
    let head = (-1i32) << ((c0 & 3) << 3);
    let tail = (u32::MAX >> ((3 - ((c1 - 1) & 3)) << 3)) as i32;
    let Some(row) = words.get_mut(w0..=w1) else {
        return;
    };
    let [first, mid @ .., last] = row else {
        if let Some(w) = row.first_mut() {
            let m = head & tail;
            *w = (*w & !m) | (v & m);
        }
        return;
    };
    *first = (*first & !head) | (v & head);
    for w in mid {
        *w = v;
    }
    *last = (*last & !tail) | (v & tail);
}

/// The exact accumulator values of a band's opaque flat colours (see the
/// module's doc): entry 0 is the background.
///
/// A band whose shapes bring more flat colours than it has entries goes
/// *dense*: every tag is set `MIXED`, and the band's shapes are composed
/// into the accumulator alone from then on (what many small shapes of many
/// colours, a scene of triangles, need: no tag to keep per pixel). So does
/// a band a Gouraud plane is composed over (a shaded mesh: every pixel a
/// value of its own; Cortex-M0, the Gouraud screen of `boards/bench-m0`:
/// 15.35 M keeping tags, 14.69 M dense from its first triangle).
#[derive(Debug, Clone)]
pub(crate) struct Palette<const C: usize> {
    acc: [[i32; C]; PALETTE],
    len: u8,
    /// Every tag of the band is `MIXED`, and stays so. A one-channel band
    /// starts dense: resolving and toning its pixel (one channel) costs
    /// about what keeping and reading its tag does (Cortex-M0, the gray
    /// screen of `boards/bench-m0`: 7.27 M with tags, 6.32 M without).
    pub(crate) dense: bool,
    /// An open hash of the entries: per slot, an entry's index + 1 (0:
    /// empty), at [`hash`](Self::hash) of its value or past it.
    index: [u8; SLOTS],
}

/// Slots of a palette's hash: twice its entries, so that probes are short.
const SLOTS: usize = 2 * PALETTE;

impl<const C: usize> Palette<C> {
    /// Only `background` (accumulator units), as entry 0.
    pub(crate) fn new(background: [i32; C]) -> Self {
        let mut acc = [[0; C]; PALETTE];
        acc[0] = background;
        let mut index = [0; SLOTS];
        index[Self::hash(&background)] = 1;
        Self {
            acc,
            len: 1,
            dense: C == 1,
            index,
        }
    }

    /// The slot a value starts its probe at: its channels' 12-bit levels
    /// folded by shifts and exclusive ors.
    #[inline]
    fn hash(v: &[i32; C]) -> usize {
        let mut h = 0u32;
        for &x in v {
            h = (h << 3) ^ (h >> 7) ^ (x as u32 >> 12);
        }
        ((h ^ (h >> 6) ^ (h >> 12)) as usize) & (SLOTS - 1)
    }

    /// Entries in use.
    pub(crate) fn len(&self) -> usize {
        usize::from(self.len)
    }

    /// The tag of value `v` (accumulator units): its entry, made if there
    /// is room; `None` when the palette is full (the caller then stores
    /// the value in the accumulator and tags the pixel `MIXED`).
    ///
    /// A probe of the hash from the value's slot to an empty one: one
    /// compare of a channel per entry met (the rest where that matches).
    /// Out of line: once per shape and band.
    #[inline(never)]
    pub(crate) fn intern(&mut self, v: &[i32; C]) -> Option<u8> {
        let mut h = Self::hash(v);
        let first = v.first().copied().unwrap_or(0);
        for _ in 0..SLOTS {
            let k = usize::from(*self.index.get(h)?);
            if k == 0 {
                break;
            }
            let e = self.acc.get(k - 1)?;
            if e.first().copied().unwrap_or(0) == first && e.iter().zip(v).all(|(a, b)| a == b) {
                return Some((k - 1) as u8);
            }
            h = (h + 1) & (SLOTS - 1);
        }
        let n = self.len();
        let slot = self.acc.get_mut(n)?;
        *slot = *v;
        self.len += 1;
        if let Some(i) = self.index.get_mut(h) {
            *i = n as u8 + 1;
        }
        Some(n as u8)
    }

    /// The value of entry `t`; `None` for `MIXED` (and an unused entry).
    #[cfg(test)]
    pub(crate) fn value(&self, t: u8) -> Option<&[i32; C]> {
        if t >= self.len {
            return None;
        }
        self.acc.get(usize::from(t))
    }

    /// The entries in use.
    pub(crate) fn entries(&self) -> &[[i32; C]] {
        self.acc.get(..self.len()).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// An unscaled Rgb565 image at a whole pixel leaves its codes, tagged
    /// `SOURCE`, in a three-channel band that keeps tags; at a fraction
    /// of a pixel, or in a dense band, values tagged `MIXED`. Each pixel's
    /// value is its code decoded (the sRGB tables read here), whatever it
    /// is stored as.
    #[test]
    fn unscaled_rgb565_images_leave_their_codes_tagged_source() {
        use crate::band::{Band, BandBuffer};
        use crate::canvas::Canvas;
        use crate::color::srgb::{SRGB5_TO_LIN12, SRGB6_TO_LIN12};
        use crate::geom::FinePoint;
        use crate::image::{format, AaImage, RawImage};
        let codes: [u16; 6] = [0xf800, 0x07e0, 0x001f, 0x1234, 0xffff, 0x8410];
        let bytes: Vec<u8> = codes.iter().flat_map(|c| c.to_le_bytes()).collect();
        let img = RawImage::<format::Rgb565>::new(&bytes, 3, 2).unwrap();
        let lin = |c: u16| {
            [
                SRGB5_TO_LIN12[usize::from(c >> 11)],
                SRGB6_TO_LIN12[usize::from(c >> 5 & 63)],
                SRGB5_TO_LIN12[usize::from(c & 31)],
            ]
        };
        let (w, rows) = (9u16, 4u16);
        for (at, dense, want_codes) in [
            (FinePoint::from_px(2, 1), false, true),
            (FinePoint::new(2 * 1024 + 512, 1024), false, false),
            (FinePoint::from_px(2, 1), true, false),
        ] {
            let mut acc = std::vec![0i32; BandBuffer::<3>::acc_len(w, rows)];
            let mut cover = std::vec![0i32; BandBuffer::<3>::cover_len(w, rows)];
            let mut buf =
                BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(w, 0, rows)).unwrap();
            buf.clear([10, 20, 30]);
            if dense {
                buf.go_dense();
            }
            Canvas::new(&mut buf, None)
                .draw_image(&AaImage::new(&img).position(at))
                .unwrap();
            let n = row_words(usize::from(w));
            for (k, &code) in codes.iter().enumerate() {
                let (c, r) = (2 + k % 3, 1 + k / 3);
                let t = get(&buf.tags[r * n..r * n + n], c);
                let first = buf.acc[(r * usize::from(w) + c) * 3];
                if want_codes {
                    assert_eq!((t, first), (SOURCE, i32::from(code)), "{at:?} pixel {k}");
                    assert_eq!(buf.lin12(c as i32, r as i32), Some(lin(code)));
                } else {
                    assert_eq!(t, MIXED, "{at:?} dense {dense} pixel {k}");
                    if at.x % 1024 == 0 {
                        assert_eq!(buf.lin12(c as i32, r as i32), Some(lin(code)));
                    }
                }
            }
        }
    }

    /// `fill` against a byte-by-byte reference, over every range of a
    /// 3-word row and every prior content pattern of interest.
    #[test]
    fn fill_sets_exactly_the_range() {
        for c0 in 0..12 {
            for c1 in c0..=12 {
                for before in [0i32, -1, 0x1234_5678] {
                    let mut words = [before; 3];
                    fill(&mut words, c0, c1, 7);
                    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
                    let old: Vec<u8> = [before; 3].iter().flat_map(|w| w.to_le_bytes()).collect();
                    for c in 0..12 {
                        let want = if (c0..c1).contains(&c) { 7 } else { old[c] };
                        assert_eq!(bytes[c], want, "{c0}..{c1}, before {before:#x}, pixel {c}");
                        assert_eq!(get(&words, c), want);
                    }
                }
            }
        }
    }

    /// `materialise` against a pixel-by-pixel reference (each pixel in
    /// the range tagged with an entry gets the entry's value, nothing else
    /// changes), over rows of runs of one word, `MIXED` words, words of
    /// mixed tags and unused entries, every range of each row.
    #[test]
    fn materialise_gives_each_tagged_pixel_its_entry() {
        fn check<const C: usize>(rng: &mut crate::path::testing::Lcg, entries: &[[i32; C]]) {
            let w = 1 + rng.below(23) as usize;
            let mut words: Vec<i32> = Vec::new();
            while words.len() < row_words(w) {
                let t = match rng.below(4) {
                    0 => MIXED,
                    _ => rng.below(entries.len() as u64 + 1) as u8,
                };
                match rng.below(3) {
                    0 => words.push(i32::from_le_bytes([0, 1, 2, 3].map(|_| {
                        if rng.below(3) == 0 {
                            MIXED
                        } else {
                            rng.below(entries.len() as u64 + 1) as u8
                        }
                    }))),
                    _ => {
                        for _ in 0..1 + rng.below(4) {
                            words.push(splat(t));
                        }
                    }
                }
            }
            words.truncate(row_words(w));
            let before: Vec<i32> = (0..w * C).map(|k| -1 - k as i32).collect();
            for c0 in 0..=w {
                for c1 in c0..=w {
                    let mut want = before.clone();
                    for c in c0..c1 {
                        if let Some(v) = entries.get(usize::from(get(&words, c))) {
                            want[c * C..c * C + C].copy_from_slice(v);
                        }
                    }
                    let mut got = before.clone();
                    materialise(&mut got, &words, entries, c0, c1);
                    assert_eq!(got, want, "{c0}..{c1} of {w}, {words:x?}");
                }
            }
        }
        let mut rng = crate::path::testing::Lcg(0x3a7e);
        for _ in 0..300 {
            check::<3>(&mut rng, &[[0, 0, 0], [1, 2, 3], [7, 7, 7], [9, 8, 7]]);
            check::<3>(&mut rng, &[[5 << 16, 6 << 16, 7 << 16]]);
            check::<1>(&mut rng, &[[0], [4], [-3]]);
        }
    }

    #[test]
    fn set_and_set_mixed_touch_one_pixel() {
        let mut words = [0i32; 2];
        set(&mut words, 5, 3);
        set_mixed(&mut words, 2);
        for c in 0..8 {
            let want = match c {
                5 => 3,
                2 => MIXED,
                _ => 0,
            };
            assert_eq!(get(&words, c), want);
        }
        set(&mut words, 2, 1);
        assert_eq!(get(&words, 2), 1);
        // Past the row: MIXED read, writes dropped.
        assert_eq!(get(&words, 8), MIXED);
        set(&mut words, 9, 1);
        fill(&mut words, 6, 20, 4);
        assert_eq!(get(&words, 7), 4);
    }

    /// Interning against a list searched in full, over values that share
    /// channels and slots: the same tags, each value once.
    #[test]
    fn interning_finds_every_entry_once() {
        let mut rng = crate::path::testing::Lcg(0x7a95);
        for _ in 0..500 {
            let mut p = Palette::<3>::new([0, 0, 0]);
            let mut seen: Vec<[i32; 3]> = Vec::from([[0, 0, 0]]);
            for _ in 0..3 * PALETTE {
                let v = [0, 1, 2].map(|_| (rng.below(4) as i32) << 16);
                let want = match seen.iter().position(|e| *e == v) {
                    Some(k) => Some(k as u8),
                    None if seen.len() < PALETTE => {
                        seen.push(v);
                        Some((seen.len() - 1) as u8)
                    }
                    None => None,
                };
                assert_eq!(p.intern(&v), want, "{v:?}");
            }
            assert_eq!(p.entries(), &seen[..]);
        }
    }

    #[test]
    fn the_palette_interns_until_full() {
        let mut p = Palette::<3>::new([5, 6, 7]);
        assert_eq!(p.intern(&[5, 6, 7]), Some(0));
        for k in 1..PALETTE {
            assert_eq!(p.intern(&[k as i32, 0, 0]), Some(k as u8));
        }
        assert_eq!(p.intern(&[1, 0, 0]), Some(1));
        assert_eq!(p.intern(&[-1, 0, 0]), None);
        assert_eq!(p.value(1), Some(&[1, 0, 0]));
        assert_eq!(p.value(MIXED), None);
        assert_eq!(p.entries().len(), PALETTE);
    }
}
