//! The Cortex-M0 benchmark: softedge's renderers and embedded-graphics'
//! aliased triangle fill (`softedge_workloads::render`, the frames the host
//! bench measures too) on the triangles of `softedge-workloads`, 240x240
//! frames, instructions counted by SysTick under
//! `qemu-system-arm -machine mps2-an385 -icount shift=0` (thumbv6m code on
//! the board's Cortex-M3; see `boards/README.md`). `cargo run --release`
//! runs it; `bash boards/bench-m0.sh` turns the output into a table.
//!
//! Output, one line per measured frame (nothing is printed inside a
//! measurement):
//!
//! ```text
//! insns_per_tick <num>/<den>
//! workload <name> <triangles> <twice the area of all> <twice the area of triangles 2..N>
//! insns <renderer> <workload> <triangles drawn> <band rows> <instructions>
//! cache <slots> <cache bytes> <band rows> <band buffer bytes> <instructions>
//! cache_listed <slots> <cache bytes> <band rows> <band buffer bytes> <instructions>
//! shape <renderer> <none|circle|gauge|gauge_round|chart|chart_cached> <instructions>
//! redraw <renderer> <full|window> <instructions> <windows> <pixels> <SPI bytes>
//! panel <band rows> <band buffer bytes> <whole|partial> <instructions>
//! image <none|copy64|rotated30|icon48> <instructions> <image pixels>
//! image_lent <none|copy64|rotated30|icon48> <instructions> <image pixels>
//! dial_ram <slots> <slot bytes> <band buffer bytes> <DMA band bytes> <the frame's stack bytes> <instructions>
//! dial_rows <band rows> <band buffer bytes> <DMA band bytes> <the frame's stack bytes> <instructions>
//! stack_bytes <n>
//! done
//! ```
//!
//! `shape` and `redraw` lines are the frames of
//! `softedge_workloads::render::ui` (a circle, an arc gauge with butt and
//! with round caps, a dial scene
//! whole or in a dirty rectangle; `aa_rgb` is softedge, `aa_rgb_lent`
//! softedge with the band buffer lent (`Renderer::render_lent`, as
//! `image_lent` for the images), `eg_fill` and
//! `eg_stock_fb` embedded-graphics); a `redraw` line's windows, pixels and
//! bytes are what an SPI display is sent (`targets::SpiCounter`).
//!
//! `<workload>` is `empty` for the frame without triangles; a frame of
//! embedded-graphics is one 240-row "band" (its framebuffer). A frame that
//! fails prints `error <renderer> <workload> ...` and the run ends with
//! exit status 1; a panic prints its location and also exits 1 (the panic
//! handler of `softedge-board-common`).
//!
//! `-append "<renderer> <workload> [rows]"` on QEMU's command line runs
//! only that frame, with all the workload's triangles (see [`cmdline`]):
//! what `boards/profile-m0.sh` profiles.
#![no_std]
#![no_main]

mod cmdline;
mod panel;

use core::hint::black_box;

use cortex_m_rt::{entry, exception};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use embedded_graphics::prelude::*;
use softedge::canvas::{ListedTriangle, ShapeEntry, WalkSlot};
use softedge::path::Segment;
use softedge::BandBuffer;
use softedge_board_common::{self as fw, insns::Counter, Line};
use softedge_workloads::render::eg_side;
use softedge_workloads::render::images;
use softedge_workloads::render::softedge_side::{
    self, Buffers, ACC_LEN, COVER_LEN, LIST_LEN, OUT_LEN, SLOTS,
};
use softedge_workloads::render::targets::{Framebuffer, SpiCounter, FB_LEN};
use softedge_workloads::render::ui;
use softedge_workloads::{
    Tri, Workload, CLASSES, COUNT, SCREEN, SLANTED, WELL_CLASSES, WELL_MEDIUM,
};

/// Band heights of the screen sweep (16 is also every other run's).
const SCREEN_BANDS: [u16; 7] = [16, 8, 6, 4, 3, 2, 1];
/// Walk-cache sizes (slots) of the cache sweep.
const CACHE_SLOTS: [usize; 6] = [0, 16, 32, 64, 128, SLOTS];
/// Band height of the workload runs.
const BAND_ROWS: u16 = 16;
/// What embedded-graphics' framebuffer is reported as: one band of the
/// whole frame.
const FRAME_ROWS: u16 = softedge_workloads::FRAME;

