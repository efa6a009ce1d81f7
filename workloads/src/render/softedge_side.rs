//! Every softedge call of the benchmark, in one place (porting the
//! benchmark to another engine API means rewriting this file only).
//!
//! A frame is 240x240, rendered band by band as a firmware with a DMA
//! display does: per band, a [`BandBuffer`] over the static buffers is
//! cleared to black, every triangle of the workload is drawn into it
//! (`Triangle::draw`, which clips it to the band), then the band goes
//! through the tone stage (sRGB γ tables of [`Rgb565Format`] /
//! [`Gray8Format`], pack) into the one-band output buffer with
//! [`BandBuffer::flush`] (one `fill_contiguous` into a [`BandSink`]), or, for
//! [`Renderer::AaFlatRgbRows`], with `resolve_row` + `code_row` row by row.
//! The workload's whole-pixel vertices become `SubPoint::from_px` and its
//! colours linear 12-bit inside the measured frame (a few instructions per
//! triangle and band).

use core::hint::black_box;

use crate::{Tri, FRAME};
use softedge::tone::format::{code_row, Gray8Format, Rgb565Format, ToneFormat};
use softedge::tone::Curve;
use softedge::{BandBuffer, Bands, RenderStyle, SubPoint, Triangle};

use super::targets::BandSink;

/// The tallest band measured (the buffers are sized for it).
pub const MAX_BAND_ROWS: u16 = 16;
/// `i32`s of the accumulation buffer: 240 x 16 pixels x 3 channels.
pub const ACC_LEN: usize = BandBuffer::<3>::acc_len(FRAME, MAX_BAND_ROWS);
/// `i32`s of the cover scratch for 16 rows.
pub const COVER_LEN: usize = BandBuffer::<3>::cover_len(FRAME, MAX_BAND_ROWS);
/// Pixels of the one-band output buffer.
pub const OUT_LEN: usize = FRAME as usize * MAX_BAND_ROWS as usize;
/// Pixels of one frame row.
pub const ROW_LEN: usize = FRAME as usize;

/// The display's tone stage: sRGB γ, Rgb565 (tables in flash).
static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
/// The gray display's tone stage: sRGB γ, Gray8.
static GRAY8: Gray8Format = Gray8Format::new(Curve::Srgb);

/// The softedge renderers measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Renderer {
    /// Anti-aliased (exact box coverage), flat RGB, Rgb565 through `flush`.
    AaFlatRgb,
    /// Anti-aliased, Gouraud RGB (a colour per vertex), Rgb565.
    AaGouraudRgb,
    /// Anti-aliased, flat gray (1 channel), Gray8.
    AaGray,
    /// `RenderStyle::ALIASED` (pixel centres, top-left rule), flat RGB, Rgb565.
    AliasedRgb,
    /// As [`AaFlatRgb`](Self::AaFlatRgb), flushed by `resolve_row` +
    /// `code_row` into the output buffer instead of `flush`.
    AaFlatRgbRows,
}

impl Renderer {
    /// Every renderer, in the order of the output.
    pub const ALL: [Renderer; 5] = [
        Renderer::AaFlatRgb,
        Renderer::AaGouraudRgb,
        Renderer::AaGray,
        Renderer::AliasedRgb,
        Renderer::AaFlatRgbRows,
    ];

    /// The name printed in the output.
    pub fn name(self) -> &'static str {
        match self {
            Renderer::AaFlatRgb => "aa_rgb",
            Renderer::AaGouraudRgb => "aa_gouraud",
            Renderer::AaGray => "aa_gray",
            Renderer::AliasedRgb => "aliased_rgb",
            Renderer::AaFlatRgbRows => "aa_rgb_rows",
        }
    }
}

/// The static buffers a frame is rendered in.
pub struct Buffers<'a> {
    /// Accumulation, at least [`ACC_LEN`].
    pub acc: &'a mut [i32],
    /// Cover scratch, at least [`COVER_LEN`].
    pub cover: &'a mut [i32],
    /// The Rgb565 output band, at least [`OUT_LEN`].
    pub out16: &'a mut [u16],
    /// The Gray8 output band, at least [`OUT_LEN`].
    pub out8: &'a mut [u8],
    /// One resolved row (`resolve_row` + `code_row` only).
    pub row: &'a mut [[u16; 3]; ROW_LEN],
}

