//! Compensated evaluation of the bicycle's characteristic polynomial and Hurwitz determinant
//! with a running error bound, and a certified stability classification.
//!
//! Near a stability boundary $H_3 = a_1(a_2a_3 - a_1a_4) - a_0a_3^2$ is a small difference of
//! large products, and in `f64` its sign can be wrong. Here every product and sum is carried
//! out in double-double arithmetic ([`Dd`]: error-free transformations `two_sum` and
//! `two_prod`, about 106 significant bits) and every value carries a bound on its absolute
//! error ([`Bounded`]), propagated operation by operation with the published relative error
//! bounds of double-double addition ($3u^2$) and multiplication ($7u^2$, the bound of their
//! DWTimesDW1; $u = 2^{-53}$;
//! Joldes, Muller, Popescu, ACM TOMS 44, 2017), rounded up. [`classify`] then says
//! [`Certified::Stable`] only when every Routh–Hurwitz quantity is positive by more than its
//! bound, [`Certified::Unstable`] when one is negative by more than its bound, and
//! [`Certified::Indeterminate`] otherwise: never stable when a bound straddles zero.
//!
//! What is certified is the classification of the polynomial built from the given matrix
//! entries, each known to within the stated relative uncertainty (`entry_rel_err`, zero for
//! entries taken as exact); the `f64` evaluation of the matrices themselves is outside the
//! bound unless that uncertainty covers it.

use std::ops::{Add, Mul, Sub};

pub use crate::numerics::dd::{two_prod, two_sum, Dd};
use crate::whipple::{Mat2, Matrices};

/// The unit roundoff $u = 2^{-53}$.
const U: f64 = f64::EPSILON / 2.0;
/// Rounds an error bound computed in `f64` up past the few roundings made computing it.
const UP: f64 = 1.0 + 8.0 * f64::EPSILON;
/// An absolute floor added to every bound, covering underflow in the trailing parts.
const TINY: f64 = 1e-300;

/// A double-double value with a bound on its absolute error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounded {
    /// The computed value.
    pub value: Dd,
    /// An upper bound of $|\text{value} - \text{exact}|$.
    pub err: f64,
}

impl Bounded {
    /// An input known to within the absolute error `err`.
    pub fn new(x: f64, err: f64) -> Bounded {
        Bounded { value: Dd::from(x), err }
    }

    /// `Some(true)` if certainly positive, `Some(false)` if certainly negative, `None` if the
    /// bound reaches zero.
    pub fn sign(self) -> Option<bool> {
        let v = self.value;
        // |hi + lo - hi| <= |lo|: compare hi against err + |lo| to stay rigorous.
        let margin = (self.err + v.lo.abs()) * UP;
        if v.hi > margin {
            Some(true)
        } else if v.hi < -margin {
            Some(false)
        } else {
            None
        }
    }
}

impl Add for Bounded {
    type Output = Bounded;
    fn add(self, o: Bounded) -> Bounded {
        let value = self.value + o.value;
        let err = ((self.err + o.err) + 3.0 * U * U * value.abs_upper()) * UP + TINY;
        Bounded { value, err }
    }
}

impl Sub for Bounded {
    type Output = Bounded;
    fn sub(self, o: Bounded) -> Bounded {
        self + Bounded { value: -o.value, err: o.err }
    }
}

impl Mul for Bounded {
    type Output = Bounded;
    fn mul(self, o: Bounded) -> Bounded {
        let value = self.value * o.value;
        let (a, b) = (self.value.abs_upper(), o.value.abs_upper());
        let prop = a * o.err + b * self.err + self.err * o.err;
        let err = (prop + 7.0 * U * U * value.abs_upper()) * UP + TINY;
        Bounded { value, err }
    }
}

