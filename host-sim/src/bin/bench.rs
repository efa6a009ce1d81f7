//! Instruction counts of the edge engine (a benchmark, not a test).
//!
//! `cargo run --release -p softedge-sim --bin bench` runs itself under
//! valgrind's callgrind three times per channel count, collecting only
//! inside the edge walk, only inside the span sweep, and over the whole
//! frame, and prints instructions per edge pixel, per swept pixel and per
//! frame. Instruction counts are deterministic for a given binary; no time
//! is measured. `bench run C` renders the reference scene once (what
//! callgrind measures). Last, the table of the Cortex-M0 benchmark's
//! workloads (softedge, embedded-graphics and tiny-skia on the same
//! triangles; see `bench/workloads.rs`), which `bench workloads` prints
//! alone.

use std::process::Command;

#[path = "bench/workloads.rs"]
mod workloads;

use softedge::edge::{AreaMode, CoverSink, EdgeWalk};
use softedge::geom::FinePoint;
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

/// A quadrilateral covering the whole frame with its corners at sub-pixel
/// positions outside it: every pixel is an interior pixel of one span.
fn fill_scene<const C: usize>() -> (Vec<Triangle<C>>, Vec<Line<C>>) {
    let (w, h) = (i32::from(W) * 16, i32::from(H) * 16);
    let v = [
        SubPoint::new(-5, -3),
        SubPoint::new(w + 7, -9),
        SubPoint::new(w + 3, h + 5),
        SubPoint::new(-9, h + 2),
    ];
    let c = |k: u16| [k * 900; C];
    (
        vec![
            Triangle::new([v[0], v[1], v[2]], [c(1), c(2), c(3)]),
            Triangle::new([v[0], v[2], v[3]], [c(1), c(3), c(4)]),
        ],
        vec![],
    )
}

/// The 3D benchmark: a lit torus of 24 x 12 segments (576 triangles, 288
/// vertices), seen along its axis tilted by 20°, orthographic, RGB,
/// projected again in every band (what a firmware without a triangle store
/// does). Returns a checksum.
#[inline(never)]
fn render_torus() -> u64 {
    use softedge::scene3d::{
        project_mesh, Angle, Camera, Light, Mesh, Shape, Transform, Vec3, ViewVertex, I16F16,
    };
    let shape = Shape::Torus {
        major: I16F16::from_num(3),
        minor: I16F16::from_num(1),
        segments: 24,
        tube_segments: 12,
    };
    let Ok(mesh) = Mesh::<288, 576>::new(&shape) else {
        return 0;
    };
    let cam = Camera::orthographic(
        Vec3::from_int(0, 0, 20),
        Vec3::ZERO,
        Vec3::from_int(0, 1, 0),
        I16F16::from_num(28),
    );
    let Ok(view) = cam.view(W, H) else {
        return 0;
    };
    let light = Light::new(Vec3::from_int(-1, -2, 3), [500; 3], [3500; 3]);
    let tilt = Transform::rotation_x(Angle::from_degrees(20));
    let mut scratch = [ViewVertex::<3>::EMPTY; 288];
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, BAND_ROWS)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, BAND_ROWS)];
    let mut row = vec![[0u16; 3]; usize::from(W)];
    let mut sum = 0u64;
    for band in Bands::new(W, H, BAND_ROWS) {
        let Ok(mut buf) = BandBuffer::<3>::new(&mut acc, &mut cover, band) else {
            continue;
        };
        buf.clear([0; 3]);
        let _ = project_mesh(
            mesh.as_ref(),
            &tilt,
            [3000, 2000, 800],
            &view,
            &light,
            &mut scratch,
            |t| {
                let _ = t.draw(&mut buf, &RenderStyle::default());
            },
        );
        for y in band.y0..band.y0 + i32::from(band.rows) {
            buf.resolve_row(y, &mut row);
            sum += row.iter().flatten().map(|&v| u64::from(v)).sum::<u64>();
        }
    }
    sum
}

/// The pixel-model benchmark: the reference mesh's 288 triangles, flat
/// gray (each its first vertex's colour), 240x240 in bands of 16 rows,
/// drawn with `model`.
#[inline(never)]
fn render_model(model: softedge::PixelModel) -> u64 {
    let (tris, _) = scene::<1>();
    let style = RenderStyle {
        antialias: true,
        model,
    };
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, BAND_ROWS)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, BAND_ROWS)];
    let mut sum = 0u64;
    for band in Bands::new(W, H, BAND_ROWS) {
        let Ok(mut buf) = BandBuffer::<1>::new(&mut acc, &mut cover, band) else {
            continue;
        };
        buf.clear([0]);
        for t in &tris {
            let _ = Triangle::flat(t.vertices, t.colors[0]).draw(&mut buf, &style);
        }
        for y in band.y0..band.y0 + i32::from(band.rows) {
            sum += u64::from(buf.lin12(5, y).map_or(0, |v| v[0]));
        }
    }
    sum
}

