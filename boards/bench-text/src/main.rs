//! The Cortex-M0 text benchmark: instructions per glyph of
//! `softedge::text` (the bundled font) drawn through the frame loop into a
//! 320x240 Rgb565 frame in 16-row bands, counted by SysTick under
//! `qemu-system-arm -machine mps2-an385 -icount shift=0` (thumbv6m code on
//! the board's Cortex-M3). `bash boards/bench-text.sh` builds it with and
//! without the `text` feature, runs it and prints the table and the flash
//! sizes.
//!
//! Issue #33's label: `LABEL` (55 glyphs in four lines) in a 16-px font,
//! white on black, on a 240x240 Rgb565 frame in 16-row bands, drawn with
//! embedded-graphics' `Text` and softedge's `AaTextStyle`: `label_empty`
//! (the frame without it), `label_prerasterized` (the bundled font
//! rasterized ahead of time, `softedge::text::bundled::SANS_16`),
//! `label_outline_first` / `label_outline_cached` (the bundled outline
//! font at 16 px through a `GlyphCache`: the first frame, every glyph
//! rasterized, and the next one, every glyph found), `label_outline` (the
//! outline font without a cache, `softedge::text::Text`). The marginal
//! cost is the frame less `label_empty`.
//!
//! Output:
//!
//! ```text
//! insns_per_tick <num>/<den>
//! insns <frame> <glyphs> <instructions>
//! font_bytes <size of a Font>
//! font_flash <name> <glyphs> <bytes>    a RasterFont's tables and masks
//! cache <code bytes used> <glyphs kept> <RAM of the cache's slices>
//! stack_bytes <n>
//! done
//! ```
//!
//! Frames: `empty` (the frame loop, a disc and no text: the fixed cost),
//! `text12` / `text24` (the same plus four lines at 12 / 24 px), each also
//! as `*_1band` (the whole frame one band of 240 rows: no line described
//! twice) and `*_tol16` (16-row bands, curves flattened within 16 fine
//! units, 1/64 px, instead of 3), `parse`
//! (opening the font: `Font::new`), `measure12` / `measure24` (laying the
//! same lines out without drawing). Per glyph: `(text - empty) / glyphs`,
//! every character but the line breaks counted (spaces too).
#![no_std]
#![no_main]

use cortex_m_rt::{entry, exception};
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::Rgb565;
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;
use softedge::canvas::{Canvas, WalkSlot};
use softedge::geom::FinePoint;
use softedge::path::Circle;
use softedge::render::Renderer;
use softedge::style::{Blend, FillRule, Opacity};
use softedge::tone::format::Rgb565Format;
use softedge::tone::Curve;
use softedge::{BandBuffer, DrawError};
use softedge_board_common::{self as fw, insns::Counter, Line};

#[cfg(feature = "text")]
mod fonts;

const W: u16 = 320;
const H: u16 = 240;
const ROWS: u16 = 16;
const ACC_LEN: usize = BandBuffer::<3>::acc_len(W, ROWS);
const COVER_LEN: usize = BandBuffer::<3>::cover_len(W, ROWS);
const SLOTS: usize = 64;
/// The whole frame as one band: the cost without describing a line again
/// in each band it touches.
const ACC_ONE: usize = BandBuffer::<3>::acc_len(W, H);
const COVER_ONE: usize = BandBuffer::<3>::cover_len(W, H);

static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);

/// Issue #33's label frame: 240x240, 16-row bands.
const LW: u16 = 240;
const LH: u16 = 240;
const LACC_LEN: usize = BandBuffer::<3>::acc_len(LW, ROWS);
const LCOVER_LEN: usize = BandBuffer::<3>::cover_len(LW, ROWS);
/// The label (LVGL 9.5 draws it in Montserrat 16 for 0.554 M).
#[cfg(feature = "text")]
const LABEL: &str = "The quick brown\nfox: 0123 °C\nSphinx of black\nquartz 3.71 V";
/// The glyph cache's slices: code bytes, slots, rasterizer cells.
#[cfg(feature = "text")]
const CACHE_CODES: usize = 2048;
#[cfg(feature = "text")]
const CACHE_SLOTS: usize = 64;
#[cfg(feature = "text")]
const CACHE_CELLS: usize = 512;

