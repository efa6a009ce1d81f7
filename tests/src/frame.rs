//! Drawing a frame through bands, and recording edge walks.

use std::collections::BTreeMap;

use softedge::canvas::{Canvas, WalkCache, WalkSlot};
use softedge::edge::CoverSink;
use softedge::{BandBuffer, Bands, SubPoint};

/// A whole frame read back from its bands.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Frame<const C: usize> {
    /// Width in pixels.
    pub width: i32,
    /// Height in pixels.
    pub height: i32,
    /// `BandBuffer::raw` of every pixel, row-major.
    pub raw: Vec<[i32; C]>,
    /// `BandBuffer::lin12` of every pixel, row-major.
    pub lin12: Vec<[u16; C]>,
}

impl<const C: usize> Frame<C> {
    /// Raw value of `(x, y)`.
    pub fn raw_at(&self, x: i32, y: i32) -> [i32; C] {
        self.raw[(y * self.width + x) as usize]
    }
    /// lin12 value of `(x, y)`.
    pub fn lin_at(&self, x: i32, y: i32) -> [u16; C] {
        self.lin12[(y * self.width + x) as usize]
    }
}

/// Draws a frame of `width x height` in bands of `rows` rows over
/// background `bg`; `draw` is called once per band with the cleared buffer.
pub fn render<const C: usize>(
    width: u16,
    height: u16,
    rows: u16,
    bg: [u16; C],
    mut draw: impl FnMut(&mut BandBuffer<'_, C>),
) -> Frame<C> {
    let (w, h) = (usize::from(width), usize::from(height));
    let mut raw = vec![[0i32; C]; w * h];
    let mut lin12 = vec![[0u16; C]; w * h];
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(width, rows)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(width, rows)];
    for band in Bands::new(width, height, rows) {
        let mut buf = BandBuffer::<C>::new(&mut acc, &mut cover, band).expect("band buffer");
        buf.clear(bg);
        draw(&mut buf);
        for y in band.y0..band.y0 + i32::from(band.rows) {
            for x in 0..i32::from(width) {
                let k = y as usize * w + x as usize;
                raw[k] = buf.raw(x, y).expect("pixel in band");
                lin12[k] = buf.lin12(x, y).expect("pixel in band");
            }
        }
    }
    Frame {
        width: i32::from(width),
        height: i32::from(height),
        raw,
        lin12,
    }
}

/// Sub-pixel points from `(x, y)` pairs.
pub fn sub_points(v: &[(i64, i64)]) -> Vec<SubPoint> {
    v.iter()
        .map(|&(x, y)| SubPoint::new(x as i32, y as i32))
        .collect()
}

/// Records everything an edge walk reports.
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    /// Cover changes `(x, y, delta)` in the order reported.
    pub covers: Vec<(i32, i32, i32)>,
}

impl CoverSink for Recorder {
    fn cover(&mut self, x: i32, y: i32, delta: i32) {
        self.covers.push((x, y, delta));
    }
}

impl Recorder {
    /// The walk's signed area per pixel: `Σ cover deltas at columns <= x
    /// of row y`, for `x` in `x_lo..=x_hi`, per row that the
    /// walk mentions. Returned as `row -> areas[x - x_lo]`.
    pub fn areas(&self, x_lo: i32, x_hi: i32) -> BTreeMap<i32, Vec<i64>> {
        let mut rows: BTreeMap<i32, Vec<i64>> = BTreeMap::new();
        let width = (x_hi - x_lo + 1) as usize;
        let mut deltas: BTreeMap<i32, Vec<i64>> = BTreeMap::new();
        for &(x, y, d) in &self.covers {
            rows.entry(y).or_insert_with(|| vec![0; width]);
            let row = deltas.entry(y).or_insert_with(|| vec![0; width]);
            // Deltas left of the window apply to all of it.
            let k = (x.max(x_lo) - x_lo) as usize;
            if x <= x_hi {
                row[k] += i64::from(d);
            }
        }
        for (y, row) in rows.iter_mut() {
            if let Some(d) = deltas.get(y) {
                let mut run = 0;
                for (a, dd) in row.iter_mut().zip(d) {
                    run += dd;
                    *a += run;
                }
            }
        }
        rows
    }
}

/// Draws a frame of `width x height` through a [`Canvas`] per band of
/// `rows` rows over background `bg`, with a walk cache of `slots` slots
/// (0: none); `draw` is called once per band.
pub fn render_canvas<const C: usize>(
    width: u16,
    height: u16,
    rows: u16,
    bg: [u16; C],
    slots: usize,
    draw: impl FnMut(&mut Canvas<'_, '_, C>),
) -> Frame<C> {
    render_canvas_of::<C, [u16; C]>(width, height, rows, bg, slots, draw)
}

/// [`render_canvas`] with a canvas of colour type `Col` (an
/// embedded-graphics colour: the canvas is then a `DrawTarget` of it).
pub fn render_canvas_of<const C: usize, Col>(
    width: u16,
    height: u16,
    rows: u16,
    bg: [u16; C],
    slots: usize,
    mut draw: impl FnMut(&mut Canvas<'_, '_, C, Col>),
) -> Frame<C> {
    let mut cache = vec![WalkSlot::<C>::EMPTY; slots];
    WalkCache::new(&mut cache).clear();
    render(width, height, rows, bg, |buf| {
        let cache = (slots > 0).then(|| WalkCache::new(&mut cache));
        let mut canvas = Canvas::typed(buf, cache).with_frame(width, height);
        draw(&mut canvas);
    })
}