/// The coefficients $a_0, \dots, a_4$ at speed `v` and $H_3$, compensated, with error bounds;
/// each matrix entry $x$ is taken as known to within `entry_rel_err`$\cdot|x|$, `g` and `v` as
/// exact.
pub fn hurwitz_bounded(
    m: &Matrices,
    g: f64,
    v: f64,
    entry_rel_err: f64,
) -> ([Bounded; 5], Bounded) {
    let b = |a: &Mat2| a.map(|r| r.map(|x| Bounded::new(x, (entry_rel_err * x.abs()) * UP)));
    let (mm, c1, k0, k2) = (b(&m.m), b(&m.c1), b(&m.k0), b(&m.k2));
    let mix = |a: &[[Bounded; 2]; 2], c: &[[Bounded; 2]; 2]| {
        a[0][0] * c[1][1] + c[0][0] * a[1][1] - a[0][1] * c[1][0] - c[0][1] * a[1][0]
    };
    let det = |a: &[[Bounded; 2]; 2]| a[0][0] * a[1][1] - a[0][1] * a[1][0];
    let (g, v) = (Bounded::new(g, 0.0), Bounded::new(v, 0.0));
    let u = v * v;
    let a0 = g * g * det(&k0) + g * u * mix(&k0, &k2) + u * u * det(&k2);
    let a1 = v * (g * mix(&c1, &k0) + u * mix(&c1, &k2));
    let a2 = g * mix(&mm, &k0) + u * (mix(&mm, &k2) + det(&c1));
    let a3 = v * mix(&mm, &c1);
    let a4 = det(&mm);
    let h3 = a1 * (a2 * a3 - a1 * a4) - a0 * a3 * a3;
    ([a0, a1, a2, a3, a4], h3)
}

/// A certified stability verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Certified {
    /// Every Routh–Hurwitz quantity is positive beyond its error bound.
    Stable,
    /// Some Routh–Hurwitz quantity is negative beyond its error bound.
    Unstable,
    /// No quantity is certainly negative and at least one bound reaches zero.
    Indeterminate,
}

/// Classifies the upright straight running at speed `v` (see the [module docs](self)).
pub fn classify(m: &Matrices, g: f64, v: f64, entry_rel_err: f64) -> Certified {
    let (a, h3) = hurwitz_bounded(m, g, v, entry_rel_err);
    let lead = match a[4].sign() {
        Some(s) => s,
        None => return Certified::Indeterminate,
    };
    // With a4 < 0 every coefficient and H3 (degree 3) change sign together.
    let signs = [a[0], a[1], a[2], a[3], h3].map(|x| x.sign().map(|s| s == lead));
    if signs.contains(&Some(false)) {
        Certified::Unstable
    } else if signs.iter().all(|s| *s == Some(true)) {
        Certified::Stable
    } else {
        Certified::Indeterminate
    }
}

/// $H_3$ at speed `v` in plain `f64` from the same formula, for comparison.
pub fn hurwitz_f64(m: &Matrices, g: f64, v: f64) -> f64 {
    let p = crate::whipple::stability::HurwitzPolys::new(m, g);
    p.at(v)[5]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_sum_and_two_prod_are_exact() {
        let (s, e) = two_sum(1.0, 1e-20);
        assert_eq!((s, e), (1.0, 1e-20));
        let x = 1.0 + f64::EPSILON;
        let (p, e) = two_prod(x, x);
        // (1 + eps)^2 = 1 + 2 eps + eps^2.
        assert_eq!(p, 1.0 + 2.0 * f64::EPSILON);
        assert_eq!(e, f64::EPSILON * f64::EPSILON);
    }

    #[test]
    fn dd_keeps_what_f64_loses() {
        let a = Dd::from(1e16) + Dd::from(1.0);
        let b = a - Dd::from(1e16);
        assert_eq!(b.to_f64(), 1.0);
        let z = Bounded::new(1.0, 0.0) - Bounded::new(1.0, 0.0);
        assert_eq!(z.sign(), None, "an exact zero is never certainly signed");
    }
}
