//! Semihosting output lines built without `core::fmt`.

use cortex_m_semihosting::hio;

/// Capacity of one line; longer lines are cut (never a panic).
const CAP: usize = 96;

/// One output line, assembled in a fixed buffer.
pub struct Line {
    buf: [u8; CAP],
    len: usize,
}

impl Default for Line {
    fn default() -> Self {
        Self::new()
    }
}

impl Line {
    /// An empty line.
    pub const fn new() -> Self {
        Self {
            buf: [0; CAP],
            len: 0,
        }
    }

    /// Appends bytes, cutting at the capacity.
    fn push(mut self, bytes: &[u8]) -> Self {
        if let Some(free) = self.buf.get_mut(self.len..) {
            for (slot, &b) in free.iter_mut().zip(bytes) {
                *slot = b;
                self.len += 1;
            }
        }
        self
    }

    /// Appends text.
    pub fn text(self, s: &str) -> Self {
        self.push(s.as_bytes())
    }

    /// Appends `v` as 8 lower-case hex digits.
    pub fn hex8(self, v: u32) -> Self {
        let mut digits = [0u8; 8];
        for (k, d) in digits.iter_mut().enumerate() {
            let nibble = (v >> (28 - 4 * k as u32)) & 0xF;
            *d = b"0123456789abcdef"[nibble as usize];
        }
        self.push(&digits)
    }

    /// Appends `v` in decimal.
    pub fn dec(self, mut v: u64) -> Self {
        let mut digits = [0u8; 20];
        let mut n = 0;
        for d in digits.iter_mut().rev() {
            *d = b'0' + (v % 10) as u8;
            v /= 10;
            n += 1;
            if v == 0 {
                break;
            }
        }
        let start = digits.len() - n;
        self.push(digits.get(start..).unwrap_or(&[]))
    }

    /// Writes the line and a newline to the host's stdout (errors ignored:
    /// there is nowhere to report them).
    pub fn print(self) {
        let mut me = self.push(b"\n");
        if me.len == CAP {
            if let Some(last) = me.buf.last_mut() {
                *last = b'\n';
            }
        }
        if let Ok(mut stdout) = hio::hstdout() {
            let _ = stdout.write_all(me.buf.get(..me.len).unwrap_or(&[]));
        }
    }
}
