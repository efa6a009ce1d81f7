//! [`QoiImage`]: a QOI file (in flash) decoded row by row, top to bottom,
//! into a caller-provided row cache, never as a whole.
//!
//! QOI is sequential: a row can only be decoded after every row above it.
//! Each band asks for the rows it needs (its pixels' reach in the image);
//! the cache keeps a window of rows, slides it down (dropping the rows
//! above the request, decoding the rows below), and restarts the stream
//! when a request starts at the image's first row (a new frame). A band
//! that needs more rows at once than the cache holds is refused
//! ([`ImageFault::RowCache`]), and so is one that needs a row above the
//! window (not the first row): that would need random access
//! ([`ImageFault::RandomAccess`]), as an image turned upside down does.

use core::cell::RefCell;
use core::ops::Range;

use super::format::rgba;
use super::sealed::{Fetch, Lin, Source};
use super::{ImageFault, MAX_SIDE};

/// Bytes of a decoded texel in the cache (`r, g, b, a`).
const TEXEL: usize = 4;

/// A QOI image decoded into a row cache of `rows x width x 4` bytes.
///
/// ```
/// use softedge::image::QoiImage;
/// // A 2x1 QOI file: two QOI_OP_RGBA texels, then the end marker.
/// static FILE: [u8; 32] = [
///     b'q', b'o', b'i', b'f', 0, 0, 0, 2, 0, 0, 0, 1, 4, 0,
///     0xff, 255, 0, 0, 255, 0xff, 0, 0, 255, 128,
///     0, 0, 0, 0, 0, 0, 0, 1,
/// ];
/// let mut rows = [0u8; 2 * 4 * 3]; // room for 3 rows of 2 texels
/// let img = QoiImage::new(&FILE, &mut rows).unwrap();
/// assert_eq!(img.size(), (2, 1));
/// ```
#[derive(Debug)]
pub struct QoiImage<'a, 'c> {
    data: &'a [u8],
    width: u16,
    height: u16,
    state: RefCell<Decoder<'c>>,
}

/// The decoder's place in the stream and the cache's window.
#[derive(Debug)]
struct Decoder<'c> {
    cache: &'c mut [u8],
    /// Rows the cache holds.
    capacity: usize,
    /// The image row of the cache's first row.
    first: i32,
    /// Rows decoded into the cache.
    held: i32,
    /// Byte offset of the next chunk.
    at: usize,
    px: [u8; 4],
    index: [[u8; 4]; 64],
    /// Repeats of `px` left from a run.
    run: u32,
}

impl<'a, 'c> QoiImage<'a, 'c> {
    /// The image in `data` (a QOI file) over the row cache `cache`; an
    /// error for a file that is not QOI or of a size softedge does not
    /// draw, or a cache without room for one row.
    pub fn new(data: &'a [u8], cache: &'c mut [u8]) -> Result<Self, ImageFault> {
        let be = |k: usize| -> Option<u32> {
            let b = data.get(k..k + 4)?;
            Some(u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
        };
        if data.get(..4) != Some(b"qoif") {
            return Err(ImageFault::Unsupported);
        }
        let (Some(w), Some(h)) = (be(4), be(8)) else {
            return Err(ImageFault::Unsupported);
        };
        if w == 0 || h == 0 || w > u32::from(MAX_SIDE) || h > u32::from(MAX_SIDE) {
            return Err(ImageFault::Size {
                width: w,
                height: h,
            });
        }
        let row = w as usize * TEXEL;
        let capacity = cache.len() / row;
        if capacity == 0 {
            return Err(ImageFault::RowCache { needed: 1, rows: 0 });
        }
        let mut dec = Decoder {
            cache,
            capacity,
            first: 0,
            held: 0,
            at: 0,
            px: [0, 0, 0, 255],
            index: [[0; 4]; 64],
            run: 0,
        };
        dec.restart();
        Ok(Self {
            data,
            width: w as u16,
            height: h as u16,
            state: RefCell::new(dec),
        })
    }

    /// Width and height, texels.
    pub fn size(&self) -> (u16, u16) {
        (self.width, self.height)
    }
}

impl Decoder<'_> {
    fn restart(&mut self) {
        self.first = 0;
        self.held = 0;
        self.at = 14;
        self.px = [0, 0, 0, 255];
        self.index = [[0; 4]; 64];
        self.run = 0;
    }

