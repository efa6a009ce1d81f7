//! CRC-32 as in IEEE 802.3 (also zlib, PNG): the fingerprint of a scene's
//! display byte stream.
//!
//! Parameters (the "CRC-32/ISO-HDLC" of the CRC catalogues): polynomial
//! `0x04C11DB7`, processed bit-reflected (least significant bit first), so
//! the register shifts right and XORs with the reflected polynomial
//! [`POLY_REFLECTED`] `= 0xEDB88320`; initial register `0xFFFFFFFF`; the
//! result XORed with `0xFFFFFFFF`. Check value:
//! `crc32(b"123456789") == 0xCBF43926`.
//!
//! Byte-wise, table-driven: entry `n` of [`TABLE`] is the register after
//! eight reflected shift/XOR steps starting from `n`, so one byte costs one
//! XOR, one look-up and one shift. The table is computed by a `const fn`
//! and lives in flash (1 KiB).

/// The IEEE 802.3 polynomial `0x04C11DB7`, bit-reflected.
pub const POLY_REFLECTED: u32 = 0x04C1_1DB7_u32.reverse_bits();

/// Initial register value, and the value XORed into the result.
const ALL_ONES: u32 = u32::MAX;

/// `TABLE[n]`: eight reflected steps of the register starting from `n`.
pub const TABLE: [u32; 256] = make_table();

const fn make_table() -> [u32; 256] {
    let mut table = [0u32; 256];
    let mut n = 0;
    while n < 256 {
        let mut r = n as u32;
        let mut bit = 0;
        while bit < 8 {
            r = if r & 1 == 1 {
                (r >> 1) ^ POLY_REFLECTED
            } else {
                r >> 1
            };
            bit += 1;
        }
        table[n] = r;
        n += 1;
    }
    table
}

/// A running CRC-32 (IEEE 802.3).
///
/// ```
/// use softedge_refscenes::Crc32;
/// let mut crc = Crc32::new();
/// crc.update(b"1234");
/// crc.update(b"56789");
/// assert_eq!(crc.finish(), 0xCBF4_3926);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Crc32 {
    register: u32,
}

impl Default for Crc32 {
    fn default() -> Self {
        Self::new()
    }
}

impl Crc32 {
    /// A CRC over no bytes yet.
    pub const fn new() -> Self {
        Self { register: ALL_ONES }
    }

    /// Feeds `bytes`.
    pub fn update(&mut self, bytes: &[u8]) {
        for &b in bytes {
            let k = (self.register ^ u32::from(b)) as u8;
            self.register = (self.register >> 8) ^ TABLE[usize::from(k)];
        }
    }

    /// The CRC of every byte fed so far.
    pub const fn finish(&self) -> u32 {
        self.register ^ ALL_ONES
    }
}

/// The CRC-32 of `bytes` in one call.
pub fn crc32(bytes: &[u8]) -> u32 {
    let mut c = Crc32::new();
    c.update(bytes);
    c.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_check_value() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn empty_input_is_zero_and_reflected_poly_matches_the_standard() {
        assert_eq!(crc32(b""), 0);
        assert_eq!(POLY_REFLECTED, 0xEDB8_8320);
    }

    /// The table agrees with the bit-at-a-time definition.
    #[test]
    fn table_equals_bitwise_crc() {
        let data = [0u8, 1, 0x7F, 0x80, 0xFF, 0x5A, 42];
        let mut r = ALL_ONES;
        for &b in &data {
            r ^= u32::from(b);
            for _ in 0..8 {
                r = if r & 1 == 1 {
                    (r >> 1) ^ 0xEDB8_8320
                } else {
                    r >> 1
                };
            }
        }
        assert_eq!(crc32(&data), r ^ ALL_ONES);
    }
}
