//! Issue #34: the example programs (`examples/three_shapes.rs`,
//! `instrument.rs`, `oled_gauge.rs`) against their embedded-graphics
//! twins (`*_eg.rs`): the same geometry. Each pair is run and its "ink"
//! (pixels away from the background) compared both ways: every pixel one
//! draws lies within a few pixels of a pixel the other draws (the
//! symmetric Hausdorff distance), outside the text, whose fonts differ.
//! `.ci/line_count.sh` checks that each program is shorter than its twin.

#![allow(dead_code)]
// Each example includes `support`; here the six are modules of one crate.
#![allow(clippy::duplicate_mod)]

#[path = "../examples/instrument.rs"]
mod instrument;
#[path = "../examples/instrument_eg.rs"]
mod instrument_eg;
#[path = "../examples/oled_gauge.rs"]
mod oled_gauge;
#[path = "../examples/oled_gauge_eg.rs"]
mod oled_gauge_eg;
#[path = "../examples/three_shapes.rs"]
mod three_shapes;
#[path = "../examples/three_shapes_eg.rs"]
mod three_shapes_eg;

use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_simulator::SimulatorDisplay;

/// Ink: pixels brighter than `min` (sum of 8-bit channels), outside
/// `skip`.
fn ink<C: PixelColor + Into<Rgb888>>(
    d: &SimulatorDisplay<C>,
    min: u32,
    skip: &[Rectangle],
) -> Vec<Point> {
    d.bounding_box()
        .points()
        .filter(|p| !skip.iter().any(|r| r.contains(*p)))
        .filter(|p| {
            let c: Rgb888 = d.get_pixel(*p).into();
            u32::from(c.r()) + u32::from(c.g()) + u32::from(c.b()) > min
        })
        .collect()
}

/// Whether every point of `a` has a point of `b` within `within` px
/// (Euclidean), and the first that has not.
fn reach(a: &[Point], b: &[Point], within: u32) -> Option<Point> {
    let set: std::collections::HashSet<Point> = b.iter().copied().collect();
    let r = within as i32;
    a.iter().copied().find(|p| {
        !(-r..=r).any(|dy| {
            (-r..=r)
                .any(|dx| dx * dx + dy * dy <= r * r && set.contains(&(*p + Point::new(dx, dy))))
        })
    })
}

fn same_geometry(what: &str, a: &[Point], b: &[Point], within: u32) {
    assert!(
        a.len() > 50 && b.len() > 50,
        "{what}: {} and {} ink pixels",
        a.len(),
        b.len()
    );
    let at = reach(a, b, within);
    assert!(
        at.is_none(),
        "{what}: softedge ink more than {within} px from the twin's at {at:?}"
    );
    let at = reach(b, a, within);
    assert!(
        at.is_none(),
        "{what}: the twin's ink more than {within} px from softedge's at {at:?}"
    );
}

#[test]
fn three_shapes_has_its_twins_geometry() {
    let (a, b): (SimulatorDisplay<Rgb565>, _) = (
        three_shapes::run().unwrap(),
        three_shapes_eg::run().unwrap(),
    );
    // Anything drawn (the background is black), and the bright white line.
    same_geometry("three shapes", &ink(&a, 40, &[]), &ink(&b, 40, &[]), 2);
    same_geometry("its line", &ink(&a, 600, &[]), &ink(&b, 600, &[]), 2);
}

#[test]
fn the_instrument_has_its_twins_geometry() {
    let (a, b) = (instrument::run().unwrap(), instrument_eg::run().unwrap());
    let text = [Rectangle::new(Point::new(60, 160), Size::new(120, 40))];
    // The dial (against black) and the bright parts: arc, needle, hub.
    same_geometry(
        "dial",
        &ink(&a.frame, 20, &text),
        &ink(&b.frame, 20, &text),
        2,
    );
    same_geometry(
        "arc, needle, hub",
        &ink(&a.frame, 250, &text),
        &ink(&b.frame, 250, &text),
        3,
    );
    // The partial redraw: softedge sends the read-out's window, e-g
    // every pixel of the scene inside it one by one.
    assert!(
        a.wire_bytes < b.wire_bytes,
        "{} vs {}",
        a.wire_bytes,
        b.wire_bytes
    );
}

#[test]
fn the_oled_gauge_has_its_twins_geometry() {
    let (a, b) = (oled_gauge::run().unwrap(), oled_gauge_eg::run().unwrap());
    let (a, b): (SimulatorDisplay<BinaryColor>, _) = (a.frame(), b.frame());
    let text = [Rectangle::new(Point::new(30, 26), Size::new(68, 38))];
    // The dithered track against e-g's thin arc: within its half-width.
    same_geometry("gauge", &ink(&a, 0, &text), &ink(&b, 0, &text), 3);
}
