//! The hoop as a mass distribution (memoir n° 4): a homogeneous circle of radius R and mass μ
//! in the plane (I, k) through its centre S = O + Rk, and the sums over its points.
//!
//! A point M of azimuth φ is at $M - O = Rk + R(I\cos\varphi + k\sin\varphi)$ and carries the
//! mass $\mu\,d\varphi/2\pi$, so a sum $\sum m\,F(M)$ is μ times the mean of F over the circle.
//! The mean of a polynomial in $\cos\varphi, \sin\varphi$ is taken term by term with the exact
//! value $\overline{\cos^a\varphi\sin^b\varphi} = (a-1)!!\,(b-1)!!/(a+b)!!$ for a, b even
//! and 0 otherwise.

use symbolica::atom::{Atom, AtomCore};

use crate::cas::var;
use crate::mechanics::frame::{Trihedron, Vector};

/// Symbol of $\cos\varphi$ (azimuth of a point of the hoop).
pub fn cos_phi() -> Atom {
    var("cos_phi")
}

/// Symbol of $\sin\varphi$.
pub fn sin_phi() -> Atom {
    var("sin_phi")
}

/// $M - O$ for the point of azimuth φ, in OIjk.
pub fn point_from_contact() -> Vector {
    let r = var("R");
    Vector::new(Trihedron::Ijk, &r * &cos_phi(), Atom::num(0), &r + &r * &sin_phi())
}

/// $S - O = Rk$.
pub fn centre_from_contact() -> Vector {
    Vector::new(Trihedron::Ijk, Atom::num(0), Atom::num(0), var("R"))
}

fn double_factorial(k: i64) -> i64 {
    if k <= 0 {
        1
    } else {
        k * double_factorial(k - 2)
    }
}

fn degree(m: &Atom, x: &Atom) -> i64 {
    let sym = x.get_symbol().expect("a symbol");
    let d = (x * &m.derivative(sym) / m).expand();
    (0..64).find(|k| d == Atom::num(*k)).unwrap_or(0)
}

/// Mean over the circle of a polynomial in $\cos\varphi, \sin\varphi$ (exact).
pub fn circle_mean(f: &Atom) -> Atom {
    let (c, s) = (cos_phi(), sin_phi());
    let mut out = Atom::num(0);
    for (key, coeff) in f.expand().coefficient_list::<u8>(&[c.clone(), s.clone()]) {
        let (a, b) = (degree(&key, &c), degree(&key, &s));
        if a % 2 == 0 && b % 2 == 0 {
            let num = double_factorial(a - 1) * double_factorial(b - 1);
            let den = double_factorial(a + b);
            out += coeff * Atom::num(num) / Atom::num(den);
        }
    }
    out.expand()
}

/// $\sum m\,F(M) = \mu\,\overline{F}$ for a scalar F.
pub fn mass_sum(f: &Atom) -> Atom {
    (var("mu") * circle_mean(f)).expand()
}

/// $\sum m\,F(M)$ for a vector F, component by component.
pub fn mass_sum_vec(f: &Vector) -> Vector {
    f.map(mass_sum)
}

/// Moment of inertia about the axis through O with unit direction `u`:
/// $\sum m\,((M-O)^2 - ((M-O)\cdot u)^2)$.
pub fn moment_of_inertia(u: &Vector) -> Atom {
    let d = point_from_contact();
    let du = d.dot(u);
    mass_sum(&(d.dot(&d) - &du * &du))
}
