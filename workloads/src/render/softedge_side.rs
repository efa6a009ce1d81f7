//! Every softedge call of the benchmark, in one place (porting the
//! benchmark to another engine API means rewriting this file only).
//!
//! A frame is 240x240, rendered as a firmware with a DMA display does,
//! through softedge's frame loop ([`softedge::render::Renderer`]): per
//! band the band buffer (reset to black as the previous band was sent),
//! every triangle of the workload drawn into the band's canvas in painter's
//! order (the canvas rejects those that miss the band by their bounds; the
//! rest resume their edges' walks from the walk cache), then one
//! `fill_contiguous` through the tone stage (sRGB γ tables of
//! [`Rgb565Format`] / [`Gray8Format`], pack) into the one-band output
//! buffer ([`BandStream`]). The workload's whole-pixel vertices are pixel
//! centres (embedded-graphics' convention for the same points) and its
//! colours linear 12-bit.

use core::hint::black_box;

use crate::{Tri, FRAME};
use embedded_graphics::pixelcolor::Rgb565;
use softedge::canvas::{Canvas, ListedTriangle, TriangleList, WalkSlot};
use softedge::geom::FinePoint;
use softedge::render::Renderer as FrameRenderer;
use softedge::style::{Blend, Opacity};
use softedge::tone::format::{Gray8Format, Rgb565Format};
use softedge::tone::Curve;
use softedge::{BandBuffer, RenderStyle};

use super::targets::BandStream;

/// The tallest band measured (the buffers are sized for it).
pub const MAX_BAND_ROWS: u16 = 16;
/// `i32`s of the accumulation buffer: 240 x 16 pixels x 3 channels.
pub const ACC_LEN: usize = BandBuffer::<3>::acc_len(FRAME, MAX_BAND_ROWS);
/// `i32`s of the cover scratch for 16 rows.
pub const COVER_LEN: usize = BandBuffer::<3>::cover_len(FRAME, MAX_BAND_ROWS);
/// Pixels of the one-band output buffer.
pub const OUT_LEN: usize = FRAME as usize * MAX_BAND_ROWS as usize;
/// Slots of the walk cache: the edges alive across a band boundary, and
/// the planes of the Gouraud triangles alive there, with room to spare.
pub const SLOTS: usize = 256;
/// Entries of the triangle list: the largest workload.
pub const LIST_LEN: usize = crate::COUNT;

/// The display's tone stage: sRGB γ, Rgb565 (tables in flash).
static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
/// The gray display's tone stage: sRGB γ, Gray8.
static GRAY8: Gray8Format = Gray8Format::new(Curve::Srgb);

/// The softedge renderers measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Renderer {
    /// Anti-aliased (exact box coverage), flat RGB, Rgb565.
    AaFlatRgb,
    /// Anti-aliased, Gouraud RGB (a colour per vertex), Rgb565.
    AaGouraudRgb,
    /// Anti-aliased, flat gray (1 channel), Gray8.
    AaGray,
    /// `RenderStyle::ALIASED` (pixel centres, top-left rule), flat RGB, Rgb565.
    AliasedRgb,
    /// As [`AaFlatRgb`](Self::AaFlatRgb) without the walk cache: every
    /// band sets its shapes up again.
    AaFlatRgbNoCache,
    /// As [`AaFlatRgb`](Self::AaFlatRgb), the triangles recorded once per
    /// frame (inside the measured frame) into a
    /// [`softedge::canvas::TriangleList`] that every band
    /// draws: the drawing closure no longer runs per triangle and band.
    AaFlatRgbListed,
}

impl Renderer {
    /// Every renderer, in the order of the output.
    pub const ALL: [Renderer; 6] = [
        Renderer::AaFlatRgb,
        Renderer::AaGouraudRgb,
        Renderer::AaGray,
        Renderer::AliasedRgb,
        Renderer::AaFlatRgbNoCache,
        Renderer::AaFlatRgbListed,
    ];

