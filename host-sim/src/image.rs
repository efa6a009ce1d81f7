//! Images on the host: linear 12-bit frames as rendered, 8-bit sRGB images
//! for viewing (through `softedge::tone`'s sRGB table), and the few
//! operations the gallery needs (upscaling, compositing, rectangles).

use softedge::tone::{Curve, GammaLut};

/// A rendered frame: linear 12-bit values (`0..=4095`) per channel, rows top
/// to bottom. `C` is 1 (gray) or 3 (RGB).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LinImage<const C: usize> {
    width: u32,
    height: u32,
    data: Vec<[u16; C]>,
}

impl<const C: usize> LinImage<C> {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            data: vec![[0; C]; width as usize * height as usize],
        }
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Pixel `(x, y)`; panics outside the image (host-side tool code).
    pub fn get(&self, x: u32, y: u32) -> &[u16; C] {
        &self.data[(y * self.width + x) as usize]
    }

    /// All pixels, row by row.
    pub fn pixels(&self) -> impl Iterator<Item = [u16; C]> + '_ {
        self.data.iter().copied()
    }

    /// Copies `row` into row `y` from column 0 (extra pixels are ignored,
    /// rows outside the image too).
    pub fn set_row(&mut self, y: u32, row: &[[u16; C]]) {
        if y >= self.height {
            return;
        }
        let start = (y * self.width) as usize;
        let end = start + self.width as usize;
        for (d, s) in self.data[start..end].iter_mut().zip(row) {
            *d = *s;
        }
    }

    /// The `w x h` part whose top-left pixel is `(x, y)`, clipped to the
    /// image.
    pub fn crop(&self, x: u32, y: u32, w: u32, h: u32) -> Self {
        let x1 = (x + w).min(self.width);
        let y1 = (y + h).min(self.height);
        let (x0, y0) = (x.min(x1), y.min(y1));
        let mut out = Self::new(x1 - x0, y1 - y0);
        for yy in y0..y1 {
            let s = (yy * self.width + x0) as usize;
            let row = &self.data[s..s + (x1 - x0) as usize];
            out.set_row(yy - y0, row);
        }
        out
    }

    /// Per-pixel `|self - other|` of two same-size images times `gain`
    /// (saturated at 4095), and the number of pixels that differ at all.
    pub fn abs_diff(&self, other: &Self, gain: u32) -> Option<(Self, usize)> {
        if self.width != other.width || self.height != other.height {
            return None;
        }
        let mut differ = 0;
        let data = self
            .data
            .iter()
            .zip(&other.data)
            .map(|(a, b)| {
                if a != b {
                    differ += 1;
                }
                let mut d = [0u16; C];
                for ch in 0..C {
                    let v = u32::from(a[ch].abs_diff(b[ch])) * gain;
                    d[ch] = v.min(u32::from(softedge::LIN_MAX)) as u16;
                }
                d
            })
            .collect();
        Some((
            Self {
                width: self.width,
                height: self.height,
                data,
            },
            differ,
        ))
    }

    /// Sum over all pixels and channels (the "energy" of the frame).
    pub fn sum(&self) -> u64 {
        self.data
            .iter()
            .flat_map(|p| p.iter())
            .map(|&v| u64::from(v))
            .sum()
    }
}

/// The sRGB encoding table of the firmware's tone stage
/// ([`GammaLut`] for [`Curve::Srgb`], IEC 61966-2-1), built at compile time.
static SRGB8: GammaLut = GammaLut::new(Curve::Srgb);

/// Linear 12-bit intensity to an 8-bit sRGB code, for viewing on a PC.
///
/// This is `softedge::tone`'s own sRGB table ([`GammaLut`] for
/// [`Curve::Srgb`]): a PC monitor is an sRGB display, so the simulator
/// shows a frame exactly as firmware would send it to an sRGB panel.
/// Values above 4095 are treated as 4095.
pub fn lin12_to_srgb8(lin12: u16) -> u8 {
    SRGB8.code(lin12)
}

/// Light emitted by a display, as a fraction `0..=1` of its white (values
/// outside are clamped), to the 8-bit sRGB code that makes a PC monitor
/// emit the same fraction: rounded to linear 12 bits, then
/// [`lin12_to_srgb8`]. Used to show what a simulated display of another
/// transfer curve (γ = 2.4, say) emits.
pub fn emitted_to_srgb8(light: f64) -> u8 {
    let lin12 = (light.clamp(0.0, 1.0) * f64::from(softedge::LIN_MAX)).round() as u16;
    lin12_to_srgb8(lin12)
}

