//! Shared pieces of the fuzz targets: a reader that turns fuzzer bytes
//! into bounded values, and a frame renderer that draws the same content
//! in bands of two heights so every target can check band invariance.
//!
//! Each target keeps its use of the core drawing API in one helper
//! function (`draw`) that draws its content into one band: when the
//! drawing API changes, that function is what to port.

use softedge::geom::COORD_LIMIT_SUB;
use softedge::{Band, BandBuffer, Bands, PixelModel, RenderStyle, SubPoint};

/// Reads fuzzer bytes as bounded values; past the end every read is 0.
pub struct Input<'a> {
    data: &'a [u8],
}

impl<'a> Input<'a> {
    pub fn new(data: &'a [u8]) -> Self {
        Self { data }
    }

    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    pub fn u8(&mut self) -> u8 {
        match self.data.split_first() {
            Some((&b, rest)) => {
                self.data = rest;
                b
            }
            None => 0,
        }
    }

    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }

    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }

    pub fn bool(&mut self) -> bool {
        self.u8() & 1 == 1
    }

    /// A value in `lo..=hi`.
    pub fn range(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (i64::from(hi) - i64::from(lo) + 1).max(1) as u64;
        (i64::from(lo) + (u64::from(self.u32()) % span) as i64) as i32
    }

    /// A sub-pixel coordinate: mostly near a frame of `size` px, sometimes
    /// at or beyond the documented limit (those must be rejected, not
    /// panic).
    pub fn coord(&mut self, size: u16) -> i32 {
        let size_sub = i32::from(size) * 16;
        match self.u8() % 16 {
            0 => COORD_LIMIT_SUB - self.range(0, 40),
            1 => -COORD_LIMIT_SUB + self.range(0, 40),
            2 => self.range(-COORD_LIMIT_SUB - 64, COORD_LIMIT_SUB + 64),
            3 => self.u32() as i32,
            _ => self.range(-64, size_sub + 64),
        }
    }

    /// A render style from two bytes: aliased one time in five, any pixel
    /// model.
    pub fn style(&mut self) -> RenderStyle {
        RenderStyle {
            antialias: !self.u8().is_multiple_of(5),
            model: PixelModel::ALL[usize::from(self.u8()) % PixelModel::ALL.len()],
        }
    }

    pub fn point(&mut self, w: u16, h: u16) -> SubPoint {
        SubPoint::new(self.coord(w), self.coord(h))
    }

    /// A linear 12-bit value, sometimes above 4095 (clamped by core).
    pub fn lin12(&mut self) -> u16 {
        match self.u8() % 8 {
            0 => self.u16(),
            1 => 0,
            2 => 4095,
            _ => self.u16() % 4096,
        }
    }

    pub fn color<const C: usize>(&mut self) -> [u16; C] {
        core::array::from_fn(|_| self.lin12())
    }

    /// A frame side in `1..=max`.
    pub fn side(&mut self, max: u16) -> u16 {
        1 + self.u16() % max
    }

    /// What every target reads first: a frame of up to 96x64 pixels, its
    /// style and gray background, and the two band heights compared.
    pub fn frame_setup(&mut self) -> FrameSetup {
        let (w, h) = (self.side(96), self.side(64));
        let style = self.style();
        let background = [self.lin12()];
        let rows = (self.side(h), self.side(h));
        FrameSetup {
            w,
            h,
            style,
            background,
            rows,
        }
    }
}

/// A fuzzed frame's size, style, background and band heights
/// ([`Input::frame_setup`]).
pub struct FrameSetup {
    pub w: u16,
    pub h: u16,
    pub style: RenderStyle,
    pub background: [u16; 1],
    /// The two band heights whose frames must be equal.
    pub rows: (u16, u16),
}

/// The resolved frame, `width * height` pixels, row by row.
pub type Frame<const C: usize> = Vec<[u16; C]>;

/// Renders a `width x height` frame in bands of `rows`, each band cleared
/// to `background` and handed to `draw` (which may fail: the error is
/// returned, so a target can check that every band height fails alike).
pub fn render<const C: usize, E>(
    width: u16,
    height: u16,
    rows: u16,
    background: [u16; C],
    mut draw: impl FnMut(&mut BandBuffer<'_, C>, Band) -> Result<(), E>,
) -> Result<Frame<C>, E> {
    let rows = rows.max(1);
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(width, rows)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(width, rows)];
    let mut frame = vec![[0u16; C]; usize::from(width) * usize::from(height)];
    for band in Bands::new(width, height, rows) {
        let mut buf = BandBuffer::<C>::new(&mut acc, &mut cover, band).expect("valid band");
        buf.clear(background);
        draw(&mut buf, band)?;
        for r in 0..band.rows {
            let y = band.y0 + i32::from(r);
            let start = y as usize * usize::from(width);
            let n = buf.resolve_row(y, &mut frame[start..start + usize::from(width)]);
            assert_eq!(n, usize::from(width));
        }
    }
    Ok(frame)
}

/// Renders the frame in bands of `rows_a` and `rows_b` rows and asserts the
/// same result (the core promises the same bits for every band height).
pub fn assert_band_invariant<const C: usize, E: PartialEq + core::fmt::Debug>(
    width: u16,
    height: u16,
    rows_a: u16,
    rows_b: u16,
    background: [u16; C],
    mut draw: impl FnMut(&mut BandBuffer<'_, C>, Band) -> Result<(), E>,
) -> Result<Frame<C>, E> {
    let a = render(width, height, rows_a, background, &mut draw);
    let b = render(width, height, rows_b, background, &mut draw);
    match (&a, &b) {
        (Ok(fa), Ok(fb)) => {
            if let Some(k) = fa.iter().zip(fb).position(|(p, q)| p != q) {
                panic!(
                    "band heights {rows_a} and {rows_b} differ at pixel ({}, {}): {:?} vs {:?}",
                    k % usize::from(width),
                    k / usize::from(width),
                    fa[k],
                    fb[k]
                );
            }
        }
        (Err(ea), Err(eb)) => assert_eq!(ea, eb, "band heights {rows_a} and {rows_b}"),
        _ => panic!(
            "band heights {rows_a} and {rows_b}: one failed: {:?} vs {:?}",
            a.as_ref().err(),
            b.as_ref().err()
        ),
    }
    a
}