    /// The name printed in the output.
    pub fn name(self) -> &'static str {
        match self {
            Renderer::AaFlatRgb => "aa_rgb",
            Renderer::AaGouraudRgb => "aa_gouraud",
            Renderer::AaGray => "aa_gray",
            Renderer::AliasedRgb => "aliased_rgb",
            Renderer::AaFlatRgbNoCache => "aa_rgb_nocache",
            Renderer::AaFlatRgbListed => "aa_rgb_listed",
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
    /// The walk cache of the RGB renderers.
    pub slots3: &'a mut [WalkSlot<3>],
    /// The walk cache of the gray renderer.
    pub slots1: &'a mut [WalkSlot<1>],
    /// The triangle list of [`Renderer::AaFlatRgbListed`], at least
    /// [`LIST_LEN`] entries.
    pub list3: &'a mut [ListedTriangle<3>],
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
    match renderer {
        Renderer::AaFlatRgb => {
            frame_rgb(tris, band_rows, bufs, RenderStyle::default(), false, SLOTS)
        }
        Renderer::AaGouraudRgb => {
            frame_rgb(tris, band_rows, bufs, RenderStyle::default(), true, SLOTS)
        }
        Renderer::AliasedRgb => {
            frame_rgb(tris, band_rows, bufs, RenderStyle::ALIASED, false, SLOTS)
        }
        Renderer::AaGray => frame_gray(tris, band_rows, bufs),
        Renderer::AaFlatRgbNoCache => {
            frame_rgb(tris, band_rows, bufs, RenderStyle::default(), false, 0)
        }
        Renderer::AaFlatRgbListed => frame_rgb_listed(tris, band_rows, bufs, SLOTS),
    }
}

/// [`Renderer::AaFlatRgb`] (or, `listed`, [`Renderer::AaFlatRgbListed`])
/// with only the first `slots` walk-cache slots (at most [`SLOTS`]; 0 is
/// no cache): what the cache's RAM buys.
pub fn frame_with_cache(
    tris: &[Tri],
    band_rows: u16,
    slots: usize,
    listed: bool,
    bufs: &mut Buffers<'_>,
) -> Result<(), FrameError> {
    if band_rows > MAX_BAND_ROWS {
        return Err(FrameError);
    }
    if listed {
        frame_rgb_listed(tris, band_rows, bufs, slots)
    } else {
        frame_rgb(tris, band_rows, bufs, RenderStyle::default(), false, slots)
    }
}

/// The vertices on the fine grid: a whole-pixel vertex `(x, y)` at the
/// centre of pixel `(x, y)`, as embedded-graphics reads it
/// (`FinePoint::centre_of`); 1/16 px is 64 fine units.
fn vertices(t: &Tri) -> [FinePoint; 3] {
    let half = FinePoint::centre_of(0, 0).x;
    t.v.map(|[x, y]| FinePoint::new(64 * i32::from(x) + half, 64 * i32::from(y) + half))
}

#[inline(never)]
fn frame_rgb(
    tris: &[Tri],
    band_rows: u16,
    bufs: &mut Buffers<'_>,
    style: RenderStyle,
    gouraud: bool,
    slots: usize,
) -> Result<(), FrameError> {
    render_rgb(band_rows, bufs, slots, |c| {
        c.set_style(style);
        for t in tris {
            let colors = if gouraud { t.rgb } else { [t.flat_rgb(); 3] };
            c.fill_triangle(vertices(t), colors, Blend::Over, Opacity::OPAQUE)?;
        }
        Ok(())
    })
}

#[inline(never)]
fn frame_rgb_listed(
    tris: &[Tri],
    band_rows: u16,
    bufs: &mut Buffers<'_>,
    slots: usize,
) -> Result<(), FrameError> {
    // The list lives in `bufs` beside what the renderer borrows: moved out
    // for the frame, put back after it.
    let store = core::mem::take(&mut bufs.list3);
    let mut list = TriangleList::new(&mut *store);
    let mut result = Ok(());
    for t in tris {
        if list
            .push(vertices(t), [t.flat_rgb(); 3], Blend::Over, Opacity::OPAQUE)
            .is_err()
        {
            result = Err(FrameError);
            break;
        }
    }
    if result.is_ok() {
        result = render_rgb(band_rows, bufs, slots, |c| {
            c.fill_triangles(&list);
            Ok(())
        });
    }
    bufs.list3 = store;
    result
}
/// One RGB frame in bands of `band_rows` into `bufs.out16`, drawn by
/// `draw` in every band, with the first `slots` walk-cache slots.
fn render_rgb(
    band_rows: u16,
    bufs: &mut Buffers<'_>,
    slots: usize,
    draw: impl FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), softedge::DrawError>,
) -> Result<(), FrameError> {
    let n = slots.min(bufs.slots3.len());
    let mut r = FrameRenderer::<3>::new(
        &mut *bufs.acc,
        &mut *bufs.cover,
        &mut bufs.slots3[..n],
        FRAME,
        FRAME,
        band_rows,
    )
    .map_err(|_| FrameError)?;
    let mut sink = BandStream::new(&mut *bufs.out16, u32::from(FRAME), u32::from(FRAME));
    let report = r
        .render(&mut sink, &RGB565, [0; 3], draw)
        .map_err(|_| FrameError)?;
    black_box(report);
    black_box(sink.pixels());
    Ok(())
}

#[inline(never)]
fn frame_gray(tris: &[Tri], band_rows: u16, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    let mut r = FrameRenderer::<1>::new(
        &mut *bufs.acc,
        &mut *bufs.cover,
        &mut *bufs.slots1,
        FRAME,
        FRAME,
        band_rows,
    )
    .map_err(|_| FrameError)?;
    let mut sink = BandStream::new(&mut *bufs.out8, u32::from(FRAME), u32::from(FRAME));
    let report = r
        .render(&mut sink, &GRAY8, [0], |c| {
            for t in tris {
                c.fill_triangle(vertices(t), [[t.gray()]; 3], Blend::Over, Opacity::OPAQUE)?;
            }
            Ok::<(), softedge::DrawError>(())
        })
        .map_err(|_| FrameError)?;
    black_box(report);
    black_box(sink.pixels());
    Ok(())
}