/// Channel layout of an [`Image8`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Channels {
    /// One byte per pixel.
    Gray,
    /// Three bytes per pixel, R G B.
    Rgb,
}

impl Channels {
    /// Bytes per pixel.
    pub fn count(self) -> usize {
        match self {
            Self::Gray => 1,
            Self::Rgb => 3,
        }
    }
}

/// An 8-bit sRGB image, rows top to bottom, channels interleaved.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image8 {
    width: u32,
    height: u32,
    channels: Channels,
    data: Vec<u8>,
}

impl Image8 {
    /// An image filled with `fill` (its length is the channel count).
    pub fn new(width: u32, height: u32, channels: Channels, fill: &[u8]) -> Self {
        let n = channels.count();
        let mut data = Vec::with_capacity(width as usize * height as usize * n);
        for _ in 0..width as usize * height as usize {
            data.extend((0..n).map(|k| fill.get(k).copied().unwrap_or(0)));
        }
        Self {
            width,
            height,
            channels,
            data,
        }
    }

    /// An image over `data`, if its length fits.
    pub fn from_raw(width: u32, height: u32, channels: Channels, data: Vec<u8>) -> Option<Self> {
        (data.len() == width as usize * height as usize * channels.count()).then_some(Self {
            width,
            height,
            channels,
            data,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Channel layout.
    pub fn channels(&self) -> Channels {
        self.channels
    }

    /// The bytes, rows top to bottom.
    pub fn data(&self) -> &[u8] {
        &self.data
    }

    /// The bytes of pixel `(x, y)`; panics outside the image.
    pub fn pixel(&self, x: u32, y: u32) -> &[u8] {
        let n = self.channels.count();
        let k = (y as usize * self.width as usize + x as usize) * n;
        &self.data[k..k + n]
    }

    /// The same image with three channels (gray repeated).
    pub fn to_rgb(&self) -> Self {
        match self.channels {
            Channels::Rgb => self.clone(),
            Channels::Gray => Self {
                width: self.width,
                height: self.height,
                channels: Channels::Rgb,
                data: self.data.iter().flat_map(|&g| [g, g, g]).collect(),
            },
        }
    }

    /// Nearest-neighbour upscaling: every pixel becomes a `factor x factor`
    /// block (a factor of 0 is taken as 1).
    pub fn upscale(&self, factor: u32) -> Self {
        let f = factor.max(1) as usize;
        let n = self.channels.count();
        let (w, h) = (self.width as usize, self.height as usize);
        let mut data = Vec::with_capacity(w * f * h * f * n);
        for y in 0..h {
            let src = &self.data[y * w * n..(y + 1) * w * n];
            let mut row = Vec::with_capacity(w * f * n);
            for px in src.chunks_exact(n) {
                for _ in 0..f {
                    row.extend_from_slice(px);
                }
            }
            for _ in 0..f {
                data.extend_from_slice(&row);
            }
        }
        Self {
            width: self.width * f as u32,
            height: self.height * f as u32,
            channels: self.channels,
            data,
        }
    }

    /// Fills the rectangle `[x, x + w) x [y, y + h)` (clipped) with `color`
    /// (its length is the channel count).
    pub fn fill_rect(&mut self, x: i64, y: i64, w: u32, h: u32, color: &[u8]) {
        let n = self.channels.count();
        let x0 = x.clamp(0, i64::from(self.width)) as usize;
        let x1 = (x + i64::from(w)).clamp(0, i64::from(self.width)) as usize;
        let y0 = y.clamp(0, i64::from(self.height)) as usize;
        let y1 = (y + i64::from(h)).clamp(0, i64::from(self.height)) as usize;
        for yy in y0..y1 {
            for xx in x0..x1 {
                let k = (yy * self.width as usize + xx) * n;
                for (c, d) in self.data[k..k + n].iter_mut().enumerate() {
                    *d = color.get(c).copied().unwrap_or(0);
                }
            }
        }
    }

    /// Copies `src` (same channel layout; otherwise nothing happens) with its
    /// top-left pixel at `(x, y)`, clipped.
    pub fn blit(&mut self, src: &Self, x: u32, y: u32) {
        if src.channels != self.channels {
            return;
        }
        let n = self.channels.count();
        let w = src.width.min(self.width.saturating_sub(x)) as usize;
        for sy in 0..src.height.min(self.height.saturating_sub(y)) {
            let s = sy as usize * src.width as usize * n;
            let d = ((y + sy) as usize * self.width as usize + x as usize) * n;
            self.data[d..d + w * n].copy_from_slice(&src.data[s..s + w * n]);
        }
    }

    /// True when every pixel equals the first.
    pub fn is_uniform(&self) -> bool {
        let n = self.channels.count();
        self.data
            .chunks_exact(n)
            .all(|px| px == &self.data[..n.min(self.data.len())])
    }
}

impl LinImage<1> {
    /// The gray image as 8-bit sRGB ([`lin12_to_srgb8`]).
    pub fn to_srgb8(&self) -> Image8 {
        Image8 {
            width: self.width,
            height: self.height,
            channels: Channels::Gray,
            data: self.data.iter().map(|[v]| lin12_to_srgb8(*v)).collect(),
        }
    }
}

impl LinImage<3> {
    /// The RGB image as 8-bit sRGB ([`lin12_to_srgb8`]).
    pub fn to_srgb8(&self) -> Image8 {
        Image8 {
            width: self.width,
            height: self.height,
            channels: Channels::Rgb,
            data: self
                .data
                .iter()
                .flat_map(|px| px.map(lin12_to_srgb8))
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_encode_hits_the_ends_and_the_mid_gray() {
        assert_eq!(lin12_to_srgb8(0), 0);
        assert_eq!(lin12_to_srgb8(4095), 255);
        assert_eq!(lin12_to_srgb8(u16::MAX), 255);
        // 18 % linear gray is about sRGB 118; 50 % linear is 188.
        assert_eq!(lin12_to_srgb8(737), 118);
        assert_eq!(lin12_to_srgb8(2048), 188);
        let codes: Vec<u8> = (0..=4095).map(lin12_to_srgb8).collect();
        assert!(codes.windows(2).all(|w| w[0] <= w[1]));
    }

    #[test]
    fn tone_srgb_table_matches_the_f64_formula() {
        // An independent f64 evaluation of IEC 61966-2-1, rounded to nearest.
        for v in 0..=softedge::LIN_MAX {
            let l = f64::from(v) / f64::from(softedge::LIN_MAX);
            let s = if l <= 0.003_130_8 {
                12.92 * l
            } else {
                1.055 * l.powf(1.0 / 2.4) - 0.055
            };
            let want = (s * 255.0).round() as u8;
            assert_eq!(lin12_to_srgb8(v), want, "lin12 {v}");
        }
    }

    #[test]
    fn emitted_light_is_shown_as_srgb() {
        assert_eq!(emitted_to_srgb8(0.0), 0);
        assert_eq!(emitted_to_srgb8(1.0), 255);
        assert_eq!(emitted_to_srgb8(7.0), 255);
        assert_eq!(emitted_to_srgb8(0.5), lin12_to_srgb8(2048));
    }

    #[test]
    fn upscale_repeats_pixels() {
        let img = Image8::from_raw(2, 1, Channels::Gray, vec![10, 20]).unwrap();
        let up = img.upscale(3);
        assert_eq!((up.width(), up.height()), (6, 3));
        for y in 0..3 {
            for x in 0..6 {
                assert_eq!(up.pixel(x, y), &[if x < 3 { 10 } else { 20 }]);
            }
        }
    }

    #[test]
    fn blit_and_fill_clip() {
        let mut dst = Image8::new(4, 4, Channels::Rgb, &[0, 0, 0]);
        let src = Image8::new(3, 3, Channels::Rgb, &[1, 2, 3]);
        dst.blit(&src, 2, 2);
        assert_eq!(dst.pixel(3, 3), &[1, 2, 3]);
        assert_eq!(dst.pixel(1, 3), &[0, 0, 0]);
        dst.fill_rect(-5, -5, 6, 6, &[9, 9, 9]);
        assert_eq!(dst.pixel(0, 0), &[9, 9, 9]);
        assert_eq!(dst.pixel(1, 1), &[0, 0, 0]);
        assert!(!dst.is_uniform());
    }

    #[test]
    fn crop_and_diff() {
        let mut a = LinImage::<1>::new(4, 3);
        a.set_row(1, &[[1], [2], [3], [4]]);
        let c = a.crop(1, 1, 10, 1);
        assert_eq!((c.width(), c.height()), (3, 1));
        assert_eq!(c.get(0, 0), &[2]);
        let b = LinImage::<1>::new(4, 3);
        let (d, n) = a.abs_diff(&b, 1000).unwrap();
        assert_eq!(n, 4);
        assert_eq!(d.get(3, 1), &[4000]);
        assert_eq!(d.get(2, 1), &[3000]);
        assert_eq!(d.get(0, 0), &[0]);
    }
}