// cortex-m-rt passes each `static mut` of `main` as an argument.
#[allow(clippy::too_many_arguments)]
#[entry]
fn main() -> ! {
    // cortex-m-rt turns these into `&'static mut`, safely (entry runs once).
    static mut ACC: [i32; ACC_LEN] = [0; ACC_LEN];
    static mut COVER: [i32; COVER_LEN] = [0; COVER_LEN];
    static mut OUT16: [u16; OUT_LEN] = [0; OUT_LEN];
    static mut OUT8: [u8; OUT_LEN] = [0; OUT_LEN];
    static mut SLOTS3: [WalkSlot<3>; SLOTS] = [WalkSlot::EMPTY; SLOTS];
    static mut SLOTS1: [WalkSlot<1>; SLOTS] = [WalkSlot::EMPTY; SLOTS];
    static mut LIST3: [ListedTriangle<3>; LIST_LEN] = [ListedTriangle::EMPTY; LIST_LEN];
    static mut FB: [u16; FB_LEN] = [0; FB_LEN];
    static mut PANEL_ACC: [i32; panel::ACC_LEN] = [0; panel::ACC_LEN];
    static mut PANEL_COVER: [i32; panel::COVER_LEN] = [0; panel::COVER_LEN];
    static mut PANEL_OUT: [u16; panel::OUT_LEN] = [0; panel::OUT_LEN];
    static mut PANEL_SLOTS: [WalkSlot<3>; panel::SLOTS] = [WalkSlot::EMPTY; panel::SLOTS];
    static mut PANEL_SEGMENTS: [Segment; panel::CACHE_SEGMENTS] =
        [Segment::ZERO; panel::CACHE_SEGMENTS];
    static mut PANEL_ENTRIES: [ShapeEntry; panel::CACHE_ENTRIES] =
        [ShapeEntry::EMPTY; panel::CACHE_ENTRIES];
    static mut STOCK: eg_side::StockFramebuffer = eg_side::StockFramebuffer::new();
    static mut SCENE_CACHE: ui::SceneCache = ui::SceneCache::new();
    fw::stack::paint();
    let Some(core) = cortex_m::Peripherals::take() else {
        fw::exit(false)
    };
    let counter = Counter::start(core.SYST);
    let (num, den) = counter.insns_per_tick();
    Line::new()
        .text("insns_per_tick ")
        .dec(num)
        .text("/")
        .dec(den)
        .print();
    for w in
        CLASSES
            .iter()
            .chain(WELL_CLASSES.iter())
            .copied()
            .chain([&SCREEN, &SLANTED, &WELL_SCREEN])
    {
        Line::new()
            .text("workload ")
            .text(w.name)
            .text(" ")
            .dec(w.tris.len() as u64)
            .text(" ")
            .dec(w.twice_area())
            .text(" ")
            .dec(w.twice_marginal_area())
            .print();
    }

    let mut bench = Bench {
        counter: &counter,
        selection: cmdline::Selection::read(),
        ran: 0,
        ok: true,
    };
    let scene_cache: &mut ui::SceneCache = SCENE_CACHE;
    let mut bufs = Buffers {
        acc: ACC,
        cover: COVER,
        out16: OUT16,
        out8: OUT8,
        slots3: SLOTS3,
        slots1: SLOTS1,
        list3: LIST3,
    };
    for r in softedge_side::Renderer::ALL {
        let mut run = |w: &Workload, tris: &[Tri], rows: u16| {
            bench.run(r.name(), w, tris.len(), rows, || {
                softedge_side::frame(r, tris, rows, &mut bufs).is_ok()
            });
        };
        if r == softedge_side::Renderer::AaFlatRgbNoCache {
            // Only the fixed cost and the screen by band height: what the
            // walk cache saves.
            run(&EMPTY, &[], BAND_ROWS);
            for rows in SCREEN_BANDS {
                run(&SCREEN, SCREEN.tris, rows);
            }
            continue;
        }
        run(&EMPTY, &[], BAND_ROWS);
        for w in CLASSES {
            run(w, w.prefix(1), BAND_ROWS);
            run(w, w.prefix(COUNT), BAND_ROWS);
        }
        for rows in SCREEN_BANDS {
            run(&SCREEN, SCREEN.tris, rows);
        }
        if matches!(
            r,
            softedge_side::Renderer::AaFlatRgb | softedge_side::Renderer::AaFlatRgbListed
        ) {
            // The screen without vertical edges, in 16- and 3-row bands.
            for rows in [BAND_ROWS, 3] {
                run(&SLANTED, SLANTED.tris, rows);
            }
            // Well-shaped triangles (issue 32), and 132 of the medium
            // ones in 16- and 3-row bands.
            for w in WELL_CLASSES {
                run(w, w.prefix(1), BAND_ROWS);
                run(w, w.prefix(COUNT), BAND_ROWS);
            }
            for rows in [BAND_ROWS, 3] {
                run(&WELL_SCREEN, WELL_SCREEN.tris, rows);
            }
        }
    }

    // The walk cache's RAM against its time (issue 14): the screen, AA
    // flat RGB, drawn directly and from a triangle list, by the number of
    // cache slots, in 16- and 3-row bands.
    for (listed, name, tag) in [
        (false, "aa_rgb_cache", "cache "),
        (true, "aa_rgb_listed_cache", "cache_listed "),
    ] {
        for slots in CACHE_SLOTS {
            for rows in [BAND_ROWS, 3] {
                let all = SCREEN.tris.len();
                let frame = || {
                    softedge_side::frame_with_cache(SCREEN.tris, rows, slots, listed, &mut bufs)
                        .is_ok()
                };
                if let Some((insns, ok)) = bench.measure(name, "screen", all, all, rows, frame) {
                    Bench::tag(ok, tag)
                        .dec(slots as u64)
                        .text(" ")
                        .dec((slots * WalkSlot::<3>::SIZE) as u64)
                        .text(" ")
                        .dec(u64::from(rows))
                        .text(" ")
                        .dec(band_bytes(rows))
                        .text(" ")
                        .dec(insns)
                        .print();
                }
            }
        }
    }

    let mut targets = eg_side::Targets {
        fb: Framebuffer::new(FB),
        stock: STOCK,
    };
    for r in eg_side::Renderer::ALL {
        let mut run = |w: &Workload, tris: &[Tri]| {
            bench.run(r.name(), w, tris.len(), FRAME_ROWS, || {
                eg_side::frame(r, tris, &mut targets);
                true
            });
        };
        run(&EMPTY, &[]);
        for w in CLASSES {
            run(w, w.prefix(1));
            run(w, w.prefix(COUNT));
        }
        run(&SCREEN, SCREEN.tris);
        if r.name() == "eg_fill" {
            for w in WELL_CLASSES {
                run(w, w.prefix(1));
                run(w, w.prefix(COUNT));
            }
            run(&WELL_SCREEN, WELL_SCREEN.tris);
        }
    }

    // Shapes (issue 16): each alone on the frame, and the frame without
    // it, by softedge (16-row bands) and by embedded-graphics (both
    // framebuffers).
    for shape in ui::Shape::ALL {
        bench.shape("aa_rgb", shape, ui::BAND_ROWS, || {
            ui::softedge_shape(shape, &mut bufs).is_ok()
        });
        // The same frame with the one-band buffer lent for the band's
        // pixels to be made in (`Renderer::render_lent`).
        bench.shape("aa_rgb_lent", shape, ui::BAND_ROWS, || {
            ui::softedge_shape_lent(shape, &mut bufs).is_ok()
        });
        bench.shape("eg_fill", shape, FRAME_ROWS, || {
            ui::eg_shape(shape, &mut targets.fb);
            black_box(targets.fb.pixels());
            true
        });
        bench.shape("eg_stock_fb", shape, FRAME_ROWS, || {
            ui::eg_shape(shape, &mut *targets.stock);
            black_box(targets.stock.data());
            true
        });
    }

    // Images (issue 35): each alone on the frame, and the frame without
    // it, softedge in 16-row bands.
    for image in images::Image::ALL {
        bench.image("image", image, || {
            images::softedge_image(image, &mut bufs).is_ok()
        });
        bench.image("image_lent", image, || {
            images::softedge_image_lent(image, &mut bufs).is_ok()
        });
    }

    // The RP2040 firmware's panel (issue 14: its band height): a whole
    // frame and the mean partial redraw by band height.
    let mut pb = panel::PanelBuffers {
        acc: PANEL_ACC,
        cover: PANEL_COVER,
        out: PANEL_OUT,
        slots: PANEL_SLOTS,
        segments: PANEL_SEGMENTS,
        entries: PANEL_ENTRIES,
        cached: false,
    };
    // Then the same with a shape cache (`Renderer::with_shape_cache`),
    // after one unmeasured whole frame has filled it: a later frame.
    for (cached, whole, partial) in [
        (false, "whole", "partial"),
        (true, "whole_cached", "partial_cached"),
    ] {
        pb.cached = cached;
        for rows in panel::ROWS {
            let p0 = panel::Panel::at(0);
            pb.forget_shapes();
            if cached {
                panel::frame(&p0, None, rows, &mut pb);
            }
            if let Some((insns, ok)) = bench.measure("panel", whole, 0, 0, rows, || {
                panel::frame(&p0, None, rows, &mut pb)
            }) {
                bench.panel_line(ok, rows, whole, insns);
            }
            let mut total = 0u64;
            let mut all_ok = true;
            let mut ran = false;
            for f in 1..=panel::PARTIAL_FRAMES {
                let (before, now) = (panel::Panel::at(f - 1), panel::Panel::at(f));
                if let Some((insns, ok)) = bench.measure("panel", partial, 0, 0, rows, || {
                    panel::frame(&now, Some(&before), rows, &mut pb)
                }) {
                    total += insns;
                    all_ok &= ok;
                    ran = true;
                }
            }
            if ran {
                bench.panel_line(
                    all_ok,
                    rows,
                    partial,
                    total / u64::from(panel::PARTIAL_FRAMES),
                );
            }
        }
    }
    pb.forget_shapes();
    pb.cached = true;
    panel::frame(&panel::Panel::at(0), None, 16, &mut pb);
    let (entries, segments, direct) = pb.shape_cache_used();
    Line::new()
        .text("panel_shape_cache ")
        .dec(entries as u64)
        .text(" ")
        .dec(segments as u64)
        .text(" ")
        .dec(direct as u64)
        .print();
    if direct > 0 {
        bench.ok = false;
        Line::new()
            .text("error the panel's shapes do not fit the shape cache")
            .print();
    }

    // Partial redraw (issue 15): the dial scene whole and in the dirty
    // rectangle. softedge is measured into the one-band DMA buffer and
    // rendered once more, unmeasured, into a counter of what an SPI
    // display is sent; embedded-graphics redraws its framebuffer, which is
    // then sent as one window of the redrawn rectangle.
    let side = u32::from(FRAME_ROWS);
    for (what, window) in [("full", None), ("window", Some(ui::DIRTY))] {
        let mut spi = SpiCounter::new(side, side);
        let counted = ui::softedge_scene(window, &mut bufs, &mut spi)
            .ok()
            .map(|()| spi);
        bench.redraw(
            "aa_rgb",
            what,
            ui::BAND_ROWS,
            || ui::softedge_scene_stream(window, &mut bufs).is_ok(),
            counted,
        );
        // The same with the one-band buffer lent (`Renderer::render_lent`,
        // `render_window_lent`): the same windows and pixels sent (one a
        // band over the band's rectangle, as `fill_contiguous` has them).
        let mut spi = SpiCounter::new(side, side);
        let counted = ui::softedge_scene(window, &mut bufs, &mut spi)
            .ok()
            .map(|()| spi);
        bench.redraw(
            "aa_rgb_lent",
            what,
            ui::BAND_ROWS,
            || ui::softedge_scene_lent(window, &mut bufs).is_ok(),
            counted,
        );
        // The scene through a renderer with a shape cache
        // (`ui::softedge_scene_cached`): its first frame describes the
        // shapes into the empty cache, the later ones fill them from it
        // (measured after one unmeasured full frame).
        for first in [true, false] {
            // The cache as the measured frame finds it: empty, or filled
            // by one whole frame.
            let prepare = |bufs: &mut softedge_side::Buffers<'_>, cache: &mut ui::SceneCache| {
                cache.entries.fill(ShapeEntry::EMPTY);
                if !first {
                    let mut warm = SpiCounter::new(side, side);
                    let _ = ui::softedge_scene_cached(None, bufs, cache, &mut warm);
                }
            };
            prepare(&mut bufs, scene_cache);
            let mut spi = SpiCounter::new(side, side);
            let counted = ui::softedge_scene_cached(window, &mut bufs, scene_cache, &mut spi)
                .ok()
                .map(|_| spi);
            prepare(&mut bufs, scene_cache);
            bench.redraw(
                if first {
                    "aa_rgb_cache_first"
                } else {
                    "aa_rgb_cached"
                },
                what,
                ui::BAND_ROWS,
                || {
                    ui::scene_stream(&mut bufs, |b, sink| {
                        ui::softedge_scene_cached(window, b, scene_cache, sink).map(|_| ())
                    })
                    .is_ok()
                },
                counted,
            );
        }
        let mut spi = SpiCounter::new(side, side);
        let area = window.unwrap_or(spi.bounding_box());
        // The framebuffer's flush: one window, its pixels in order.
        let counted = spi.fill_solid(&area, Rgb565::BLACK).ok().map(|()| spi);
        bench.redraw(
            "eg_fill",
            what,
            FRAME_ROWS,
            || {
                ui::eg_scene(window, &mut targets.fb);
                black_box(targets.fb.pixels());
                true
            },
            counted,
        );
    }

    // The dial's RAM (issue 32): the plain path's whole frame by walk-cache
    // slots, with the deepest stack its frame reaches (the stack painted
    // again just before it; the run's own high-water mark is kept).
    let high_water = fw::stack::used_bytes();
    let mut dial_stack = 0;
    for slots in DIAL_SLOTS {
        let n = slots.min(bufs.slots3.len());
        let mut b = Buffers {
            acc: &mut *bufs.acc,
            cover: &mut *bufs.cover,
            out16: &mut *bufs.out16,
            out8: &mut *bufs.out8,
            slots3: bufs.slots3.get_mut(..n).unwrap_or_default(),
            slots1: &mut *bufs.slots1,
            list3: &mut *bufs.list3,
        };
        fw::stack::paint();
        let here = fw::stack::depth_here();
        let measured = bench.measure("dial_ram", "full", 0, 0, ui::BAND_ROWS, || {
            ui::softedge_scene_stream(None, &mut b).is_ok()
        });
        let used = fw::stack::used_bytes();
        dial_stack = dial_stack.max(used);
        // The frame's own stack, below the benchmark's frame (whose
        // buffers a firmware keeps elsewhere).
        let stack = used.saturating_sub(here);
        if let Some((insns, ok)) = measured {
            Bench::tag(ok, "dial_ram ")
                .dec(n as u64)
                .text(" ")
                .dec((n * WalkSlot::<3>::SIZE) as u64)
                .text(" ")
                .dec(band_bytes(ui::BAND_ROWS))
                .text(" ")
                .dec((usize::from(FRAME_ROWS) * usize::from(ui::BAND_ROWS) * 2) as u64)
                .text(" ")
                .dec(stack as u64)
                .text(" ")
                .dec(insns)
                .print();
        }
    }

    // The dial's RAM by band height (no walk cache): what a firmware with
    // less RAM trades for instructions.
    for rows in DIAL_ROWS {
        let mut b = Buffers {
            acc: &mut *bufs.acc,
            cover: &mut *bufs.cover,
            out16: &mut *bufs.out16,
            out8: &mut *bufs.out8,
            slots3: &mut [],
            slots1: &mut *bufs.slots1,
            list3: &mut *bufs.list3,
        };
        fw::stack::paint();
        let here = fw::stack::depth_here();
        let measured = bench.measure("dial_rows", "full", 0, 0, rows, || {
            ui::softedge_scene_rows(rows, &mut b).is_ok()
        });
        let used = fw::stack::used_bytes();
        dial_stack = dial_stack.max(used);
        let stack = used.saturating_sub(here);
        if let Some((insns, ok)) = measured {
            Bench::tag(ok, "dial_rows ")
                .dec(u64::from(rows))
                .text(" ")
                .dec(band_bytes(rows))
                .text(" ")
                .dec((usize::from(FRAME_ROWS) * usize::from(rows) * 2) as u64)
                .text(" ")
                .dec(stack as u64)
                .text(" ")
                .dec(insns)
                .print();
        }
    }

    Line::new()
        .text("stack_bytes ")
        .dec(high_water.max(dial_stack).max(fw::stack::used_bytes()) as u64)
        .print();
    let margin_ok = fw::stack::margin_bytes() >= fw::stack::MIN_MARGIN_BYTES;
    if !margin_ok {
        Line::new()
            .text("error stack too close to the statics")
            .print();
    }
    if bench.ran == 0 {
        Line::new()
            .text("error no frame matches the selection")
            .print();
    }
    let ok = bench.ok && margin_ok && bench.ran > 0;
    if ok {
        Line::new().text("done").print();
    }
    fw::exit(ok)
}

