//! The Cortex-M0 benchmark's workloads on x86-64 (`bench workloads`).
//!
//! The same triangles (`softedge-workloads`) and the same frames
//! (`softedge_workloads::render`, the code the firmware `boards/bench-m0`
//! runs) measured with callgrind, beside tiny-skia's `fill_path` of the same
//! triangles, anti-aliased and aliased, into a 240x240 `Pixmap`. Each
//! frame is one run of this binary under valgrind, collecting only inside
//! [`workload_frame`] (buffers, and tiny-skia's paths, are made before it),
//! and the table gives per renderer the fixed cost of a frame (N = 0), the
//! marginal instructions per pixel of triangle area of each size class,
//! `(insns(N = 2000) - insns(N = 1)) / (area of triangles 2..2000)`, and the
//! 132-triangle screen, then the screen by band height.

use softedge_workloads::render::eg_side::{self, StockFramebuffer, Targets};
use softedge_workloads::render::softedge_side::{
    self, Buffers, ACC_LEN, COVER_LEN, LIST_LEN, OUT_LEN, SLOTS,
};
use softedge_workloads::render::targets::{Framebuffer, FB_LEN};
use softedge_workloads::{Tri, Workload, CLASSES, COUNT, SCREEN, WELL_CLASSES};

/// Band heights of the screen sweep.
const SCREEN_BANDS: [u16; 7] = [16, 8, 6, 4, 3, 2, 1];
/// Band height of the other runs.
const BAND_ROWS: u16 = 16;

/// The renderers of the table, by the names the firmware prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Renderer {
    Softedge(softedge_side::Renderer),
    Eg(eg_side::Renderer),
    /// tiny-skia `fill_path`, `anti_alias` on or off.
    TinySkia(bool),
}

fn renderers() -> Vec<Renderer> {
    let mut all: Vec<Renderer> = softedge_side::Renderer::ALL
        .into_iter()
        .map(Renderer::Softedge)
        .collect();
    all.extend(eg_side::Renderer::ALL.into_iter().map(Renderer::Eg));
    all.extend([Renderer::TinySkia(true), Renderer::TinySkia(false)]);
    all
}

impl Renderer {
    fn name(self) -> &'static str {
        match self {
            Renderer::Softedge(r) => r.name(),
            Renderer::Eg(r) => r.name(),
            Renderer::TinySkia(true) => "ts_aa",
            Renderer::TinySkia(false) => "ts_aliased",
        }
    }

    fn label(self) -> &'static str {
        match self.name() {
            "aa_rgb" => "softedge AA flat RGB, Rgb565",
            "aa_gouraud" => "softedge AA Gouraud RGB, Rgb565",
            "aa_gray" => "softedge AA gray, Gray8",
            "aliased_rgb" => "softedge aliased flat RGB, Rgb565",
            "aa_rgb_nocache" => "softedge AA flat RGB, Rgb565, no walk cache",
            "aa_rgb_listed" => "softedge AA flat RGB, Rgb565, `TriangleList` recorded in the frame",
            "eg_fill" => "e-g `Triangle` fill, framebuffer with slice `fill_solid`",
            "eg_stock_fb" => "e-g `Triangle` fill, e-g `Framebuffer` (`draw_iter`)",
            "ts_aa" => "tiny-skia `fill_path`, anti-aliased, RGBA8888 `Pixmap`",
            "ts_aliased" => "tiny-skia `fill_path`, aliased, RGBA8888 `Pixmap`",
            other => other,
        }
    }

    fn from_name(name: &str) -> Option<Renderer> {
        renderers().into_iter().find(|r| r.name() == name)
    }
}

/// Everything a frame needs, made before the measured function.
struct Job {
    renderer: Renderer,
    tris: &'static [Tri],
    rows: u16,
    acc: Vec<i32>,
    cover: Vec<i32>,
    out16: Vec<u16>,
    out8: Vec<u8>,
    slots3: Vec<softedge::canvas::WalkSlot<3>>,
    slots1: Vec<softedge::canvas::WalkSlot<1>>,
    list3: Vec<softedge::canvas::ListedTriangle<3>>,
    fb: Box<[u16; FB_LEN]>,
    stock: Box<StockFramebuffer>,
    pixmap: tiny_skia::Pixmap,
    paths: Vec<(tiny_skia::Path, tiny_skia::Paint<'static>)>,
}

fn workload(name: &str) -> Option<&'static Workload> {
    CLASSES
        .iter()
        .chain(WELL_CLASSES.iter())
        .copied()
        .chain([&SCREEN])
        .find(|w| w.name == name)
}

impl Job {
    fn new(renderer: Renderer, tris: &'static [Tri], rows: u16) -> Option<Self> {
        let paths = match renderer {
            Renderer::TinySkia(aa) => tris
                .iter()
                .map(|t| tiny_skia_triangle(t, aa))
                .collect::<Option<Vec<_>>>()?,
            _ => Vec::new(),
        };
        Some(Self {
            renderer,
            tris,
            rows,
            acc: vec![0; ACC_LEN],
            cover: vec![0; COVER_LEN],
            out16: vec![0; OUT_LEN],
            out8: vec![0; OUT_LEN],
            slots3: vec![softedge::canvas::WalkSlot::EMPTY; SLOTS],
            slots1: vec![softedge::canvas::WalkSlot::EMPTY; SLOTS],
            list3: vec![softedge::canvas::ListedTriangle::EMPTY; LIST_LEN],
            fb: Box::new([0; FB_LEN]),
            stock: Box::new(StockFramebuffer::new()),
            pixmap: tiny_skia::Pixmap::new(240, 240)?,
            paths,
        })
    }
}

