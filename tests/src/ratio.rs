//! A small exact rational over `i128`: every operation is checked, so an
//! overflow panics (in every build profile) instead of giving a wrong
//! answer. Fast enough for debug-build property tests, where a big-integer
//! rational allocates on every operation.
//!
//! The reference's numbers stay small: vertices are below `2^16`
//! sub-pixels, so a clip point's coordinates are fractions with
//! denominators below `2^34`, and sums of a pixel's few pieces stay far
//! below `2^127`.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

/// `n / d` in lowest terms, `d > 0`.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Ratio {
    n: i128,
    d: i128,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

fn mul(a: i128, b: i128) -> i128 {
    a.checked_mul(b).expect("exact rational overflow (mul)")
}

fn add(a: i128, b: i128) -> i128 {
    a.checked_add(b).expect("exact rational overflow (add)")
}

impl Ratio {
    /// `n / d`; panics when `d == 0`.
    pub fn new(n: i128, d: i128) -> Self {
        assert!(d != 0, "zero denominator");
        let g = gcd(n, d).max(1);
        let s = if d < 0 { -1 } else { 1 };
        Self {
            n: s * n / g,
            d: s * d / g,
        }
    }
    /// An integer.
    pub const fn int(n: i128) -> Self {
        Self { n, d: 1 }
    }
    /// Numerator (lowest terms).
    pub fn numer(&self) -> i128 {
        self.n
    }
    /// Denominator (lowest terms, positive).
    pub fn denom(&self) -> i128 {
        self.d
    }
    /// Absolute value.
    pub fn abs(&self) -> Self {
        Self {
            n: self.n.abs(),
            d: self.d,
        }
    }
    /// `< 0`.
    pub fn is_negative(&self) -> bool {
        self.n < 0
    }
    /// `== 0`.
    pub fn is_zero(&self) -> bool {
        self.n == 0
    }
    /// Largest integer `<= self`.
    pub fn floor(&self) -> i128 {
        self.n.div_euclid(self.d)
    }
    /// Nearest `f64` (reporting only).
    pub fn to_f64(&self) -> f64 {
        self.n as f64 / self.d as f64
    }
}

impl fmt::Debug for Ratio {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl fmt::Display for Ratio {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.d == 1 {
            write!(f, "{}", self.n)
        } else {
            write!(f, "{}/{} (~{:.4})", self.n, self.d, self.to_f64())
        }
    }
}

impl Ord for Ratio {
    fn cmp(&self, o: &Self) -> Ordering {
        mul(self.n, o.d).cmp(&mul(o.n, self.d))
    }
}

impl PartialOrd for Ratio {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Add for Ratio {
    type Output = Ratio;
    fn add(self, o: Ratio) -> Ratio {
        let g = gcd(self.d, o.d);
        let (a, b) = (self.d / g, o.d / g);
        Ratio::new(add(mul(self.n, b), mul(o.n, a)), mul(mul(a, b), g))
    }
}

impl Neg for Ratio {
    type Output = Ratio;
    fn neg(self) -> Ratio {
        Ratio {
            n: self.n.checked_neg().expect("exact rational overflow (neg)"),
            d: self.d,
        }
    }
}

impl Sub for Ratio {
    type Output = Ratio;
    fn sub(self, o: Ratio) -> Ratio {
        self + (-o)
    }
}

impl Mul for Ratio {
    type Output = Ratio;
    fn mul(self, o: Ratio) -> Ratio {
        // Cross-reduce first so the products stay small.
        let g1 = gcd(self.n, o.d).max(1);
        let g2 = gcd(o.n, self.d).max(1);
        Ratio::new(mul(self.n / g1, o.n / g2), mul(self.d / g2, o.d / g1))
    }
}

impl Div for Ratio {
    type Output = Ratio;
    fn div(self, o: Ratio) -> Ratio {
        assert!(o.n != 0, "division by zero");
        self * Ratio::new(o.d, o.n)
    }
}

macro_rules! by_ref {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr<&Ratio> for Ratio {
            type Output = Ratio;
            fn $f(self, o: &Ratio) -> Ratio { $tr::$f(self, *o) }
        }
        impl $tr<Ratio> for &Ratio {
            type Output = Ratio;
            fn $f(self, o: Ratio) -> Ratio { $tr::$f(*self, o) }
        }
        impl $tr<&Ratio> for &Ratio {
            type Output = Ratio;
            fn $f(self, o: &Ratio) -> Ratio { $tr::$f(*self, *o) }
        }
    )*};
}
by_ref!(Add add, Sub sub, Mul mul, Div div);

impl AddAssign for Ratio {
    fn add_assign(&mut self, o: Ratio) {
        *self = *self + o;
    }
}

impl SubAssign for Ratio {
    fn sub_assign(&mut self, o: Ratio) {
        *self = *self - o;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_exact() {
        let a = Ratio::new(6, -4);
        assert_eq!((a.numer(), a.denom()), (-3, 2));
        assert_eq!(a + Ratio::new(1, 3), Ratio::new(-7, 6));
        assert_eq!(a * Ratio::new(4, 9), Ratio::new(-2, 3));
        assert_eq!(a / Ratio::new(-3, 5), Ratio::new(5, 2));
        assert!(Ratio::new(1, 3) < Ratio::new(34, 100));
        assert_eq!(Ratio::new(-7, 2).floor(), -4);
    }

    #[test]
    #[should_panic(expected = "overflow")]
    fn overflow_panics() {
        let big = Ratio::int(i128::MAX / 2);
        let _ = big * Ratio::int(3);
    }
}
