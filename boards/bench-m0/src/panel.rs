//! The RP2040 firmware's instrument panel (`boards/rp2040-st7789/src/ui.rs`,
//! compiled here unchanged) rendered as the firmware renders it: a whole
//! frame, and the partial redraws from one state to the next (each of
//! `Panel::dirty`'s rectangles through `render_window`), in bands of
//! several heights, into a one-band stream as a DMA flush would take it.
//! The firmware's frame loop without its display: what its README's
//! frame times are measured with.

#[allow(dead_code)]
#[path = "../../rp2040-st7789/src/ui.rs"]
mod ui;

use softedge::canvas::{ShapeCache, ShapeEntry};
use softedge::path::Segment;
use softedge::prelude::*;
use softedge::render::Renderer;
use softedge::tone::Curve;
use softedge_workloads::render::targets::BandStream;

pub use ui::Panel;

/// The panel's size.
pub const W: u16 = 240;
pub const H: u16 = 240;
/// Band heights measured (the firmware's own is 40).
pub const ROWS: [u16; 4] = [8, 16, 24, 40];
/// The tallest of them.
pub const MAX_ROWS: u16 = 40;
/// Buffers for bands of [`MAX_ROWS`].
pub const ACC_LEN: usize = BandBuffer::<3>::acc_len(W, MAX_ROWS);
pub const COVER_LEN: usize = BandBuffer::<3>::cover_len(W, MAX_ROWS);
pub const OUT_LEN: usize = W as usize * MAX_ROWS as usize;
/// Walk-cache slots, as the firmware has.
pub const SLOTS: usize = 16;
/// Partial redraws averaged: the states `1..=PARTIAL_FRAMES`, each from
/// the one before.
pub const PARTIAL_FRAMES: u32 = 60;

static TONE: Rgb565Format = Rgb565Format::new(Curve::Srgb);

/// Segments and entries of the shape cache some runs use, as the
/// firmware has (the panel's outlines hold 2 132 segments in 32 entries:
/// `shape_cache_used`).
pub const CACHE_SEGMENTS: usize = 2304;
pub const CACHE_ENTRIES: usize = 40;

/// What the panel's frames draw into.
pub struct PanelBuffers<'a> {
    pub acc: &'a mut [i32],
    pub cover: &'a mut [i32],
    pub out: &'a mut [u16],
    pub slots: &'a mut [WalkSlot<3>],
    /// The shape cache, used when `cached` is set.
    pub segments: &'a mut [Segment],
    pub entries: &'a mut [ShapeEntry],
    pub cached: bool,
}

impl PanelBuffers<'_> {
    /// Empties the shape cache.
    pub fn forget_shapes(&mut self) {
        self.entries.fill(ShapeEntry::EMPTY);
    }

    /// The shape cache's outlines kept, segments held, and shapes drawn
    /// directly for lack of room.
    pub fn shape_cache_used(&mut self) -> (usize, usize, usize) {
        ShapeCache::new(self.segments, self.entries, 0).used()
    }
}

/// The band buffers' bytes for bands of `rows` (accumulator and cover
/// scratch, as `softedge-sim memory` counts them).
pub fn band_bytes(rows: u16) -> usize {
    4 * (BandBuffer::<3>::acc_len(W, rows) + BandBuffer::<3>::cover_len(W, rows))
}

/// Renders `panel` whole (`from: None`) or its redraw from the state
/// `from` (each dirty rectangle a window), in bands of `rows`; `false`
/// on any error or skipped shape.
pub fn frame(panel: &Panel, from: Option<&Panel>, rows: u16, b: &mut PanelBuffers<'_>) -> bool {
    let Some(acc) = b.acc.get_mut(..BandBuffer::<3>::acc_len(W, rows)) else {
        return false;
    };
    let Some(cover) = b.cover.get_mut(..BandBuffer::<3>::cover_len(W, rows)) else {
        return false;
    };
    let Ok(mut r) = Renderer::new(acc, cover, b.slots, W, H, rows) else {
        return false;
    };
    if b.cached {
        r = r.with_shape_cache(b.segments, b.entries);
    }
    let mut sink = BandStream::new(&mut *b.out, u32::from(W), u32::from(H));
    let clean = |rep: Result<FrameReport, _>| matches!(rep, Ok(rep) if rep.skipped.count == 0);
    let ok = match from {
        None => clean(r.render(&mut sink, &TONE, ui::BACKGROUND, |c| panel.draw(c))),
        Some(before) => before.dirty(panel).rects().all(|area| {
            clean(r.render_window(&mut sink, &TONE, ui::BACKGROUND, area, |c| panel.draw(c)))
        }),
    };
    core::hint::black_box(sink.pixels());
    ok
}
