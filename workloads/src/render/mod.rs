//! The benchmark's renderers (feature `render`): the frames that the
//! Cortex-M0 firmware (`boards/bench-m0`) and the host bench
//! (`softedge-sim`'s `bench` binary) measure, the very same code on both.
//!
//! - [`softedge_side`]: every softedge call, in one module (porting the
//!   benchmark to another softedge API means rewriting that file only).
//! - [`eg_side`]: embedded-graphics' aliased `Triangle` fill.
//! - [`targets`]: the displays both draw into (a one-band DMA buffer, a
//!   240x240 framebuffer), plain memory, and a counter of what an SPI
//!   display would be sent.
//! - [`ui`]: a filled circle, a stroked arc gauge, and a dial screen
//!   redrawn whole or in a dirty rectangle, by both (issues 16 and 15).

pub mod eg_side;
pub mod images;
pub mod softedge_side;
pub mod targets;
pub mod ui;

#[cfg(test)]
mod tests {
    extern crate std;
    use std::boxed::Box;
    use std::vec;

    use super::eg_side::{self, StockFramebuffer, Targets};
    use super::softedge_side::{
        self, Buffers, Renderer, ACC_LEN, COVER_LEN, LIST_LEN, OUT_LEN, SLOTS,
    };
    use super::targets::{Framebuffer, FB_LEN};
    use crate::{Tri, CLASSES, SCREEN};
    use softedge::canvas::{ListedTriangle, WalkSlot};

    struct Storage {
        acc: vec::Vec<i32>,
        cover: vec::Vec<i32>,
        out16: vec::Vec<u16>,
        out8: vec::Vec<u8>,
        slots3: vec::Vec<WalkSlot<3>>,
        slots1: vec::Vec<WalkSlot<1>>,
        list3: vec::Vec<ListedTriangle<3>>,
    }

    impl Storage {
        fn new() -> Self {
            Self {
                acc: vec![0; ACC_LEN],
                cover: vec![0; COVER_LEN],
                out16: vec![0; OUT_LEN],
                out8: vec![0; OUT_LEN],
                slots3: vec![WalkSlot::EMPTY; SLOTS],
                slots1: vec![WalkSlot::EMPTY; SLOTS],
                list3: vec![ListedTriangle::EMPTY; LIST_LEN],
            }
        }

        fn bufs(&mut self) -> Buffers<'_> {
            Buffers {
                acc: &mut self.acc,
                cover: &mut self.cover,
                out16: &mut self.out16,
                out8: &mut self.out8,
                slots3: &mut self.slots3,
                slots1: &mut self.slots1,
                list3: &mut self.list3,
            }
        }

        fn frame(&mut self, r: Renderer, tris: &[Tri], rows: u16) -> bool {
            softedge_side::frame(r, tris, rows, &mut self.bufs()).is_ok()
        }
    }

    #[test]
    fn every_softedge_renderer_renders_every_workload_at_every_band_height() {
        let mut s = Storage::new();
        for r in Renderer::ALL {
            for w in CLASSES {
                assert!(s.frame(r, w.prefix(40), 16), "{} {}", r.name(), w.name);
            }
            for rows in [16, 8, 6, 4, 3, 2, 1] {
                assert!(s.frame(r, SCREEN.tris, rows), "{} {rows}", r.name());
            }
            assert!(
                !s.frame(r, SCREEN.tris, 17),
                "bands over 16 rows are refused"
            );
        }
    }

    #[test]
    fn neither_the_walk_cache_nor_a_triangle_list_changes_a_pixel() {
        // The last band of the frame stays in the output buffer. A cache
        // of 16 slots is too small for the screen's live edges in 3-row
        // bands: entries are refused and set up again, never wrong.
        // Nor does drawing the triangles from a list recorded per frame.
        let (mut a, mut b, mut c) = (Storage::new(), Storage::new(), Storage::new());
        let mut d = Storage::new();
        for rows in [16, 3, 1] {
            assert!(a.frame(Renderer::AaFlatRgb, SCREEN.tris, rows));
            assert!(d.frame(Renderer::AaFlatRgbListed, SCREEN.tris, rows));
            assert!(b.frame(Renderer::AaFlatRgbNoCache, SCREEN.tris, rows));
            assert!(
                softedge_side::frame_with_cache(SCREEN.tris, rows, 16, false, &mut c.bufs())
                    .is_ok()
            );
            let last_rows = match 240 % rows {
                0 => rows,
                r => r,
            };
            let n = 240 * usize::from(last_rows);
            assert_eq!(a.out16[..n], b.out16[..n]);
            assert_eq!(a.out16[..n], c.out16[..n]);
            assert_eq!(a.out16[..n], d.out16[..n]);
            assert!(a.out16[..n].iter().any(|&p| p != 0));
        }
    }

    #[test]
    fn both_framebuffers_get_the_same_pixels() {
        let mut fb = Box::new([0u16; FB_LEN]);
        let mut stock = Box::new(StockFramebuffer::new());
        for w in CLASSES.iter().copied().chain([&SCREEN]) {
            let mut targets = Targets {
                fb: Framebuffer::new(&mut fb),
                stock: &mut stock,
            };
            for r in eg_side::Renderer::ALL {
                eg_side::frame(r, w.prefix(200), &mut targets);
            }
            let stock_px: vec::Vec<u16> = targets
                .stock
                .data()
                .chunks_exact(2)
                .map(|b| u16::from_le_bytes([b[0], b[1]]))
                .collect();
            assert_eq!(targets.fb.pixels()[..], stock_px[..], "{}", w.name);
        }
    }
}
