//! Renders every softedge reference scene as Cortex-M0 code (thumbv6m, in
//! the 16 KiB of RAM of the BBC micro:bit's nRF51; run on QEMU's MPS2
//! AN385, whose code memory holds it: see `memory.x`) and prints the
//! CRCs, instruction counts and stack depth over semihosting (see
//! `softedge-board-common`). `cargo run --release` runs it in QEMU.
#![no_std]
#![no_main]

use cortex_m_rt::{entry, exception};
use softedge_board_common as fw;
use softedge_refscenes::{Buffers, ACC_LEN, COVERED_LEN, COVER_LEN, DEPTH_LEN};

#[entry]
fn main() -> ! {
    // cortex-m-rt turns these into `&'static mut`, safely (entry runs once).
    static mut ACC: [i32; ACC_LEN] = [0; ACC_LEN];
    static mut COVER: [i32; COVER_LEN] = [0; COVER_LEN];
    static mut DEPTH: [u16; DEPTH_LEN] = [0; DEPTH_LEN];
    static mut COVERED: [u16; COVERED_LEN] = [0; COVERED_LEN];
    fw::stack::paint();
    let Some(core) = cortex_m::Peripherals::take() else {
        fw::exit(false)
    };
    let counter = fw::insns::Counter::start(core.SYST);
    let mut bufs = Buffers {
        acc: ACC,
        cover: COVER,
        depth: DEPTH,
        covered: COVERED,
    };
    fw::run(&mut bufs, &counter)
}

#[exception]
fn SysTick() {
    fw::insns::on_wrap();
}
