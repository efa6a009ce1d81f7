//! Stack high-water mark: the free RAM between the statics and the stack is
//! painted with a pattern at start-up; after the work, the lowest word that
//! no longer holds it marks the deepest the stack has been.
//!
//! Uses the symbols of cortex-m-rt's `link.x`: `__sheap` (end of the
//! statics) and `_stack_start` (initial stack pointer, top of RAM).

/// What painted words hold; a stack word equal to it by chance makes the
/// figure low by that word at most (it is not at the deepest point unless
/// every word below it was also untouched).
const PAINT: u32 = 0x5AA5_C33C;
/// Words left unpainted below the current stack pointer, for the painter's
/// own frame.
const MARGIN_WORDS: usize = 16;

extern "C" {
    static __sheap: u32;
    static _stack_start: u32;
}

fn bounds() -> (*mut u32, *mut u32) {
    // Only the addresses of the linker symbols are taken, never their values.
    (
        core::ptr::addr_of!(__sheap) as *mut u32,
        core::ptr::addr_of!(_stack_start) as *mut u32,
    )
}

/// Paints the free RAM below the current stack pointer.
#[inline(never)]
pub fn paint() {
    let (low, _) = bounds();
    let sp = cortex_m::register::msp::read() as usize;
    let end = (sp & !3).saturating_sub(MARGIN_WORDS * 4) as *mut u32;
    let mut p = low;
    while p < end {
        // SAFETY: between the end of the statics and below the live stack:
        // RAM nothing else uses.
        unsafe {
            p.write_volatile(PAINT);
            p = p.add(1);
        }
    }
}

/// Bytes of painted RAM the stack never reached (since [`paint`]): the
/// margin left between the deepest stack and the statics.
pub fn margin_bytes() -> usize {
    let (low, top) = bounds();
    (top as usize - low as usize).saturating_sub(used_bytes())
}

/// A run whose stack came closer than this to the statics fails: the stack
/// may already have overwritten them (a 16 KiB Cortex-M0 leaves little room).
pub const MIN_MARGIN_BYTES: usize = 512;

/// Bytes of stack used so far (since [`paint`]).
pub fn used_bytes() -> usize {
    let (low, top) = bounds();
    let mut p = low;
    // SAFETY: reads RAM between the statics and the top of the stack.
    while p < top && unsafe { p.read_volatile() } == PAINT {
        p = unsafe { p.add(1) };
    }
    top as usize - p as usize
}

/// Bytes of stack in use at the caller (from the top of RAM to the
/// current stack pointer): subtracted from [`used_bytes`] after a call, it
/// leaves what the call itself needed below its caller's frame.
#[inline(never)]
pub fn depth_here() -> usize {
    let (_, top) = bounds();
    (top as usize).saturating_sub(cortex_m::register::msp::read() as usize)
}
