//! PCG32, the random number generator of the workloads.
//!
//! M. E. O'Neill's permuted congruential generator, the `XSH RR 64/32`
//! member ("PCG: A Family of Simple Fast Space-Efficient Statistically Good
//! Algorithms for Random Number Generation", 2014): a 64-bit linear
//! congruential state
//!
//! ```text
//! state' = state * 6364136223846793005 + inc      (mod 2^64, inc odd)
//! ```
//!
//! whose output is the old state's high bits, xor-shifted and rotated:
//! `rotr32(((s >> 18) ^ s) >> 27, s >> 59)`. Seeding follows the reference
//! `pcg32_srandom(initstate, initseq)`: `inc = 2 initseq + 1`, one step from
//! 0, add `initstate`, one step. So `Pcg32::new(42, 54)` gives the
//! reference demo's first outputs `0xa15c02b7, 0x7b47f409, ...` (tested).
//!
//! Everything is a `const fn` with wrapping integer arithmetic: the
//! workloads are generated at compile time and are the same bytes on every
//! target.

/// The LCG multiplier of PCG32 (Knuth's MMIX constant).
const MULTIPLIER: u64 = 6_364_136_223_846_793_005;

/// A PCG32 (`XSH RR 64/32`) stream.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pcg32 {
    state: u64,
    inc: u64,
}

impl Pcg32 {
    /// The stream `initseq` started at `initstate`, as the reference
    /// `pcg32_srandom` seeds it.
    pub const fn new(initstate: u64, initseq: u64) -> Self {
        let mut rng = Self {
            state: 0,
            inc: (initseq << 1) | 1,
        };
        rng.step();
        rng.state = rng.state.wrapping_add(initstate);
        rng.step();
        rng
    }

    const fn step(&mut self) {
        self.state = self.state.wrapping_mul(MULTIPLIER).wrapping_add(self.inc);
    }

    /// The next 32 uniformly distributed bits.
    pub const fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.step();
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// A uniform integer in `0..n` (`n >= 1`; 0 for `n == 0`), without
    /// modulo bias: outputs below `2^32 mod n` are drawn again, so the
    /// accepted range is a whole number of copies of `0..n`.
    pub const fn below(&mut self, n: u32) -> u32 {
        if n == 0 {
            return 0;
        }
        let threshold = n.wrapping_neg() % n;
        loop {
            let r = self.next_u32();
            if r >= threshold {
                return r % n;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_reference_demo_stream() {
        // pcg32-demo of the reference C library, pcg32_srandom(42, 54).
        let mut rng = Pcg32::new(42, 54);
        let expected = [
            0xa15c_02b7,
            0x7b47_f409,
            0xba1d_3330,
            0x83d2_f293,
            0xbfa4_784b,
            0xcbed_606e,
        ];
        for e in expected {
            assert_eq!(rng.next_u32(), e);
        }
    }

    #[test]
    fn same_seed_same_stream_other_seed_other_stream() {
        let (mut a, mut b, mut c) = (Pcg32::new(7, 1), Pcg32::new(7, 1), Pcg32::new(8, 1));
        let mut differs = false;
        for _ in 0..1000 {
            let x = a.next_u32();
            assert_eq!(x, b.next_u32());
            differs |= x != c.next_u32();
        }
        assert!(differs);
    }

    #[test]
    fn below_stays_in_range_and_hits_every_value() {
        let mut rng = Pcg32::new(1, 2);
        let mut seen = [0u32; 19];
        for _ in 0..19_000 {
            let v = rng.below(19) as usize;
            seen[v] += 1;
        }
        // Each value about 1000 times (binomial sd ~31).
        assert!(seen.iter().all(|&n| (850..1150).contains(&n)), "{seen:?}");
        assert_eq!(rng.below(1), 0);
        assert_eq!(rng.below(0), 0);
    }
}
