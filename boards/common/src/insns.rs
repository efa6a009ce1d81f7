//! Deterministic instruction counts from SysTick under `qemu -icount shift=0`.
//!
//! With `-icount shift=0`, QEMU advances virtual time by exactly 1 ns per
//! guest instruction, and SysTick (clocked from the core clock: 16 MHz on
//! `microbit`, 25 MHz on `mps2-an385`) counts virtual time. So
//! `instructions = ticks * insns_per_tick`, and the same binary gives the
//! same count on every run. The ratio is not assumed but calibrated at
//! start-up with a loop whose instruction count is exact ([`spin`]); at
//! 16 MHz a tick is 62.5 instructions, which is the resolution of a count.
//!
//! The counter is 24 bits: it runs with the largest reload and the SysTick
//! exception counts its wrap-arounds ([`on_wrap`], called from the board's
//! `SysTick` handler), so intervals of any length are measured.

use core::sync::atomic::{AtomicU32, Ordering};
use cortex_m::peripheral::{syst::SystClkSource, SYST};

/// Largest SysTick reload value (24 bits).
const RELOAD: u32 = (1 << 24) - 1;
/// Ticks between two wrap-arounds.
const PERIOD: u64 = RELOAD as u64 + 1;

/// Wrap-arounds so far. Only the exception writes it (single core, load and
/// store only, which thumbv6m has).
static WRAPS: AtomicU32 = AtomicU32::new(0);

/// Call from the board's `SysTick` exception handler.
pub fn on_wrap() {
    WRAPS.store(
        WRAPS.load(Ordering::Relaxed).wrapping_add(1),
        Ordering::Relaxed,
    );
}

/// Loop iterations of the two calibration runs: their difference, times the
/// loop's 2 instructions, is the calibration's instruction count.
const CAL_SHORT: u32 = 100_000;
const CAL_LONG: u32 = 1_100_000;
/// The calibrated ratio is rounded to `1 / SNAP` instruction per tick.
const SNAP: u64 = 16;

/// A running SysTick with its calibration.
pub struct Counter {
    /// Instructions per tick as the fraction `num / den`, reduced; `(0, 0)`
    /// when SysTick did not run.
    num: u64,
    den: u64,
}

impl Counter {
    /// Starts SysTick from the core clock with the wrap exception enabled,
    /// then calibrates.
    pub fn start(mut syst: SYST) -> Self {
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(RELOAD);
        syst.clear_current();
        syst.enable_interrupt();
        syst.enable_counter();
        // Until the first reload the current value reads 0, which
        // `ticks` would take for the end of a period: wait it out
        // (a few instructions; bounded, in case SysTick does not run).
        for _ in 0..1000 {
            if SYST::get_current() != 0 {
                break;
            }
        }
        let mut c = Self { num: 0, den: 0 };
        let short = c.measure(|| spin(CAL_SHORT));
        let long = c.measure(|| spin(CAL_LONG));
        let ticks = long.saturating_sub(short);
        // Snap to sixteenths of an instruction: the true ratio is
        // 1 GHz / f_systick, a multiple of 1/16 for every SysTick clock
        // dividing 16 GHz (16 MHz: 62.5, 25 MHz: 40), while the one-tick
        // quantisation of the two readings moves the measured ratio by
        // ratio / ticks < 1/1000 here, far under the 1/32 of rounding.
        // No ticks (SysTick not running): no calibration, counts read 0.
        let insns = 2 * u64::from(CAL_LONG - CAL_SHORT);
        if let Some(num) = (insns * SNAP + ticks / 2).checked_div(ticks) {
            let g = gcd(num, SNAP);
            c.num = num / g;
            c.den = SNAP / g;
        }
        c
    }

    /// Ticks since start, wrap-arounds included.
    pub fn ticks(&self) -> u64 {
        loop {
            let w0 = WRAPS.load(Ordering::Relaxed);
            let v = SYST::get_current();
            let w1 = WRAPS.load(Ordering::Relaxed);
            // A wrap between the two loads: the value may belong to either
            // period, read again.
            if w0 == w1 {
                return u64::from(w0) * PERIOD + u64::from(RELOAD - v);
            }
        }
    }

    /// Ticks taken by `f`.
    pub fn measure(&self, f: impl FnOnce()) -> u64 {
        let t0 = self.ticks();
        f();
        self.ticks().saturating_sub(t0)
    }

    /// Instructions in `ticks`, rounded to nearest; 0 without a calibration.
    pub fn insns(&self, ticks: u64) -> u64 {
        (ticks * self.num + self.den / 2)
            .checked_div(self.den)
            .unwrap_or(0)
    }

    /// The calibration, `(num, den)` instructions per tick.
    pub fn insns_per_tick(&self) -> (u64, u64) {
        (self.num, self.den)
    }
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

/// Runs exactly `2 * n` instructions (`subs` and `bne` per iteration) for
/// `n >= 1`, plus the call.
#[inline(never)]
pub fn spin(n: u32) {
    // SAFETY: touches only r0 and the flags; no memory, no stack.
    unsafe {
        core::arch::asm!(
            "2:",
            "subs r0, #1",
            "bne 2b",
            inout("r0") n.max(1) => _,
            options(nomem, nostack),
        );
    }
}
