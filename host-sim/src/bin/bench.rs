//! Instruction counts of the edge engine (a benchmark, not a test).
//!
//! `cargo run --release -p softedge-sim --bin bench` runs itself under
//! valgrind's callgrind three times per channel count, collecting only
//! inside the edge walk, only inside the span sweep, and over the whole
//! frame, and prints instructions per edge pixel, per swept pixel and per
//! frame. Instruction counts are deterministic for a given binary; no time
//! is measured. `bench run C` renders the reference scene once (what
//! callgrind measures).

use std::process::Command;

use softedge::edge::{walk_edge, AreaMode, EdgeSink, Plane};
use softedge::{BandBuffer, Bands, Line, RenderStyle, SubPoint, Triangle};

const W: u16 = 240;
const H: u16 = 240;
const BAND_ROWS: u16 = 16;
const GRID: i32 = 12;

/// The reference scene: a 12x12 grid of jittered quads, each split into two
/// Gouraud triangles (288 triangles sharing edges), and 16 lines.
fn scene<const C: usize>() -> (Vec<Triangle<C>>, Vec<Line<C>>) {
    let cell = i32::from(W) * 16 / GRID;
    let mut seed = 0x2545_f491_u32;
    let mut jitter = || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        (seed % 97) as i32 - 48
    };
    let mut pts = vec![];
    for j in 0..=GRID {
        for i in 0..=GRID {
            let inner = i > 0 && i < GRID && j > 0 && j < GRID;
            let (jx, jy) = if inner { (jitter(), jitter()) } else { (0, 0) };
            pts.push(SubPoint::new(i * cell + jx, j * cell + jy));
        }
    }
    let color =
        |k: usize| -> [u16; C] { core::array::from_fn(|ch| ((k * 37 + ch * 1500) % 4096) as u16) };
    let idx = |i: i32, j: i32| (j * (GRID + 1) + i) as usize;
    let mut tris = vec![];
    for j in 0..GRID {
        for i in 0..GRID {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            tris.push(Triangle::new(
                [pts[a], pts[b], pts[c]],
                [color(a), color(b), color(c)],
            ));
            tris.push(Triangle::new(
                [pts[a], pts[c], pts[d]],
                [color(a), color(c), color(d)],
            ));
        }
    }
    let lines = (0..16)
        .map(|k| {
            let t = k * 16 * 15;
            Line::new(
                SubPoint::new(8 + t / 4, 40),
                SubPoint::new(3800 - t, 3700),
                [[4095; C], [500; C]],
            )
        })
        .collect();
    (tris, lines)
}

/// Renders the scene once, band by band; returns a checksum so nothing is
/// optimised away.
#[inline(never)]
fn render_frame<const C: usize>() -> u64 {
    let (tris, lines) = scene::<C>();
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(W, BAND_ROWS)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(W, BAND_ROWS)];
    let style = RenderStyle::default();
    let mut sum = 0u64;
    let mut row = vec![[0u16; C]; usize::from(W)];
    for band in Bands::new(W, H, BAND_ROWS) {
        let Ok(mut buf) = BandBuffer::<C>::new(&mut acc, &mut cover, band) else {
            continue;
        };
        buf.clear([0; C]);
        for t in &tris {
            let _ = t.draw(&mut buf, &style);
        }
        for l in &lines {
            let _ = l.draw(&mut buf, &style);
        }
        for y in band.y0..band.y0 + i32::from(band.rows) {
            buf.resolve_row(y, &mut row);
            sum += row.iter().flatten().map(|&v| u64::from(v)).sum::<u64>();
        }
    }
    sum
}

