//! Units every stage shares: linear intensity, coverage, the
//! accumulator's fixed point and its one rounding.
//!
//! Kept below the stages (geometry, edges, band, compose, tone) so that none
//! of them owns a unit the others depend on.

/// Coverage of one whole pixel: `2^16`.
///
/// Edge walks report signed areas in these units (each an exact floor, so a
/// pixel cut by a few edges is within a few 1/65536 px of its true area),
/// the band's scratch sums them, and the accumulator holds
/// `lin12 * COVER_ONE` per channel: a fully covered pixel of intensity 4095
/// is `4095 * 2^16 < 2^28`, and rounding to 12 bits happens once, when the
/// band is resolved. The fine unit matters for small shapes: a disc of
/// radius 1/2 px has some 30 edge cells, and their floors, at 1/4096 px
/// each, would lose up to 1 % of its area; at 1/65536 px, 0.06 %.
pub const COVER_ONE: i32 = 1 << COVER_BITS;
/// `log2(COVER_ONE)`.
pub const COVER_BITS: u32 = 16;

/// Most vertices a [`Polygon`](crate::raster::Polygon) may have (seed
/// 000's primitives; paths and shapes have no such limit).
pub const MAX_POLYGON_VERTICES: usize = 64;

/// Largest linear intensity: 12 bits.
pub const LIN_MAX: u16 = 4095;

/// Rounds an accumulated value to linear 12 bits: the pipeline's one
/// rounding, to nearest (halves up), then clamped to `0..=4095`.
///
/// (`(acc + 2^15) >> 16` in `u32`, with the sign tested only out of
/// range, is the same function, but LLVM turns its clamp into selects
/// computed for every pixel: 20 more Cortex-M0 instructions a pixel in
/// the flush.)
#[inline]
pub(crate) fn resolve(acc: i32) -> u16 {
    let v = ((acc >> (COVER_BITS - 1)) + 1) >> 1;
    // One unsigned compare in the common case.
    if v as u32 <= u32::from(LIN_MAX) {
        v as u16
    } else if v < 0 {
        0
    } else {
        LIN_MAX
    }
}

/// [`resolve`] with the clamp out of line and cold: the same function.
/// The one-channel flush takes it (the Cortex-M0's gray screen 5 % fewer
/// instructions: one compare and a branch a pixel); the three-channel
/// flush keeps [`resolve`] (this form cost its frames 0.6 to 1 %).
#[inline]
pub(crate) fn resolve_split(acc: i32) -> u16 {
    let v = ((acc >> (COVER_BITS - 1)) + 1) >> 1;
    if v as u32 <= u32::from(LIN_MAX) {
        v as u16
    } else {
        clamped(v)
    }
}

/// `v` outside `0..=4095` clamped to it.
#[cold]
#[inline(never)]
fn clamped(v: i32) -> u16 {
    if v < 0 {
        0
    } else {
        LIN_MAX
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rounding in exact arithmetic: `floor(acc / 2^16 + 1/2)`,
    /// clamped.
    fn reference(acc: i32) -> u16 {
        let v = (i64::from(acc) + (1 << 15)).div_euclid(1 << 16);
        v.clamp(0, i64::from(LIN_MAX)) as u16
    }

    #[test]
    fn resolve_rounds_halves_up_and_clamps_over_the_whole_range() {
        let check = |acc: i32| {
            assert_eq!(resolve(acc), reference(acc), "acc = {acc}");
            assert_eq!(resolve_split(acc), reference(acc), "split, acc = {acc}");
        };
        for acc in [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX] {
            check(acc);
        }
        let half = 1 << 15;
        for k in [-2, -1, 0, 1, 2, 4094, 4095, 4096, 4097] {
            for d in [
                -half - 1,
                -half,
                -half + 1,
                -1,
                0,
                1,
                half - 1,
                half,
                half + 1,
            ] {
                check(k * COVER_ONE + d);
            }
        }
        // And a walk over all of i32 in steps that are not a power of two.
        let mut a = i64::from(i32::MIN);
        while a <= i64::from(i32::MAX) {
            check(a as i32);
            a += 65_537 * 3 + 7;
        }
    }
}