/// The hidden-surface benchmark: the same torus tilted 60° (its near tube
/// hides part of the far inner wall: 576 triangles, about half culled),
/// projected once per frame into a triangle store, sorted front to back,
/// then drawn band by band by `mode`: `plain` (accumulated, no hidden-
/// surface removal), `z1` (one z-buffer pass, anti-aliased), `z3` (the
/// three passes of `draw_zbuffer`), `zal` (aliased z-buffer), `warnock`
/// (Warnock's subdivision in every band), `wa` (Weiler–Atherton's visible
/// pieces, computed once, drawn per band).
#[inline(never)]
fn render_torus_z(mode: &str) -> u64 {
    use softedge::hsr::{
        draw_warnock, draw_zbuffer, scratch_len, sort_front_to_back, DepthBuffer, DepthTriangle,
        VisibleSet, ZPass,
    };
    use softedge::scene3d::{
        project_mesh, Angle, Camera, Light, Mesh, Shape, Transform, Vec3, ViewVertex, I16F16,
    };
    let shape = Shape::Torus {
        major: I16F16::from_num(3),
        minor: I16F16::from_num(1),
        segments: 24,
        tube_segments: 12,
    };
    let Ok(mesh) = Mesh::<288, 576>::new(&shape) else {
        return 0;
    };
    let mut cam = Camera::orthographic(
        Vec3::from_int(0, 0, 20),
        Vec3::ZERO,
        Vec3::from_int(0, 1, 0),
        I16F16::from_num(28),
    );
    cam.far = I16F16::from_num(40);
    let Ok(view) = cam.view(W, H) else {
        return 0;
    };
    let light = Light::new(Vec3::from_int(-1, -2, 3), [500; 3], [3500; 3]);
    let tilt = Transform::rotation_x(Angle::from_degrees(60));
    let mut scratch = [ViewVertex::<3>::EMPTY; 288];
    let mut store: Vec<DepthTriangle<3>> = Vec::with_capacity(576);
    let _ = project_mesh(
        mesh.as_ref(),
        &tilt,
        [3000, 2000, 800],
        &view,
        &light,
        &mut scratch,
        |t| store.push(t),
    );
    sort_front_to_back(&mut store);
    // Weiler–Atherton: the visible pieces, once per frame.
    let mut pieces: Box<VisibleSet<2048>> = Box::default();
    if mode == "wa" && pieces.compute(&store).is_err() {
        return 0;
    }
    let mut scratch = vec![0u16; scratch_len(store.len())];
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, BAND_ROWS)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, BAND_ROWS)];
    let mut depth = vec![0u16; DepthBuffer::len(W, BAND_ROWS)];
    let mut covered = vec![0u16; DepthBuffer::covered_len(W, BAND_ROWS)];
    let mut row = vec![[0u16; 3]; usize::from(W)];
    let mut sum = 0u64;
    for band in Bands::new(W, H, BAND_ROWS) {
        let (Ok(mut buf), Ok(mut zbuf)) = (
            BandBuffer::<3>::new(&mut acc, &mut cover, band),
            DepthBuffer::new(&mut depth, &mut covered, band),
        ) else {
            continue;
        };
        buf.clear([0; 3]);
        let aa = RenderStyle::default();
        match mode {
            "plain" => store.iter().for_each(|t| {
                let _ = t.draw(&mut buf, &aa);
            }),
            "z1" => store.iter().for_each(|t| {
                let _ = t.draw_z(&mut buf, &mut zbuf, &aa, ZPass::Single);
            }),
            "zal" => {
                let _ = draw_zbuffer(&store, &mut buf, &mut zbuf, &RenderStyle::ALIASED);
            }
            "wa" => {
                let _ = pieces.draw(&store, &mut buf, &aa);
            }
            "warnock" => {
                let _ = draw_warnock(&store, &mut buf, &mut scratch);
            }
            _ => {
                let _ = draw_zbuffer(&store, &mut buf, &mut zbuf, &aa);
            }
        }
        for y in band.y0..band.y0 + i32::from(band.rows) {
            buf.resolve_row(y, &mut row);
            sum += row.iter().flatten().map(|&v| u64::from(v)).sum::<u64>();
        }
    }
    sum + store.len() as u64
}