/// Counts the edge pixels the walker reports and the pixels the span sweep
/// visits for the scene (what the instruction totals are divided by).
fn counts<const C: usize>() -> (u64, u64) {
    struct Count(u64);
    impl<const C: usize> EdgeSink<C> for Count {
        fn cell(&mut self, _: i32, _: i32, _: i32, _: &[i32; C]) {
            self.0 += 1;
        }
        fn cover(&mut self, _: i32, _: i32, _: i32) {}
    }
    let (tris, lines) = scene::<C>();
    let mut outlines: Vec<Vec<SubPoint>> = tris.iter().map(|t| t.vertices.to_vec()).collect();
    for l in &lines {
        // The line's rectangle, as `Line::draw` builds it.
        let (dx, dy) = (i64::from(l.to.x - l.from.x), i64::from(l.to.y - l.from.y));
        let len = ((dx * dx + dy * dy) as u64).isqrt() as i64;
        let nx = (-dy * 16 + len).div_euclid(2 * len) as i32;
        let ny = (dx * 16 + len).div_euclid(2 * len) as i32;
        outlines.push(vec![
            SubPoint::new(l.from.x + nx, l.from.y + ny),
            SubPoint::new(l.to.x + nx, l.to.y + ny),
            SubPoint::new(l.to.x - nx, l.to.y - ny),
            SubPoint::new(l.from.x - nx, l.from.y - ny),
        ]);
    }
    let plane = Plane::<C>::flat([4095; C], [0; C]);
    let (mut cells, mut swept) = (Count(0), 0u64);
    for v in &outlines {
        for band in Bands::new(W, H, BAND_ROWS) {
            let rows = band.y0..band.y0 + i32::from(band.rows);
            for k in 0..v.len() {
                walk_edge(
                    v[k],
                    v[(k + 1) % v.len()],
                    1,
                    &plane,
                    AreaMode::Exact,
                    rows.clone(),
                    &mut cells,
                );
            }
        }
        let (x0, x1) = (
            v.iter().map(|p| p.x).min().unwrap_or(0) >> 4,
            v.iter().map(|p| p.x).max().unwrap_or(0) >> 4,
        );
        let (y0, y1) = (
            v.iter().map(|p| p.y).min().unwrap_or(0) >> 4,
            v.iter().map(|p| p.y).max().unwrap_or(0) >> 4,
        );
        let cols = (x1 + 1).min(i32::from(W) - 1) - x0.max(0) + 1;
        let rows = y1.min(i32::from(H) - 1) - y0.max(0) + 1;
        swept += (cols.max(0) * rows.max(0)) as u64;
    }
    (cells.0, swept)
}

fn callgrind(channels: &str, toggle: Option<&str>) -> Result<u64, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = std::env::temp_dir().join(format!(
        "softedge-bench-{}-{channels}.out",
        std::process::id()
    ));
    let mut cmd = Command::new("valgrind");
    cmd.arg("--tool=callgrind")
        .arg(format!("--callgrind-out-file={}", out.display()));
    if let Some(t) = toggle {
        cmd.arg(format!("--toggle-collect={t}"));
    }
    let status = cmd
        .arg(&exe)
        .args(["run", channels])
        .output()
        .map_err(|e| {
            format!("cannot run valgrind ({e}); install it with `apt-get install valgrind`")
        })?;
    if !status.status.success() {
        return Err(String::from_utf8_lossy(&status.stderr).into_owned());
    }
    let text = std::fs::read_to_string(&out).map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(&out);
    text.lines()
        .find_map(|l| {
            l.strip_prefix("summary:")
                .or_else(|| l.strip_prefix("totals:"))
        })
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .ok_or_else(|| "no totals in callgrind output".into())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("run") {
        let sum = match args.get(1).map(String::as_str) {
            Some("3") => render_frame::<3>(),
            _ => render_frame::<1>(),
        };
        println!("checksum {sum}");
        return;
    }
    println!("softedge edge-engine instruction counts (valgrind callgrind; deterministic)");
    println!("scene: {W}x{H}, 288 Gouraud triangles sharing edges + 16 lines, bands of {BAND_ROWS} rows, exact box coverage");
    for channels in ["1", "3"] {
        let (cells, swept) = if channels == "3" {
            counts::<3>()
        } else {
            counts::<1>()
        };
        let run = |t| callgrind(channels, t);
        let (walk, sweep, frame) = match (
            run(Some("*walk_edge*")),
            run(Some("*sweep*")),
            run(Some("*render_frame*")),
        ) {
            (Ok(a), Ok(b), Ok(c)) => (a, b, c),
            (Err(e), ..) | (_, Err(e), _) | (.., Err(e)) => {
                eprintln!("bench: {e}");
                std::process::exit(1);
            }
        };
        println!("channels {channels}:");
        println!("  edge walk   {walk:>11} instructions / {cells:>6} edge pixels  = {:>6.1} per edge pixel", walk as f64 / cells as f64);
        println!("  span sweep  {sweep:>11} instructions / {swept:>6} swept pixels = {:>6.1} per swept pixel", sweep as f64 / swept as f64);
        println!("  whole frame {frame:>11} instructions                        = {:>6.1} per frame pixel", frame as f64 / (f64::from(W) * f64::from(H)));
    }
}
