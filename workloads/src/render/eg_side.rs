//! embedded-graphics' aliased `Triangle` fill of the same triangles, into a
//! 240x240 Rgb565 framebuffer (the comparison softedge is measured
//! against).
//!
//! A frame: `clear` (the framebuffer's fixed cost; a DMA sends a
//! framebuffer without the CPU), then per triangle
//! `Triangle::new(..).into_styled(PrimitiveStyle::with_fill(c)).draw(fb)`,
//! which walks the triangle's scanlines and calls `fill_solid` once per
//! scanline. The colour is the workload's flat linear colour truncated to
//! 5-6-5 bits (embedded-graphics has no γ stage), once per triangle.
//!
//! Two framebuffers: ours ([`Framebuffer`]: `fill_solid` fills row slices)
//! and embedded-graphics' own `framebuffer::Framebuffer`, which implements
//! only `draw_iter`, so every pixel of a scanline (and of `clear`) goes
//! through `set_pixel`'s bounds check.

use core::hint::black_box;

use crate::Tri;
use embedded_graphics::framebuffer::{buffer_size, Framebuffer as EgFramebuffer};
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Triangle};

use super::targets::{Framebuffer, FB_SIDE};

/// embedded-graphics' own 240x240 Rgb565 framebuffer.
pub type StockFramebuffer = EgFramebuffer<
    Rgb565,
    RawU16,
    LittleEndian,
    FB_SIDE,
    FB_SIDE,
    { buffer_size::<Rgb565>(FB_SIDE, FB_SIDE) },
>;

/// The embedded-graphics renderers measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Renderer {
    /// `Triangle` fill into [`Framebuffer`] (row-slice `fill_solid`).
    Fill,
    /// `Triangle` fill into [`StockFramebuffer`] (per-pixel `draw_iter`).
    StockFramebuffer,
}

impl Renderer {
    /// Every renderer, in the order of the output.
    pub const ALL: [Renderer; 2] = [Renderer::Fill, Renderer::StockFramebuffer];

    /// The name printed in the output.
    pub fn name(self) -> &'static str {
        match self {
            Renderer::Fill => "eg_fill",
            Renderer::StockFramebuffer => "eg_stock_fb",
        }
    }
}

/// The framebuffers of both renderers.
pub struct Targets<'a> {
    /// Ours.
    pub fb: Framebuffer<'a>,
    /// embedded-graphics'.
    pub stock: &'a mut StockFramebuffer,
}

/// Renders one frame of `tris` with `renderer`.
pub fn frame(renderer: Renderer, tris: &[Tri], targets: &mut Targets<'_>) {
    match renderer {
        Renderer::Fill => {
            draw_all(tris, &mut targets.fb);
            black_box(targets.fb.pixels());
        }
        Renderer::StockFramebuffer => {
            draw_all(tris, targets.stock);
            black_box(targets.stock.data());
        }
    }
}

/// The 5-6-5 colour of a linear 12-bit one, truncated.
fn rgb565([r, g, b]: [u16; 3]) -> Rgb565 {
    Rgb565::new((r >> 7) as u8, (g >> 6) as u8, (b >> 7) as u8)
}

#[inline(never)]
fn draw_all<D: DrawTarget<Color = Rgb565>>(tris: &[Tri], target: &mut D) {
    // Both targets are infallible.
    let _ = target.clear(Rgb565::BLACK);
    for t in tris {
        let [a, b, c] = t.px().map(|[x, y]| Point::new(x, y));
        let _ = Triangle::new(a, b, c)
            .into_styled(PrimitiveStyle::with_fill(rgb565(t.flat_rgb())))
            .draw(target);
    }
}
