//! `softedge-sim window` (feature `window`): the display's codes shown in
//! an embedded-graphics-simulator window, sent band by band with one
//! `fill_contiguous` per band as firmware sends them to a display.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::{DrawTarget, Point, Size};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay, Window};

use super::{Frame, SceneFile};

/// Renders `file`, tones it for its display and shows it until the window
/// is closed. Errors are messages (a scene error, no display to open).
pub fn show(file: &SceneFile, scale: u32) -> Result<(), String> {
    if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
        return Err(
            "no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset)".into(),
        );
    }
    let lin = file.render_linear().map_err(|d| d.to_string())?;
    let shown = file.tone(&lin).to_image8().to_rgb();
    let (w, h) = file.size();
    let band_rows = match &file.frame {
        Frame::Gray(s) => s.band_rows,
        Frame::Rgb(s) => s.band_rows,
    }
    .max(1);
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(u32::from(w), u32::from(h)));
    for band in softedge::Bands::new(w, h, band_rows) {
        let area = Rectangle::new(
            Point::new(0, band.y0),
            Size::new(u32::from(w), u32::from(band.rows)),
        );
        let rows = band.y0 as u32..band.y0 as u32 + u32::from(band.rows);
        let colors = rows.flat_map(|y| (0..u32::from(w)).map(move |x| (x, y)));
        let colors = colors.map(|(x, y)| {
            let p = shown.pixel(x, y);
            Rgb888::new(p[0], p[1], p[2])
        });
        display
            .fill_contiguous(&area, colors)
            .map_err(|e| format!("{e:?}"))?;
    }
    let settings = OutputSettingsBuilder::new().scale(scale.max(1)).build();
    let title = format!("softedge-sim: {}", file.stem());
    Window::new(&title, &settings).show_static(&display);
    Ok(())
}