/// Bytes of an RGB band buffer (accumulator and cover scratch) of
/// `rows` rows of the frame.
fn band_bytes(rows: u16) -> u64 {
    let w = softedge_workloads::FRAME;
    let n = BandBuffer::<3>::acc_len(w, rows) + BandBuffer::<3>::cover_len(w, rows);
    (n * core::mem::size_of::<i32>()) as u64
}

/// Walk-cache slots the dial's RAM is measured with (the last: all the
/// benchmark has, as its other dial rows use).
const DIAL_SLOTS: [usize; 5] = [0, 16, 32, 64, SLOTS];
/// Band heights of the dial's `dial_rows` lines.
const DIAL_ROWS: [u16; 6] = [16, 8, 6, 5, 4, 2];

/// The first 132 of [`WELL_MEDIUM`]'s triangles (as many as the screen
/// has, of about its triangles' area, overlapping at random).
static WELL_SCREEN: Workload = Workload {
    name: "wscreen",
    tris: WELL_MEDIUM.tris.split_at(132).0,
};

/// The frame without triangles (the fixed cost), as a workload name.
static EMPTY: Workload = Workload {
    name: "empty",
    tris: &[],
};

/// Measures frames and prints their lines.
struct Bench<'a> {
    counter: &'a Counter,
    selection: cmdline::Selection,
    /// Frames measured.
    ran: usize,
    ok: bool,
}

