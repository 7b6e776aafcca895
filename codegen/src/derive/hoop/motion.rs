//! Equations of motion by the moments about the contact point (memoir n° 5–7).
//!
//! The moment of the weight about O is $\mathfrak M = |kR\,(-\mu g K)$ (n° 5). The moment of
//! the inertia forces, sign changed, is $\mathfrak J = \mathfrak J_1 + \mathfrak J_2$ (n° 6)
//! with $\mathfrak J_1$ the derivative of the momentum moment $ApI + Bqj + Crk$ (taken with
//! the frame rules of n° 3, $n = r/\cos\theta$) and
//! $\mathfrak J_2 = \mu\,|O'S'$, $O' = IRs$, $S' = |\Omega(S - O)$. The vector equation
//! $\mathfrak M = \mathfrak J$ gives system (1) in p, q, r; with $q = s + n\sin\theta$,
//! $r = n\cos\theta$ it gives system (2) in p, n, s (n° 7).

use symbolica::atom::Atom;

use super::body;
use crate::cas::{cos_t, sin_t, var};
use crate::cas::{solve_linear, subst};
use crate::mechanics::frame::{time_derivative, Trihedron, Vector};

/// $\Omega = pI + qj + rk$.
pub fn omega_pqr() -> Vector {
    Vector::new(Trihedron::Ijk, var("p"), var("q"), var("r"))
}

/// Momentum moment about O from the mass sums: $\sum m\,|(M-O)\,|\Omega(M-O)$.
pub fn momentum_moment_from_sums() -> Vector {
    let d = body::point_from_contact();
    body::mass_sum_vec(&d.cross(&omega_pqr().cross(&d)))
}

/// Momentum moment $ApI + Bqj + Crk$ with the given moments of inertia.
pub fn momentum_moment(a: &Atom, b: &Atom, c: &Atom) -> Vector {
    Vector::new(Trihedron::Ijk, a * var("p"), b * var("q"), c * var("r"))
}

/// Moment of the weight about O: $\mathfrak M = |kR\,(-\mu g K)$ (n° 5).
pub fn weight_moment() -> Vector {
    let weight = Vector::new(Trihedron::IJK, Atom::num(0), Atom::num(0), -(var("mu") * var("g")));
    body::centre_from_contact().cross(&weight)
}

/// $\mathfrak J = \mathfrak J_1 + \mathfrak J_2$ for the momentum moment `h` (n° 6), in p, q, r.
pub fn inertia_moment(h: &Vector) -> Vector {
    let n = var("r") / cos_t();
    let j1 = h.derivative(&var("p"), &n);
    let s = var("q") - var("r") * sin_t() / cos_t();
    let o_dot = Vector::new(Trihedron::Ijk, var("R") * s, Atom::num(0), Atom::num(0));
    let s_dot = omega_pqr().cross(&body::centre_from_contact());
    let j2 = o_dot.cross(&s_dot).scale(&var("mu"));
    j1.add(&j2)
}

/// The three equations $\mathfrak J - \mathfrak M = 0$ on I, j, k.
pub fn equations_pqr(h: &Vector) -> [Atom; 3] {
    let e = inertia_moment(h).sub(&weight_moment());
    e.comps
}

/// Rewrites an expression in p, q, r, q', r' with $q = s + n\sin\theta$, $r = n\cos\theta$.
pub fn to_pns(e: &Atom) -> Atom {
    let q = var("s") + var("n") * sin_t();
    let r = var("n") * cos_t();
    let dq = time_derivative(&q);
    let dr = time_derivative(&r);
    let e = subst(e, "dq", &dq);
    let e = subst(&e, "dr", &dr);
    let e = subst(&e, "q", &q);
    subst(&e, "r", &r)
}

/// System (1) solved: $(p', q', r')$ as functions of θ, p, q, r.
pub fn system1(h: &Vector) -> Vec<Atom> {
    solve_linear(&equations_pqr(h), &["dp", "dq", "dr"])
}

/// System (2) solved: $(p', n', s')$ as functions of θ, p, n, s.
pub fn system2(h: &Vector) -> Vec<Atom> {
    let eqs: Vec<Atom> = equations_pqr(h).iter().map(to_pns).collect();
    solve_linear(&eqs, &["dp", "dn", "ds"])
}
