//! Double-double arithmetic: the error-free transformations `two_sum` and `two_prod` and the
//! unevaluated sum [`Dd`] of two `f64` (about 106 significant bits), as the certified
//! Routh–Hurwitz evaluation uses them.

use std::ops::{Add, Mul, Neg, Sub};

/// A double-double number: the unevaluated sum `hi + lo` with `|lo| <= ulp(hi) / 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    /// The leading part.
    pub hi: f64,
    /// The trailing part.
    pub lo: f64,
}

/// `a + b = s + e` exactly (Knuth's TwoSum).
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly, assuming `|a| >= |b|` (Dekker's FastTwoSum).
#[inline]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp's splitting: `a = hi + lo` exactly, each half with at most 26 significant bits
/// (for $|a| < 2^{996}$).
#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a * b = p + e` exactly (Dekker's TwoProduct, for $|a|, |b| < 2^{996}$ and no underflow).
/// Plain multiplications and additions: without a hardware fused multiply-add enabled at
/// compile time, `f64::mul_add` is a library call and several times slower.
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl From<f64> for Dd {
    fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }
}

impl Dd {
    /// The nearest `f64` (up to one rounding of `hi + lo`).
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// An upper bound of $|x|$ (rounded up by one relative ulp).
    pub fn abs_upper(self) -> f64 {
        (self.hi.abs() + self.lo.abs()) * (1.0 + 2.0 * f64::EPSILON)
    }
}

impl Add for Dd {
    type Output = Dd;
    /// The accurate double-double sum (relative error at most $3u^2$).
    #[inline]
    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        Dd { hi, lo }
    }
}

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd { hi: -self.hi, lo: -self.lo }
    }
}

impl Sub for Dd {
    type Output = Dd;
    #[inline]
    fn sub(self, o: Dd) -> Dd {
        self + (-o)
    }
}

impl Mul for Dd {
    type Output = Dd;
    /// The double-double product (relative error below $7u^2$).
    #[inline]
    fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        let t = self.hi * o.lo + self.lo * o.hi;
        let (hi, lo) = fast_two_sum(p, e + t);
        Dd { hi, lo }
    }
}
