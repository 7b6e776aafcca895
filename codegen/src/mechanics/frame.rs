//! Moving trihedra OIJK and OIjk, Grassmann's product and derivatives of moving vectors
//! (memoir n° 1–3), written with symbolica expressions.
//!
//! OIJK has OI along the hoop's tangent at the contact point O, OK vertical; OIjk is obtained
//! by the rotation θ about OI, so that $j = J\cos\theta + K\sin\theta$ and
//! $k = -J\sin\theta + K\cos\theta$ (n° 1). Grassmann's product $|ab$ is the cross product
//! ($|IJ = K$). The trihedron OIJK turns with the rotation $nK$ and OIjk with
//! $\Phi = pI + nK$ (n° 2), so the derivative of a vector given by its components in either
//! trihedron is the derivative of its components plus $|\omega v$ (formulas (4)–(6), n° 3).
//!
//! Inside the derivations $\sin\theta$ and $\cos\theta$ are the polynomial symbols
//! [`crate::cas::sin_t`] and [`crate::cas::cos_t`], tied by $\sin^2\theta + \cos^2\theta = 1$
//! (see [`crate::cas`]).
//!
//! The printed formulas (4)–(6) are checked against these rules in
//! `codegen/tests/derive/hoop_frame.rs`.

use symbolica::atom::{Atom, AtomCore};

use crate::cas::{cos_t, is_zero, sin_t, var};

/// Time derivative of a scalar along the motion: $\theta' = p$ and the derivatives of the
/// rates are the symbols `dp`, `dq`, `dr`, `dn`, `ds`.
pub fn time_derivative(f: &Atom) -> Atom {
    let p = var("p");
    let rules: [(Atom, Atom); 8] = [
        (sin_t(), cos_t() * &p),
        (cos_t(), -(sin_t() * &p)),
        (var("theta"), p.clone()),
        (var("p"), var("dp")),
        (var("q"), var("dq")),
        (var("r"), var("dr")),
        (var("n"), var("dn")),
        (var("s"), var("ds")),
    ];
    let mut out = Atom::num(0);
    for (x, rate) in rules {
        if let Some(sym) = x.get_symbol() {
            if f.contains_symbol(sym) {
                out += f.derivative(sym) * rate;
            }
        }
    }
    out
}

/// The two moving trihedra of n° 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trihedron {
    /// OIJK: OI tangent to the hoop at O, OK vertical.
    IJK,
    /// OIjk: OIJK turned by θ about OI; Oj is the hoop's axis, Ok the diameter through S.
    Ijk,
}

/// A vector given by its components in one of the trihedra.
#[derive(Clone, Debug, PartialEq)]
pub struct Vector {
    /// The trihedron the components refer to.
    pub frame: Trihedron,
    /// Components on (I, J, K) or (I, j, k).
    pub comps: [Atom; 3],
}

impl Vector {
    /// The vector with components `a, b, c` in `frame`.
    pub fn new(frame: Trihedron, a: Atom, b: Atom, c: Atom) -> Self {
        Vector { frame, comps: [a, b, c] }
    }

    /// The zero vector.
    pub fn zero(frame: Trihedron) -> Self {
        Vector::new(frame, Atom::num(0), Atom::num(0), Atom::num(0))
    }

    /// The `i`-th unit vector of `frame` (0: I, 1: J or j, 2: K or k).
    pub fn unit(frame: Trihedron, i: usize) -> Self {
        let mut v = Vector::zero(frame);
        v.comps[i] = Atom::num(1);
        v
    }

    /// Components of the same vector in `target`: $J = j\cos\theta - k\sin\theta$,
    /// $K = j\sin\theta + k\cos\theta$ and conversely.
    pub fn to(&self, target: Trihedron) -> Self {
        let (c, s) = (cos_t(), sin_t());
        let [a, b, d] = &self.comps;
        match (self.frame, target) {
            (x, y) if x == y => self.clone(),
            (Trihedron::IJK, Trihedron::Ijk) => {
                Vector::new(target, a.clone(), b * &c + d * &s, -(b * &s) + d * &c)
            }
            _ => Vector::new(target, a.clone(), b * &c - d * &s, b * &s + d * &c),
        }
    }

    /// Sum, in the frame of `self`.
    pub fn add(&self, o: &Vector) -> Self {
        let o = o.to(self.frame);
        Vector::new(
            self.frame,
            &self.comps[0] + &o.comps[0],
            &self.comps[1] + &o.comps[1],
            &self.comps[2] + &o.comps[2],
        )
    }

    /// Difference, in the frame of `self`.
    pub fn sub(&self, o: &Vector) -> Self {
        self.add(&o.scale(&Atom::num(-1)))
    }

    /// Product by a scalar.
    pub fn scale(&self, k: &Atom) -> Self {
        Vector::new(self.frame, k * &self.comps[0], k * &self.comps[1], k * &self.comps[2])
    }

    /// Scalar product (both trihedra are orthonormal).
    pub fn dot(&self, o: &Vector) -> Atom {
        let o = o.to(self.frame);
        &self.comps[0] * &o.comps[0] + &self.comps[1] * &o.comps[1] + &self.comps[2] * &o.comps[2]
    }

    /// Grassmann's product $|ab$ (n° 1): the velocity of the end of `b` under the rotation
    /// `self`, or the moment about the origin of the force `b` applied at the end of `self`.
    /// Both trihedra are direct ($|IJ = K$, $|Ij = k$), so it is the cross product.
    pub fn cross(&self, o: &Vector) -> Self {
        let o = o.to(self.frame);
        let [a1, a2, a3] = &self.comps;
        let [b1, b2, b3] = &o.comps;
        Vector::new(self.frame, a2 * b3 - a3 * b2, a3 * b1 - a1 * b3, a1 * b2 - a2 * b1)
    }

    /// Applies `f` to every component.
    pub fn map(&self, f: impl Fn(&Atom) -> Atom) -> Self {
        Vector::new(self.frame, f(&self.comps[0]), f(&self.comps[1]), f(&self.comps[2]))
    }

    /// Whether all components vanish identically (see [`is_zero`]).
    pub fn is_zero(&self) -> bool {
        self.comps.iter().all(is_zero)
    }

    /// Time derivative of the vector (n° 3): derivative of the components plus $|\omega v$,
    /// with $\omega = nK$ for OIJK and $\omega = \Phi = pI + nK$ for OIjk. `p` and `n` are the
    /// fall and turning rates as expressions (for example `n` may be `r/cos θ`).
    pub fn derivative(&self, p: &Atom, n: &Atom) -> Self {
        let omega = match self.frame {
            Trihedron::IJK => Vector::new(Trihedron::IJK, Atom::num(0), Atom::num(0), n.clone()),
            Trihedron::Ijk => {
                Vector::new(Trihedron::IJK, p.clone(), Atom::num(0), n.clone()).to(Trihedron::Ijk)
            }
        };
        self.map(time_derivative).add(&omega.cross(self))
    }
}