    /// The next texel of the stream (transparent black past its end).
    fn texel(&mut self, data: &[u8]) -> [u8; 4] {
        if self.run > 0 {
            self.run -= 1;
            return self.px;
        }
        let byte = |k: usize| data.get(k).copied().unwrap_or(0);
        let Some(&op) = data.get(self.at) else {
            return [0; 4];
        };
        self.at += 1;
        let p = self.px;
        match op {
            0xfe => {
                self.px = [byte(self.at), byte(self.at + 1), byte(self.at + 2), p[3]];
                self.at += 3;
            }
            0xff => {
                self.px = [
                    byte(self.at),
                    byte(self.at + 1),
                    byte(self.at + 2),
                    byte(self.at + 3),
                ];
                self.at += 4;
            }
            _ => match op >> 6 {
                0 => self.px = self.index[usize::from(op & 63)],
                1 => {
                    let d = |s: u8| ((op >> s) & 3).wrapping_sub(2);
                    self.px = [
                        p[0].wrapping_add(d(4)),
                        p[1].wrapping_add(d(2)),
                        p[2].wrapping_add(d(0)),
                        p[3],
                    ];
                }
                2 => {
                    let dg = (op & 63).wrapping_sub(32);
                    let b2 = byte(self.at);
                    self.at += 1;
                    let dr = (b2 >> 4).wrapping_sub(8).wrapping_add(dg);
                    let db = (b2 & 15).wrapping_sub(8).wrapping_add(dg);
                    self.px = [
                        p[0].wrapping_add(dr),
                        p[1].wrapping_add(dg),
                        p[2].wrapping_add(db),
                        p[3],
                    ];
                }
                _ => self.run = u32::from(op & 63),
            },
        }
        let [r, g, b, a] = self.px;
        let h =
            (usize::from(r) * 3 + usize::from(g) * 5 + usize::from(b) * 7 + usize::from(a) * 11)
                % 64;
        if let Some(e) = self.index.get_mut(h) {
            *e = self.px;
        }
        self.px
    }

    /// Makes the cache hold image rows `rows` (clipped to `0..height`).
    fn hold(&mut self, data: &[u8], width: usize, rows: Range<i32>) -> Result<(), ImageFault> {
        if rows.start >= rows.end {
            return Ok(());
        }
        let needed = (rows.end - rows.start) as usize;
        if needed > self.capacity {
            return Err(ImageFault::RowCache {
                needed: needed as u32,
                rows: self.capacity as u32,
            });
        }
        if rows.start < self.first {
            if rows.start != 0 {
                return Err(ImageFault::RandomAccess {
                    row: rows.start as u32,
                    held: self.first as u32,
                });
            }
            self.restart();
        }
        let row = width * TEXEL;
        // Slide the window: drop the rows above the request, or all of
        // them when the request lies beyond what would stay.
        while self.first + self.held < rows.end {
            if self.held as usize == self.capacity || (self.first < rows.start && self.held > 0) {
                let drop = if self.first < rows.start {
                    ((rows.start - self.first) as usize).min(self.held as usize)
                } else {
                    1
                };
                let keep = self.held as usize - drop;
                self.cache.copy_within(drop * row..(drop + keep) * row, 0);
                self.first += drop as i32;
                self.held = keep as i32;
                continue;
            }
            let at = self.held as usize * row;
            for k in 0..width {
                let t = self.texel(data);
                if let Some(c) = self.cache.get_mut(at + k * TEXEL..at + (k + 1) * TEXEL) {
                    c.copy_from_slice(&t);
                }
            }
            self.held += 1;
        }
        Ok(())
    }
}

/// The rows a band asked for, as texels.
#[derive(Debug)]
pub struct QoiTexels<'r> {
    rows: &'r [u8],
    first: i32,
    width: usize,
}

impl Fetch for QoiTexels<'_> {
    const OPAQUE: bool = false;
    const MASK: bool = false;
    const GRAY: bool = false;
    #[inline(always)]
    fn texel(&self, x: i32, y: i32) -> Lin {
        let r = y.wrapping_sub(self.first) as usize;
        let k = (r * self.width + x as usize) * TEXEL;
        match self.rows.get(k..k + TEXEL) {
            Some(t) => rgba([t[0], t[1], t[2], t[3]]),
            None => Lin { c: [0; 3], a: 0 },
        }
    }
}

impl<'a, 'c> Source for QoiImage<'a, 'c> {
    type Fetch<'f> = QoiTexels<'f>;
    fn size(&self) -> (u16, u16) {
        (self.width, self.height)
    }
    fn with_rows<R>(
        &self,
        rows: Range<i32>,
        f: impl FnOnce(&Self::Fetch<'_>) -> R,
    ) -> Result<R, ImageFault> {
        let w = usize::from(self.width);
        let rows = rows.start.max(0)..rows.end.min(i32::from(self.height));
        {
            let Ok(mut dec) = self.state.try_borrow_mut() else {
                return Err(ImageFault::Unsupported);
            };
            dec.hold(self.data, w, rows)?;
        }
        let Ok(dec) = self.state.try_borrow() else {
            return Err(ImageFault::Unsupported);
        };
        let held = (dec.held as usize * w * TEXEL).min(dec.cache.len());
        let texels = QoiTexels {
            rows: dec.cache.get(..held).unwrap_or(&[]),
            first: dec.first,
            width: w,
        };
        Ok(f(&texels))
    }
}