impl Bench<'_> {
    /// Measures `frame` (which returns `false` on failure), drawing `tris`
    /// triangles of `workload`, and prints
    /// `insns <renderer> <workload> <triangles> <rows> <n>`; frames the
    /// selection leaves out are skipped.
    fn run(
        &mut self,
        renderer: &str,
        workload: &Workload,
        tris: usize,
        rows: u16,
        frame: impl FnOnce() -> bool,
    ) {
        let all = workload.tris.len();
        let Some((insns, ok)) = self.measure(renderer, workload.name, tris, all, rows, frame)
        else {
            return;
        };
        Self::tag(ok, "insns ")
            .text(renderer)
            .text(" ")
            .text(workload.name)
            .text(" ")
            .dec(tris as u64)
            .text(" ")
            .dec(u64::from(rows))
            .text(" ")
            .dec(insns)
            .print();
    }

    /// Measures a frame of one of the [`ui`] shapes and prints
    /// `shape <renderer> <shape> <n>`.
    fn shape(&mut self, renderer: &str, shape: ui::Shape, rows: u16, frame: impl FnOnce() -> bool) {
        let Some((insns, ok)) = self.measure(renderer, shape.name(), 0, 0, rows, frame) else {
            return;
        };
        Self::tag(ok, "shape ")
            .text(renderer)
            .text(" ")
            .text(shape.name())
            .text(" ")
            .dec(insns)
            .print();
    }

    /// Measures a frame of the [`ui`] scene (`what`: `full` or `window`)
    /// and prints `redraw <renderer> <what> <n> <windows> <pixels> <bytes>`
    /// with what `spi` counted the display is sent (`None`: the counting
    /// run failed, an error).
    fn redraw(
        &mut self,
        renderer: &str,
        what: &str,
        rows: u16,
        frame: impl FnOnce() -> bool,
        spi: Option<SpiCounter>,
    ) {
        let Some((insns, ok)) = self.measure(renderer, what, 0, 0, rows, frame) else {
            return;
        };
        let Some(spi) = spi else {
            self.ok = false;
            Line::new()
                .text("error ")
                .text(renderer)
                .text(" ")
                .text(what)
                .text(" spi count failed")
                .print();
            return;
        };
        Self::tag(ok, "redraw ")
            .text(renderer)
            .text(" ")
            .text(what)
            .text(" ")
            .dec(insns)
            .text(" ")
            .dec(u64::from(spi.windows))
            .text(" ")
            .dec(u64::from(spi.pixels))
            .text(" ")
            .dec(u64::from(spi.bytes()))
            .print();
    }

    /// Measures a frame of one of the [`images`] cases and prints
    /// `image <case> <n> <image pixels>`.
    /// Prints `<kind> <image> <instructions> <image pixels>` (`kind`:
    /// `image`, or `image_lent` with the band buffer lent).
    fn image(&mut self, kind: &str, image: images::Image, frame: impl FnOnce() -> bool) {
        let Some((insns, ok)) = self.measure(kind, image.name(), 0, 0, images::BAND_ROWS, frame)
        else {
            return;
        };
        Self::tag(ok, kind)
            .text(" ")
            .text(image.name())
            .text(" ")
            .dec(insns)
            .text(" ")
            .dec(u64::from(image.area()))
            .print();
    }

    /// Prints `panel <rows> <band bytes> <whole|partial> <instructions>`.
    fn panel_line(&mut self, ok: bool, rows: u16, what: &str, insns: u64) {
        Self::tag(ok, "panel ")
            .dec(u64::from(rows))
            .text(" ")
            .dec(panel::band_bytes(rows) as u64)
            .text(" ")
            .text(what)
            .text(" ")
            .dec(insns)
            .print();
    }

    /// The line's first word: `tag` for a frame that succeeded, `error `
    /// (and the run fails) for one that did not.
    fn tag(ok: bool, tag: &str) -> Line {
        Line::new().text(if ok { tag } else { "error " })
    }

    /// Runs `frame` (which returns `false` on failure) between the profile
    /// marks and returns its instructions and success, or `None` when the
    /// selection leaves it out.
    fn measure(
        &mut self,
        renderer: &str,
        workload: &str,
        tris: usize,
        all: usize,
        rows: u16,
        frame: impl FnOnce() -> bool,
    ) -> Option<(u64, bool)> {
        if !self.selection.wants(renderer, workload, tris, all, rows) {
            return None;
        }
        self.ran += 1;
        let mut frame_ok = false;
        let ticks = self.counter.measure(|| {
            bench_profile_on();
            frame_ok = frame();
            bench_profile_off();
        });
        self.ok &= frame_ok;
        Some((self.counter.insns(ticks), frame_ok))
    }
}

/// What the profile marks write: a volatile store cannot be optimised
/// away (an empty function's call would be), and the two values keep LLVM
/// from merging the two functions into one address.
static mut PROFILE_MARK: u32 = 0;

/// Entered right before a measured frame: `boards/profile-m0.sh` has the
/// insn-profile plugin count only from the entry of this function to the
/// entry of [`bench_profile_off`] (about 10 instructions per frame).
#[no_mangle]
#[inline(never)]
pub extern "C" fn bench_profile_on() {
    // SAFETY: a plain word only these two functions write (single core).
    unsafe { core::ptr::addr_of_mut!(PROFILE_MARK).write_volatile(1) }
}

/// Entered right after a measured frame (see [`bench_profile_on`]).
#[no_mangle]
#[inline(never)]
pub extern "C" fn bench_profile_off() {
    // SAFETY: as in `bench_profile_on`.
    unsafe { core::ptr::addr_of_mut!(PROFILE_MARK).write_volatile(2) }
}

#[exception]
fn SysTick() {
    fw::insns::on_wrap();
}
