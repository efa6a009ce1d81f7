//! The display byte stream: what a scene would send to its display.
//!
//! Takes resolved rows of linear 12-bit values (from
//! [`BandBuffer::resolve_row`](softedge::BandBuffer::resolve_row)), gives
//! bytes to a [`ByteSink`]. Until the tone stage (γ table, Rgb565 / Gray8 /
//! BinaryColor with dithering) lands, the stream is the linear values
//! themselves: per pixel in row-major order, each channel's 12-bit value as
//! two bytes, big-endian.
//!
//! [`encode_row`] is the only place that decides the byte format: switching
//! the boards and the host to the tone stage's display bytes is a change of
//! that one function (it gets the frame row `y` and the [`Scene`] so that a
//! position-dependent dither and a per-scene pixel format fit its
//! signature).

use crate::Scene;

/// Where display bytes go (a CRC, a display driver, a file).
pub trait ByteSink {
    /// Takes the next bytes of the stream.
    fn write(&mut self, bytes: &[u8]);
}

impl ByteSink for crate::Crc32 {
    fn write(&mut self, bytes: &[u8]) {
        self.update(bytes);
    }
}

/// Encodes frame row `y` of `scene`, whose resolved linear 12-bit pixels
/// are `row`, into display bytes.
///
/// Now: each channel's `lin12` as 2 bytes, big-endian, pixel after pixel.
pub fn encode_row<const C: usize>(
    _scene: &Scene,
    _y: u16,
    row: &[[u16; C]],
    sink: &mut impl ByteSink,
) {
    for px in row {
        for &lin12 in px {
            sink.write(&lin12.to_be_bytes());
        }
    }
}