/// A display that takes the colours and keeps a checksum (so nothing is
/// optimised away); its cost is the same in every frame.
struct Sink(u32);

impl OriginDimensions for Sink {
    fn size(&self) -> Size {
        Size::new(u32::from(W), u32::from(H))
    }
}

impl DrawTarget for Sink {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(_, c) in px {
            self.0 = self.0.wrapping_add(u32::from(
                embedded_graphics_core::pixelcolor::IntoStorage::into_storage(c),
            ));
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        // As e-g's contract says: the area's pixels and no more (its
        // `fill_solid` passes an endless `repeat`).
        let n = area.size.width as usize * area.size.height as usize;
        for c in colors.into_iter().take(n) {
            self.0 = self.0.wrapping_add(u32::from(
                embedded_graphics_core::pixelcolor::IntoStorage::into_storage(c),
            ));
        }
        Ok(())
    }
}

/// A DMA display for the label ([`softedge::render::BandTarget`]): it
/// lends a 16-row band buffer and hands each band on (a real driver starts
/// the DMA of it; here nothing is done but keeping it).
struct Lender {
    band: &'static mut [u16],
}

impl OriginDimensions for Lender {
    fn size(&self) -> Size {
        Size::new(u32::from(LW), u32::from(LH))
    }
}

impl softedge::render::BandTarget for Lender {
    type Color = Rgb565;
    type Raw = u16;
    type Error = core::convert::Infallible;
    fn buffer(&mut self) -> &mut [u16] {
        self.band
    }
    fn send(&mut self, _area: &Rectangle) -> Result<(), Self::Error> {
        core::hint::black_box(&self.band);
        Ok(())
    }
}

/// The lines drawn at 12 px (and their first halves at 24 px).
#[cfg(feature = "text")]
const LINES_12: &str = "The quick brown fox jumps over\nthe lazy dog. 0123456789 °C ±µ\nSphinx of black quartz, judge\nmy vow! AVAWAY Ty To 3.71 V";
#[cfg(feature = "text")]
const LINES_24: &str = "The quick brown\nfox: 0123 °C\nSphinx of black\nquartz 3.71 V";

/// Characters drawn (line breaks left out).
#[cfg(feature = "text")]
fn glyphs(s: &str) -> u64 {
    s.chars().filter(|&c| c != '\n').count() as u64
}