/// tiny-skia's path and paint of a triangle: whole-pixel vertices are pixel
/// corners there too; the flat colour's top 8 bits (tiny-skia blends in
/// its own colour space, no γ stage).
fn tiny_skia_triangle(t: &Tri, aa: bool) -> Option<(tiny_skia::Path, tiny_skia::Paint<'static>)> {
    let mut pb = tiny_skia::PathBuilder::new();
    let [a, b, c] = t.v.map(|[x, y]| (f32::from(x) / 16.0, f32::from(y) / 16.0));
    pb.move_to(a.0, a.1);
    pb.line_to(b.0, b.1);
    pb.line_to(c.0, c.1);
    pb.close();
    let path = pb.finish()?;
    let [r, g, b] = t.flat_rgb().map(|v| (v >> 4) as u8);
    let mut paint = tiny_skia::Paint::default();
    paint.set_color_rgba8(r, g, b, 255);
    paint.anti_alias = aa;
    Some((path, paint))
}

/// One frame: what callgrind measures. Returns whether it rendered.
#[inline(never)]
fn workload_frame(job: &mut Job) -> bool {
    match job.renderer {
        Renderer::Softedge(r) => {
            let mut bufs = Buffers {
                acc: &mut job.acc,
                cover: &mut job.cover,
                out16: &mut job.out16,
                out8: &mut job.out8,
                slots3: &mut job.slots3,
                slots1: &mut job.slots1,
                list3: &mut job.list3,
            };
            softedge_side::frame(r, job.tris, job.rows, &mut bufs).is_ok()
        }
        Renderer::Eg(r) => {
            let mut targets = Targets {
                fb: Framebuffer::new(&mut job.fb),
                stock: &mut job.stock,
            };
            eg_side::frame(r, job.tris, &mut targets);
            true
        }
        Renderer::TinySkia(_) => {
            job.pixmap.fill(tiny_skia::Color::BLACK);
            for (path, paint) in &job.paths {
                job.pixmap.fill_path(
                    path,
                    paint,
                    tiny_skia::FillRule::Winding,
                    tiny_skia::Transform::identity(),
                    None,
                );
            }
            std::hint::black_box(job.pixmap.data());
            true
        }
    }
}

/// `bench run workload <renderer> <workload|empty> <n> <rows>`: one frame.
pub fn run(args: &[String]) -> Result<(), String> {
    let [renderer, name, n, rows] = args else {
        return Err("usage: bench run workload RENDERER WORKLOAD N ROWS".into());
    };
    let renderer = Renderer::from_name(renderer).ok_or("unknown renderer")?;
    let tris: &'static [Tri] = if name == "empty" {
        &[]
    } else {
        let w = workload(name).ok_or("unknown workload")?;
        w.prefix(n.parse().map_err(|_| "bad N")?)
    };
    let rows = rows.parse().map_err(|_| "bad ROWS")?;
    let mut job = Job::new(renderer, tris, rows).ok_or("cannot set the frame up")?;
    if workload_frame(&mut job) {
        Ok(())
    } else {
        Err("the frame failed".into())
    }
}

/// Measures every frame of the table with `callgrind(args)` and prints it.
pub fn table(callgrind: impl Fn(&[&str]) -> Result<u64, String>) -> Result<(), String> {
    let measure = |r: Renderer, w: &str, n: usize, rows: u16| -> Result<u64, String> {
        let (n, rows) = (n.to_string(), rows.to_string());
        callgrind(&["workload", r.name(), w, &n, &rows])
    };
    println!(
        "Cortex-M0 benchmark workloads on x86-64 (valgrind callgrind, instructions; \
         softedge in {BAND_ROWS}-row bands; the same frames as boards/bench-m0)"
    );
    println!();
    print!("| renderer | fixed cost of a frame (N = 0) ");
    for w in CLASSES {
        let mean = w.twice_area() as f64 / 2.0 / w.tris.len() as f64;
        print!("| per px, {} ({mean:.1} px) ", w.name);
    }
    println!("| screen, 132 triangles |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    let mut sweep = Vec::new();
    for r in renderers() {
        let rows = if matches!(r, Renderer::Softedge(_)) {
            BAND_ROWS
        } else {
            240
        };
        let fixed = measure(r, "empty", 0, rows)?;
        print!("| {} | {} ", r.label(), mega(fixed));
        let classes = r != Renderer::Softedge(softedge_side::Renderer::AaFlatRgbNoCache);
        for w in CLASSES {
            if classes {
                let one = measure(r, w.name, 1, rows)?;
                let all = measure(r, w.name, COUNT, rows)?;
                let px = all.saturating_sub(one) as f64 / (w.twice_marginal_area() as f64 / 2.0);
                print!("| {} ", per_px(px));
            } else {
                print!("| — ");
            }
        }
        let screen = measure(r, "screen", SCREEN.tris.len(), rows)?;
        println!("| {} |", mega(screen));
        if classes && matches!(r, Renderer::Softedge(_)) {
            let mut counts = vec![screen];
            for &rows in &SCREEN_BANDS[1..] {
                counts.push(measure(r, "screen", SCREEN.tris.len(), rows)?);
            }
            sweep.push((r, counts));
        }
    }
    println!();
    println!("The screen by band height (rows per band), softedge:");
    println!();
    print!("| renderer ");
    for rows in SCREEN_BANDS {
        print!("| {rows} ");
    }
    println!("|");
    println!("| --- |{}", " ---: |".repeat(SCREEN_BANDS.len()));
    for (r, counts) in sweep {
        print!("| {} ", r.label());
        for c in counts {
            print!("| {} ", mega(c));
        }
        println!("|");
    }
    Ok(())
}

fn mega(n: u64) -> String {
    format!("{:.2} M", n as f64 / 1e6)
}

fn per_px(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.1}")
    }
}
