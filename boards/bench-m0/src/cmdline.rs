//! The run's selection, from the command line QEMU hands the firmware.
//!
//! Semihosting's `SYS_GET_CMDLINE` returns, when `-semihosting-config`
//! gives no `arg=`, the kernel's path followed by QEMU's `-append` string.
//! `boards/profile-m0.sh` runs
//! `qemu-system-arm ... -kernel ELF -append "<renderer> <workload> [rows]"`
//! so that the firmware measures that one frame (the whole workload, or
//! the screen in bands of `rows`) and the profiler counts little else; a
//! plain `cargo run` passes no words and runs everything.

use cortex_m_semihosting::{nr, syscall1};

/// Capacity of the command line read; a longer one selects nothing
/// (the full run).
const CAP: usize = 256;

/// The words after the kernel path, at most three of them.
pub struct Selection {
    buf: [u8; CAP],
    words: [(usize, usize); 3],
    n: usize,
}

impl Selection {
    /// Reads the command line (an empty selection when semihosting fails).
    pub fn read() -> Self {
        let mut sel = Self {
            buf: [0; CAP],
            words: [(0, 0); 3],
            n: 0,
        };
        let mut block = [sel.buf.as_mut_ptr() as usize, CAP];
        // SAFETY: SYS_GET_CMDLINE's parameter block is {buffer, length}; the
        // host writes at most `length` bytes into the buffer and the length
        // used back into the block, both owned here and alive for the call.
        let status = unsafe { syscall1(nr::GET_CMDLINE, block.as_mut_ptr() as usize) };
        let len = block[1].min(CAP);
        if status != 0 {
            return sel;
        }
        let mut k = 0;
        let mut seen = 0;
        while k < len {
            while k < len && sel.buf[k] == b' ' {
                k += 1;
            }
            let start = k;
            while k < len && sel.buf[k] != b' ' && sel.buf[k] != 0 {
                k += 1;
            }
            if k == start {
                break;
            }
            // The first word is the kernel's path.
            if seen > 0 && sel.n < sel.words.len() {
                sel.words[sel.n] = (start, k);
                sel.n += 1;
            }
            seen += 1;
        }
        sel
    }

    fn word(&self, i: usize) -> Option<&[u8]> {
        let &(a, b) = self.words.get(i).filter(|_| i < self.n)?;
        self.buf.get(a..b)
    }

    /// Whether anything was selected.
    pub fn is_some(&self) -> bool {
        self.n > 0
    }

    /// Whether the frame of `renderer` on `workload` with `tris` triangles
    /// (of the workload's `all`) in bands of `rows` is to be run.
    pub fn wants(
        &self,
        renderer: &str,
        workload: &str,
        tris: usize,
        all: usize,
        rows: u16,
    ) -> bool {
        if !self.is_some() {
            return true;
        }
        let rows_ok = match self.word(2) {
            None => true,
            Some(w) => parse_u16(w) == Some(rows),
        };
        self.word(0) == Some(renderer.as_bytes())
            && self.word(1) == Some(workload.as_bytes())
            && tris == all
            && rows_ok
    }
}

fn parse_u16(w: &[u8]) -> Option<u16> {
    let mut v: u16 = 0;
    for &d in w {
        if !d.is_ascii_digit() {
            return None;
        }
        v = v.checked_mul(10)?.checked_add(u16::from(d - b'0'))?;
    }
    Some(v)
}