// cortex-m-rt passes each `static mut` below to `main` as an argument.
#[allow(clippy::too_many_arguments)]
#[entry]
fn main() -> ! {
    static mut ACC: [i32; ACC_LEN] = [0; ACC_LEN];
    static mut COVER: [i32; COVER_LEN] = [0; COVER_LEN];
    static mut SLOT: [WalkSlot<3>; SLOTS] = [WalkSlot::EMPTY; SLOTS];
    static mut ACC1: [i32; ACC_ONE] = [0; ACC_ONE];
    static mut COVER1: [i32; COVER_ONE] = [0; COVER_ONE];
    static mut LACC: [i32; LACC_LEN] = [0; LACC_LEN];
    static mut LCOVER: [i32; LCOVER_LEN] = [0; LCOVER_LEN];
    static mut LBAND: [u16; LW as usize * ROWS as usize] = [0; LW as usize * ROWS as usize];
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
    let mut ok = true;
    #[cfg_attr(not(feature = "text"), allow(unused_mut))]
    let mut measured_ok = true;
    let Ok(mut banded) = Renderer::new(ACC, COVER, SLOT, W, H, ROWS) else {
        fw::exit(false)
    };
    let Ok(mut whole) = Renderer::new(ACC1, COVER1, &mut [], W, H, H) else {
        fw::exit(false)
    };
    let mut sink = Sink(0);
    let disc = Circle::new(FinePoint::new(280 * 1024, 200 * 1024), 30 * 1024);
    let mut frame =
        |name: &str,
         one_band: bool,
         glyphs: u64,
         draw: &mut dyn FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>| {
            let mut good = false;
            let r = if one_band { &mut whole } else { &mut banded };
            let ticks = counter.measure(|| {
                good = r
                    .render(&mut sink, &RGB565, [0, 0, 0], |c| {
                        c.fill_shape(
                            &disc,
                            [4095, 2000, 0],
                            FillRule::NonZero,
                            Blend::Over,
                            Opacity::OPAQUE,
                        )?;
                        draw(c)
                    })
                    .is_ok();
            });
            ok &= good;
            Line::new()
                .text(if good { "insns " } else { "error " })
                .text(name)
                .text(if one_band { "_1band" } else { "" })
                .text(" ")
                .dec(glyphs)
                .text(" ")
                .dec(counter.insns(ticks))
                .print();
        };
    frame("empty", false, 0, &mut |_| Ok(()));
    frame("empty", true, 0, &mut |_| Ok(()));
    #[cfg(feature = "text")]
    {
        use softedge::text::{Baseline, Font, FontStyle, Text};
        let mut font = None;
        let ticks = counter.measure(|| font = Font::bundled().ok());
        let Some(font) = font else { fw::exit(false) };
        Line::new()
            .text("insns parse 0 ")
            .dec(counter.insns(ticks))
            .print();
        Line::new()
            .text("font_bytes ")
            .dec(core::mem::size_of::<Font<'static>>() as u64)
            .print();
        for (size, lines, name, mname) in [
            (12u16, LINES_12, "text12", "measure12"),
            (24, LINES_24, "text24", "measure24"),
        ] {
            let style = FontStyle::<3>::new(&font, size, [4095, 4095, 4095]);
            let text = Text::with_baseline(
                lines,
                FinePoint::new(4 * 1024 + 300, 8 * 1024),
                style,
                Baseline::Top,
            );
            frame(name, false, glyphs(lines), &mut |c| {
                text.draw(c).map(|_| ())
            });
            frame(name, true, glyphs(lines), &mut |c| text.draw(c).map(|_| ()));
            // Curves flattened within 1/64 px instead of 1/341 px.
            let coarse = Text {
                style: style.with_tolerance(softedge::path::Tolerance::new(16)),
                ..text
            };
            let tname = if size == 12 {
                "text12_tol16"
            } else {
                "text24_tol16"
            };
            frame(tname, false, glyphs(lines), &mut |c| {
                coarse.draw(c).map(|_| ())
            });
            let mut w = 0;
            let ticks = counter.measure(|| w = text.measure().width);
            measured_ok &= w > 0;
            Line::new()
                .text("insns ")
                .text(mname)
                .text(" ")
                .dec(glyphs(lines))
                .text(" ")
                .dec(counter.insns(ticks))
                .print();
        }
    }
    // Issue #33's label on a 240x240 frame.
    #[cfg_attr(not(feature = "text"), allow(unused_mut))]
    let mut cache_ok = true;
    let Ok(mut label_renderer) = Renderer::new(LACC, LCOVER, &mut [], LW, LH, ROWS) else {
        fw::exit(false)
    };
    let mut lender = Lender { band: LBAND };
    // `lent`: into the lender's band buffer (`Renderer::render_lent`),
    // else streamed to the checksum display.
    let mut label_frame =
        |name: &str,
         glyphs: u64,
         lent: bool,
         draw: &mut dyn FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>| {
            let mut good = false;
            let ticks = counter.measure(|| {
                good = if lent {
                    label_renderer
                        .render_lent(&mut lender, &RGB565, [0, 0, 0], |c| draw(c))
                        .is_ok()
                } else {
                    label_renderer
                        .render(&mut sink, &RGB565, [0, 0, 0], |c| draw(c))
                        .is_ok()
                };
            });
            ok &= good;
            Line::new()
                .text(if good { "insns " } else { "error " })
                .text(name)
                .text(" ")
                .dec(glyphs)
                .text(" ")
                .dec(counter.insns(ticks))
                .print();
        };
    // Twice: the first frame of a renderer clears its band buffer (about
    // 85 k more); the second is the steady state every later frame has.
    label_frame("label_empty_first", 0, false, &mut |_| Ok(()));
    label_frame("label_empty", 0, false, &mut |_| Ok(()));
    label_frame("label_empty_lent", 0, true, &mut |_| Ok(()));
    #[cfg(feature = "text")]
    {
        use embedded_graphics::prelude::*;
        use embedded_graphics::text::{Baseline, Text as EgText};
        use softedge::text::DrawAaText;
        use softedge::text::{
            bundled, AaTextStyle, CachedFont, Font, GlyphCache, TextSize, SLOT_WORDS,
        };
        static mut CODES: [u8; CACHE_CODES] = [0; CACHE_CODES];
        static mut SLOTS: [u32; CACHE_SLOTS * SLOT_WORDS] = [0; CACHE_SLOTS * SLOT_WORDS];
        static mut CELLS: [i32; CACHE_CELLS] = [0; CACHE_CELLS];
        let n = glyphs(LABEL);
        let at = Point::new(8, 8);
        let white = Rgb565::new(31, 63, 31);
        let raster = AaTextStyle::new(&bundled::SANS_16, white);
        // The frame `bash boards/profile-text.sh` profiles.
        bench_profile_on();
        label_frame("label_prerasterized", n, false, &mut |c| {
            EgText::with_baseline(LABEL, at, raster, Baseline::Top)
                .draw(c)
                .map(|_| ())
        });
        bench_profile_off();
        label_frame("label_prerasterized_lent", n, true, &mut |c| {
            EgText::with_baseline(LABEL, at, raster, Baseline::Top)
                .draw(c)
                .map(|_| ())
        });
        let Ok(font) = Font::bundled() else {
            fw::exit(false)
        };
        // SAFETY: the cache's statics are borrowed once, here, for the
        // rest of `main` (single core, no interrupt touches them).
        let (codes, slots, cells) = unsafe {
            (
                &mut *core::ptr::addr_of_mut!(CODES),
                &mut *core::ptr::addr_of_mut!(SLOTS),
                &mut *core::ptr::addr_of_mut!(CELLS),
            )
        };
        let cache = GlyphCache::new(codes, slots, cells);
        let outline = AaTextStyle::new(CachedFont::new(&font, TextSize::px(16), &cache), white);
        for name in ["label_outline_first", "label_outline_cached"] {
            label_frame(name, n, false, &mut |c| {
                EgText::with_baseline(LABEL, at, outline, Baseline::Top)
                    .draw(c)
                    .map(|_| ())
            });
        }
        cache_ok &= cache.stats().uncached == 0;
        Line::new()
            .text("cache ")
            .dec(cache.used_bytes() as u64)
            .text(" ")
            .dec(cache.glyphs() as u64)
            .text(" ")
            .dec(
                (CACHE_CODES
                    + CACHE_SLOTS * SLOT_WORDS * 4
                    + core::mem::size_of::<GlyphCache<'static>>()
                    + CACHE_CELLS * 4) as u64,
            )
            .print();
        let style = softedge::text::FontStyle::<3>::new(&font, 16, [4095, 4095, 4095]);
        let direct = softedge::text::Text::with_baseline(
            LABEL,
            FinePoint::from_px(8, 8),
            style,
            softedge::text::Baseline::Top,
        );
        label_frame("label_outline", n, false, &mut |c| {
            direct.draw(c).map(|_| ())
        });
        for (name, f) in [
            ("sans16", &bundled::SANS_16),
            ("latin1", &fonts::latin1::SANS_16_LATIN1),
        ] {
            Line::new()
                .text("font_flash ")
                .text(name)
                .text(" ")
                .dec(f.glyph_count() as u64)
                .text(" ")
                .dec(f.flash_bytes() as u64)
                .print();
        }
    }
    ok &= measured_ok && cache_ok;
    Line::new().text("checksum ").hex8(sink.0).print();
    Line::new()
        .text("stack_bytes ")
        .dec(fw::stack::used_bytes() as u64)
        .print();
    ok &= fw::stack::margin_bytes() >= fw::stack::MIN_MARGIN_BYTES;
    if ok {
        Line::new().text("done").print();
    }
    fw::exit(ok)
}

/// What the profile marks write (see boards/bench-m0: a volatile store
/// keeps the two functions apart and present).
static mut PROFILE_MARK: u32 = 0;

/// Entered right before issue #33's label frame (rasterized ahead):
/// `bash boards/profile-text.sh` counts instructions by function from here
/// to [`bench_profile_off`] (with boards/tools/insn-profile.c).
#[no_mangle]
#[inline(never)]
pub extern "C" fn bench_profile_on() {
    // SAFETY: a plain word only these two functions write (single core).
    unsafe { core::ptr::addr_of_mut!(PROFILE_MARK).write_volatile(1) }
}

/// Entered right after the label frame.
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