/// A frame stopped: a buffer did not fit its band or a triangle was
/// rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameError;

/// Renders one 240x240 frame of `tris` with `renderer` in bands of
/// `band_rows` rows (at most [`MAX_BAND_ROWS`]).
pub fn frame(
    renderer: Renderer,
    tris: &[Tri],
    band_rows: u16,
    bufs: &mut Buffers<'_>,
) -> Result<(), FrameError> {
    if band_rows > MAX_BAND_ROWS {
        return Err(FrameError);
    }
    let aa = RenderStyle::default();
    match renderer {
        Renderer::AaFlatRgb => frame_rgb(tris, band_rows, bufs, &aa, false),
        Renderer::AaGouraudRgb => frame_rgb(tris, band_rows, bufs, &aa, true),
        Renderer::AliasedRgb => frame_rgb(tris, band_rows, bufs, &RenderStyle::ALIASED, false),
        Renderer::AaGray => frame_gray(tris, band_rows, bufs),
        Renderer::AaFlatRgbRows => frame_rgb_rows(tris, band_rows, bufs),
    }
}

fn vertices(t: &Tri) -> [SubPoint; 3] {
    t.v.map(|[x, y]| SubPoint::from_px(i32::from(x), i32::from(y)))
}

fn triangle_rgb(t: &Tri, gouraud: bool) -> Triangle<3> {
    if gouraud {
        Triangle::new(vertices(t), t.rgb)
    } else {
        Triangle::flat(vertices(t), t.flat_rgb())
    }
}

#[inline(never)]
fn frame_rgb(
    tris: &[Tri],
    band_rows: u16,
    bufs: &mut Buffers<'_>,
    style: &RenderStyle,
    gouraud: bool,
) -> Result<(), FrameError> {
    for band in Bands::new(FRAME, FRAME, band_rows) {
        let mut buf = BandBuffer::<3>::new(bufs.acc, bufs.cover, band).map_err(|_| FrameError)?;
        buf.clear([0; 3]);
        for t in tris {
            triangle_rgb(t, gouraud)
                .draw(&mut buf, style)
                .map_err(|_| FrameError)?;
        }
        let mut sink = BandSink::new(
            &mut *bufs.out16,
            u32::from(FRAME),
            u32::from(FRAME),
            band.y0,
            u32::from(band.rows),
        );
        let Ok(()) = buf.flush(&mut sink, |px| RGB565.color(px));
        black_box(sink.pixels());
    }
    Ok(())
}

#[inline(never)]
fn frame_gray(tris: &[Tri], band_rows: u16, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    let aa = RenderStyle::default();
    for band in Bands::new(FRAME, FRAME, band_rows) {
        let mut buf = BandBuffer::<1>::new(bufs.acc, bufs.cover, band).map_err(|_| FrameError)?;
        buf.clear([0]);
        for t in tris {
            Triangle::flat(vertices(t), [t.gray()])
                .draw(&mut buf, &aa)
                .map_err(|_| FrameError)?;
        }
        let mut sink = BandSink::new(
            &mut *bufs.out8,
            u32::from(FRAME),
            u32::from(FRAME),
            band.y0,
            u32::from(band.rows),
        );
        let Ok(()) = buf.flush(&mut sink, |px| GRAY8.color(px));
        black_box(sink.pixels());
    }
    Ok(())
}

#[inline(never)]
fn frame_rgb_rows(tris: &[Tri], band_rows: u16, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    let aa = RenderStyle::default();
    for band in Bands::new(FRAME, FRAME, band_rows) {
        let mut buf = BandBuffer::<3>::new(bufs.acc, bufs.cover, band).map_err(|_| FrameError)?;
        buf.clear([0; 3]);
        for t in tris {
            triangle_rgb(t, false)
                .draw(&mut buf, &aa)
                .map_err(|_| FrameError)?;
        }
        let rows = bufs.out16.chunks_exact_mut(ROW_LEN);
        for (y, out) in (band.y0..band.y0 + i32::from(band.rows)).zip(rows) {
            buf.resolve_row(y, &mut bufs.row[..]);
            code_row(&RGB565, &bufs.row[..], out);
        }
        black_box(&bufs.out16[..]);
    }
    Ok(())
}
