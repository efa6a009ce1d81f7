//! RAM of the band buffers a firmware allocates, from core's own size
//! functions (`softedge-sim memory`).

use softedge::hsr::{DepthBuffer, DepthTriangle};
use softedge::BandBuffer;

/// Bytes of the buffers of one band.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BandMemory {
    /// Rows per band.
    pub rows: u16,
    /// The accumulator: one `i32` per channel per pixel.
    pub acc: usize,
    /// The cover scratch: one `i32` per pixel plus four per row, and the
    /// pixels' tags, a byte each (whole words per row).
    pub cover: usize,
    /// The z-buffer's depths: one `u16` per pixel.
    pub depth: usize,
    /// The z-buffer's coverage counts and sample masks: two `u16`s per pixel.
    pub covered: usize,
}

impl BandMemory {
    /// Without hidden-surface removal.
    pub fn plain(&self) -> usize {
        self.acc + self.cover
    }

    /// With the z-buffer.
    pub fn zbuffer(&self) -> usize {
        self.plain() + self.depth + self.covered
    }
}

/// The buffers of a band of `rows` rows, `width` pixels wide, `channels`
/// channels (1 or 3; anything else counts as 3).
pub fn band_memory(width: u16, channels: usize, rows: u16) -> BandMemory {
    let acc = if channels == 1 {
        BandBuffer::<1>::acc_len(width, rows)
    } else {
        BandBuffer::<3>::acc_len(width, rows)
    };
    BandMemory {
        rows,
        acc: 4 * acc,
        cover: 4 * BandBuffer::<1>::cover_len(width, rows),
        depth: 2 * DepthBuffer::len(width, rows),
        covered: 2 * DepthBuffer::covered_len(width, rows),
    }
}

/// Bytes of one stored depth triangle (a frame sorted front to back keeps
/// one per visible triangle).
pub fn depth_triangle_bytes(channels: usize) -> usize {
    if channels == 1 {
        core::mem::size_of::<DepthTriangle<1>>()
    } else {
        core::mem::size_of::<DepthTriangle<3>>()
    }
}

/// The table `softedge-sim memory` prints.
pub fn report(width: u16, height: u16, channels: usize, rows: &[u16], triangles: usize) -> String {
    let mut out = format!(
        "band RAM for {width}x{height}, {channels} channel(s) accumulated \
         (an Rgb565 display accumulates 3), bytes:\n\
         rows      acc    cover    depth  covered    plain  z-buffer\n"
    );
    for &r in rows {
        let m = band_memory(width, channels, r.clamp(1, height.max(1)));
        out += &format!(
            "{:>4} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9}\n",
            m.rows,
            m.acc,
            m.cover,
            m.depth,
            m.covered,
            m.plain(),
            m.zbuffer()
        );
    }
    let per = depth_triangle_bytes(channels);
    out += &format!(
        "a frame's depth triangles, sorted once per frame: {per} bytes each, {} for {triangles}\n",
        per * triangles
    );
    let slot = if channels == 1 {
        softedge::canvas::WalkSlot::<1>::SIZE
    } else {
        softedge::canvas::WalkSlot::<3>::SIZE
    };
    out += &format!(
        "walk cache (optional, caller-provided, not in the totals above): {slot} bytes a slot \
         (an edge's walk state or a Gouraud plane carried to the next band)\n"
    );
    let listed = if channels == 1 {
        softedge::canvas::ListedTriangle::<1>::SIZE
    } else {
        softedge::canvas::ListedTriangle::<3>::SIZE
    };
    out += &format!(
        "triangle list (optional, caller-provided, not in the totals above): {listed} bytes \
         a triangle, {} for {triangles} (a frame's triangles recorded once, drawn in every band)\n",
        listed * triangles
    );
    let dma = if channels == 1 { 1 } else { 2 };
    out += &format!(
        "a firmware that streams each band to its display by DMA adds one band of display codes: \
         {} bytes a row ({dma} a pixel; {} at {} rows)\n",
        usize::from(width) * dma,
        usize::from(width) * dma * usize::from(rows.first().copied().unwrap_or(1)),
        rows.first().copied().unwrap_or(1),
    );
    out += &format!(
        "stack: the dial scene's frame (boards/bench-m0, Cortex-M0, 240x240 Rgb565, 16-row bands) \
         needs {DIAL_FRAME_STACK} bytes below its caller (`dial_ram` lines of bash boards/bench-m0.sh); \
         its whole frame then needs, with no walk cache, {} bytes in all\n",
        band_memory(240, 3, 16).plain() + 240 * 16 * 2 + DIAL_FRAME_STACK
    );
    out
}

/// The stack of the dial scene's whole frame below its caller, measured on
/// the Cortex-M0 (QEMU, `bash boards/bench-m0.sh`, its `dial_ram` lines).
pub const DIAL_FRAME_STACK: usize = 8_680;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb565_240_at_16_rows() {
        let m = band_memory(240, 3, 16);
        assert_eq!(
            (m.acc, m.cover, m.depth, m.covered),
            (46_080, 19_456, 7_680, 15_360)
        );
        assert_eq!(m.zbuffer(), 88_576);
        let one = band_memory(240, 3, 1);
        assert_eq!(one.zbuffer(), 2_880 + 1_216 + 480 + 960);
    }
}
