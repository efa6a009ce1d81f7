//! Firmware shared by the QEMU boards (`qemu-m0`, `qemu-m3`).
//!
//! [`run`] renders every reference scene of `softedge-refscenes` into the
//! board's static band buffers and prints, over semihosting,
//!
//! ```text
//! crc <scene> <crc32, 8 hex digits>     one per scene, same format as the host
//! insns <scene> <n>                     instructions per scene (SysTick, see [`insns`])
//! insns_per_tick <num>/<den>            the calibration behind those counts
//! stack_bytes <n>                       deepest stack use seen (see [`stack`])
//! stack_margin_bytes <n>                 untouched RAM left; under 512 fails the run
//! ```
//!
//! then ends QEMU with exit status 0, or 1 when a scene failed. Output is
//! written without `core::fmt`, so the `no-panic` build checks core's
//! rendering code and not the formatting machinery.
#![no_std]

pub mod insns;
mod out;
pub mod stack;

use cortex_m_semihosting::debug;
use softedge_refscenes::{render_crc, Buffers, SCENES};

pub use out::Line;

/// Renders and reports every scene, then exits QEMU.
///
/// `bufs` are the board's band buffers, sized
/// [`ACC_LEN`](softedge_refscenes::ACC_LEN),
/// [`COVER_LEN`](softedge_refscenes::COVER_LEN) and
/// [`DEPTH_LEN`](softedge_refscenes::DEPTH_LEN) and
/// [`COVERED_LEN`](softedge_refscenes::COVERED_LEN). `counter` is the
/// instruction counter, already started.
pub fn run(bufs: &mut Buffers<'_>, counter: &insns::Counter) -> ! {
    let mut ok = true;
    let mut counts = [0u64; SCENES.len()];
    for (scene, count) in SCENES.iter().zip(counts.iter_mut()) {
        let t0 = counter.ticks();
        let result = render_crc(scene, bufs);
        let t1 = counter.ticks();
        *count = counter.insns(t1.saturating_sub(t0));
        match result {
            Ok(crc) => Line::new()
                .text("crc ")
                .text(scene.name)
                .text(" ")
                .hex8(crc)
                .print(),
            Err(_) => {
                ok = false;
                Line::new().text("error ").text(scene.name).print()
            }
        }
    }
    for (scene, &n) in SCENES.iter().zip(counts.iter()) {
        Line::new()
            .text("insns ")
            .text(scene.name)
            .text(" ")
            .dec(n)
            .print();
    }
    let (num, den) = counter.insns_per_tick();
    Line::new()
        .text("insns_per_tick ")
        .dec(num)
        .text("/")
        .dec(den)
        .print();
    Line::new()
        .text("stack_bytes ")
        .dec(stack::used_bytes() as u64)
        .print();
    let margin = stack::margin_bytes();
    Line::new()
        .text("stack_margin_bytes ")
        .dec(margin as u64)
        .print();
    if margin < stack::MIN_MARGIN_BYTES {
        Line::new()
            .text("error stack too close to the statics")
            .print();
    }
    exit(ok && margin >= stack::MIN_MARGIN_BYTES)
}

/// Ends QEMU: status 0 when `ok`, 1 otherwise.
pub fn exit(ok: bool) -> ! {
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    // Only reached without a debugger/QEMU to end us.
    loop {
        cortex_m::asm::wfi();
    }
}

#[cfg(not(feature = "no-panic"))]
#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    // Report where, then fail the run so CI never hangs on a panic.
    let mut line = Line::new().text("panic");
    if let Some(loc) = info.location() {
        line = line
            .text(" ")
            .text(loc.file())
            .text(":")
            .dec(u64::from(loc.line()));
    }
    line.print();
    exit(false)
}

#[cfg(feature = "no-panic")]
#[panic_handler]
fn panic(_info: &core::panic::PanicInfo) -> ! {
    extern "Rust" {
        /// Defined nowhere: if any panic survives optimisation, the link
        /// fails and names the function that could panic.
        fn softedge_no_panic_build_found_a_reachable_panic() -> !;
    }
    // SAFETY: never executed in a binary that links (see above).
    unsafe { softedge_no_panic_build_found_a_reachable_panic() }
}