/// Renders a scene once, band by band; returns a checksum so nothing is
/// optimised away.
#[inline(never)]
fn render_frame<const C: usize>(fill: bool) -> u64 {
    let (tris, lines) = if fill {
        fill_scene::<C>()
    } else {
        scene::<C>()
    };
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
    /// An edge's cover changes, by row: a row with changes at `k`
    /// distinct columns holds `k - 1` edge pixels (a cell of area `S` is
    /// `+S` at its column and `-S` at the next, where the next cell's
    /// change or the row's remaining cover lands).
    struct Count(std::collections::BTreeSet<(i32, i32)>);
    impl CoverSink for Count {
        fn cover(&mut self, x: i32, y: i32, d: i32) {
            if d != 0 {
                self.0.insert((y, x));
            }
        }
    }
    impl Count {
        fn pixels(&self) -> u64 {
            let mut rows = std::collections::BTreeMap::<i32, u64>::new();
            for &(y, _) in &self.0 {
                *rows.entry(y).or_default() += 1;
            }
            rows.values().map(|k| k.saturating_sub(1)).sum()
        }
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
    let (mut cells, mut swept) = (0u64, 0u64);
    for v in &outlines {
        for band in Bands::new(W, H, BAND_ROWS) {
            let rows = band.y0..band.y0 + i32::from(band.rows);
            for k in 0..v.len() {
                let (p0, p1) = (FinePoint::from(v[k]), FinePoint::from(v[(k + 1) % v.len()]));
                if let Some(mut w) = EdgeWalk::new(p0, p1, AreaMode::Exact, 0..i32::from(W)) {
                    let mut edge = Count(Default::default());
                    w.walk(rows.clone(), &mut edge);
                    cells += edge.pixels();
                }
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
    (cells, swept)
}

fn callgrind(channels: &str, scene: &str, toggle: Option<&str>) -> Result<u64, String> {
    callgrind_run(&[channels, scene], toggle)
}

/// Instructions of `bench run ARGS..` under callgrind, collected only inside
/// the functions matching `toggle` (all of them without).
fn callgrind_run(run_args: &[&str], toggle: Option<&str>) -> Result<u64, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = std::env::temp_dir().join(format!(
        "softedge-bench-{}-{}.out",
        std::process::id(),
        run_args.join("-")
    ));
    let mut cmd = Command::new("valgrind");
    cmd.arg("--tool=callgrind")
        .arg(format!("--callgrind-out-file={}", out.display()));
    if let Some(t) = toggle {
        cmd.arg(format!("--toggle-collect={t}"));
    }
    let status = cmd
        .arg(&exe)
        .arg("run")
        .args(run_args)
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

/// The workloads table alone (`bench workloads`), or after the rest.
fn workloads_table() {
    if let Err(e) = workloads::table(|args| callgrind_run(args, Some("*workload_frame*"))) {
        eprintln!("bench: {e}");
        std::process::exit(1);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("workloads") {
        workloads_table();
        return;
    }
    if args.first().map(String::as_str) == Some("run")
        && args.get(1).map(String::as_str) == Some("workload")
    {
        if let Err(e) = workloads::run(&args[2..]) {
            eprintln!("bench: {e}");
            std::process::exit(1);
        }
        return;
    }
    if args.first().map(String::as_str) == Some("run") {
        let fill = args.get(2).map(String::as_str) == Some("fill");
        if args.get(2).map(String::as_str) == Some("torus") {
            println!("checksum {}", render_torus());
            return;
        }
        if let Some(name) = args.get(2).and_then(|a| a.strip_prefix("model-")) {
            let model = softedge_sim::scene_file::model_named(name);
            println!("checksum {}", model.map_or(0, render_model));
            return;
        }
        if let Some(mode) = args.get(2).and_then(|a| a.strip_prefix("torus-")) {
            println!("checksum {}", render_torus_z(mode));
            return;
        }
        let sum = match args.get(1).map(String::as_str) {
            Some("3") => render_frame::<3>(fill),
            _ => render_frame::<1>(fill),
        };
        println!("checksum {sum}");
        return;
    }
    println!("softedge edge-engine instruction counts (valgrind callgrind; deterministic)");
    println!("scene: {W}x{H}, 288 Gouraud triangles sharing edges + 16 lines, bands of {BAND_ROWS} rows, exact box coverage");
    println!(
        "interior: the same frame filled by one Gouraud quadrilateral (two triangles), {} pixels",
        u32::from(W) * u32::from(H)
    );
    for channels in ["1", "3"] {
        let (cells, _) = if channels == "3" {
            counts::<3>()
        } else {
            counts::<1>()
        };
        let run = |scene, t| callgrind(channels, scene, t);
        let results = [
            run("mesh", Some("*EdgeWalk*walk*")),
            run("mesh", Some("*render_frame*")),
            run("fill", Some("*sweep*")),
            run("fill", Some("*render_frame*")),
        ];
        let mut n = [0u64; 4];
        for (slot, r) in n.iter_mut().zip(results) {
            match r {
                Ok(v) => *slot = v,
                Err(e) => {
                    eprintln!("bench: {e}");
                    std::process::exit(1);
                }
            }
        }
        let px = f64::from(W) * f64::from(H);
        println!("channels {channels}:");
        println!(
            "  mesh edge walk  {:>10} instructions / {cells} edge pixels = {:.1} per edge pixel",
            n[0],
            n[0] as f64 / cells as f64
        );
        println!(
            "  mesh frame      {:>10} instructions = {:.1} per frame pixel",
            n[1],
            n[1] as f64 / px
        );
        println!(
            "  fill span sweep {:>10} instructions = {:.1} per interior pixel",
            n[2],
            n[2] as f64 / px
        );
        println!("  fill frame      {:>10} instructions = {:.1} per frame pixel (incl. clear and resolve)", n[3], n[3] as f64 / px);
    }
    let torus = [
        callgrind("3", "torus", Some("*render_torus*")),
        callgrind("3", "torus", Some("*scene3d*project*")),
        callgrind("3", "torus", Some("*EdgeWalk*walk*")),
        callgrind("3", "torus", Some("*raster*fill*")),
    ];
    let mut n = [0u64; 4];
    for (slot, r) in n.iter_mut().zip(torus) {
        match r {
            Ok(v) => *slot = v,
            Err(e) => {
                eprintln!("bench: {e}");
                std::process::exit(1);
            }
        }
    }
    let bands = u64::from(H.div_ceil(BAND_ROWS));
    println!("3D: lit torus 24x12 segments (576 triangles, 288 vertices), RGB, {W}x{H}, bands of {BAND_ROWS} (projected once per band, {bands} bands):");
    println!(
        "  whole frame     {:>10} instructions = {:.1} per frame pixel",
        n[0],
        n[0] as f64 / (f64::from(W) * f64::from(H))
    );
    // `project` calls the drawing back for every triangle: subtract it.
    let geometry = n[1].saturating_sub(n[3]);
    println!(
        "  geometry (transform, light, project, cull) {:>10} instructions = {:.0} per band = {:.0} per vertex and band (incl. its share of triangle setup)",
        geometry,
        geometry as f64 / bands as f64,
        geometry as f64 / (288.0 * bands as f64)
    );
    println!(
        "  drawing (edge walk {}, spans, setup) {:>10} instructions",
        n[2], n[3]
    );
    println!("pixel models: the mesh's 288 triangles, flat gray, {W}x{H}, bands of {BAND_ROWS}:");
    let mut box_count = 0u64;
    for name in softedge::PixelModel::ALL.map(softedge_sim::scene_file::model_name) {
        match callgrind("1", &format!("model-{name}"), Some("*render_model*")) {
            Ok(v) => {
                if name == "box" {
                    box_count = v;
                }
                println!(
                    "  {name:<9} {v:>11} instructions per frame = {:.1} x box",
                    v as f64 / box_count.max(1) as f64
                );
            }
            Err(e) => {
                eprintln!("bench: {e}");
                std::process::exit(1);
            }
        }
    }
    println!("hidden surfaces: the torus tilted 60° (self-occluding), projected once into a triangle store, sorted, RGB, {W}x{H}, bands of {BAND_ROWS}:");
    for (mode, what) in [
        ("plain", "accumulated, no hidden-surface removal"),
        ("zal", "z-buffer, aliased (one pass)"),
        ("z1", "z-buffer, anti-aliased, one pass"),
        ("z3", "z-buffer, anti-aliased, three passes (draw_zbuffer)"),
        ("warnock", "Warnock's subdivision (per band)"),
        (
            "wa",
            "Weiler-Atherton (pieces once per frame, drawn per band)",
        ),
    ] {
        match callgrind("3", &format!("torus-{mode}"), Some("*render_torus_z*")) {
            Ok(v) => println!(
                "  {what:<52} {v:>10} instructions = {:.1} per frame pixel",
                v as f64 / (f64::from(W) * f64::from(H))
            ),
            Err(e) => {
                eprintln!("bench: {e}");
                std::process::exit(1);
            }
        }
    }
    println!();
    workloads_table();
}
