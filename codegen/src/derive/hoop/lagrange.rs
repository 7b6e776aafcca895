//! Carvallo's modified Lagrange equations for the hoop (memoir n° 71–73, printed "72"/"75").
//!
//! The parameters θ, ν, σ (fall, conversion and rolling angles, with rates p, n, s) are not
//! true coordinates: the contact point O depends on the history of ν and σ. For θ the usual
//! equation holds; for ν and σ the term $-\partial T/\partial\nu$ is replaced by
//! $-\sum m\,M'\,|\,(\partial M/\partial\nu)'$ with $\partial M/\partial\nu = |K(M - O)$ and
//! $\partial M/\partial\sigma = |j(M - O)$ (n° 72). The sums are computed over the hoop's
//! points with $M' = |\Omega(M - O)$, $O' = IRs$.

use symbolica::atom::{Atom, AtomCore};

use super::{body, omega_pns};
use crate::cas::solve_linear;
use crate::cas::{cos_t, sin_t, var};
use crate::mechanics::frame::{time_derivative, Trihedron, Vector};

/// Kinetic energy $T = \frac12\sum m M'^2$ from the mass sums, in θ, p, n, s.
pub fn kinetic_energy() -> Atom {
    let v = omega_pns().cross(&body::point_from_contact());
    body::mass_sum(&v.dot(&v)) / Atom::num(2)
}

/// $\partial/\partial\theta$ of an expression in the stand-ins $\sin\theta, \cos\theta$.
pub fn d_theta(f: &Atom) -> Atom {
    let (st, ct) = (sin_t(), cos_t());
    f.derivative(st.get_symbol().expect("symbol")) * &ct
        - f.derivative(ct.get_symbol().expect("symbol")) * &st
}

fn d(f: &Atom, x: &str) -> Atom {
    f.derivative(var(x).get_symbol().expect("symbol"))
}

fn contact_velocity() -> Vector {
    Vector::new(Trihedron::Ijk, var("R") * var("s"), Atom::num(0), Atom::num(0))
}

/// $-\sum m\,M'\,|\,(\partial M/\partial\nu)'$ with $(\partial M/\partial\nu)' = |K(M' - O')$.
pub fn correction_nu() -> Atom {
    let d_mo = body::point_from_contact();
    let m_dot = omega_pns().cross(&d_mo);
    let k_big = Vector::unit(Trihedron::IJK, 2);
    let dm_dnu_dot = k_big.cross(&m_dot.sub(&contact_velocity()));
    -body::mass_sum(&m_dot.dot(&dm_dnu_dot))
}

/// $-\sum m\,M'\,|\,(\partial M/\partial\sigma)'$ with
/// $(\partial M/\partial\sigma)' = |j'(M - O) + |j(M' - O')$.
pub fn correction_sigma() -> Atom {
    let d_mo = body::point_from_contact();
    let m_dot = omega_pns().cross(&d_mo);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let j_dot = j.derivative(&var("p"), &var("n"));
    let dm_dsigma_dot = j_dot.cross(&d_mo).add(&j.cross(&m_dot.sub(&contact_velocity())));
    -body::mass_sum(&m_dot.dot(&dm_dsigma_dot))
}

/// The first members of the (θ), (ν), (σ) equations; `modified` selects n° 72's correction
/// terms (true) or the plain Lagrange equations of n° 71 (false), where
/// $\partial T/\partial\nu = \partial T/\partial\sigma = 0$.
pub fn equations(modified: bool) -> [Atom; 3] {
    let t = kinetic_energy();
    let weight = var("mu") * var("g") * var("R") * sin_t();
    let eq_theta = time_derivative(&d(&t, "p")) - d_theta(&t) - weight;
    let mut eq_nu = time_derivative(&d(&t, "n"));
    let mut eq_sigma = time_derivative(&d(&t, "s"));
    if modified {
        eq_nu += correction_nu();
        eq_sigma += correction_sigma();
    }
    [eq_theta, eq_nu, eq_sigma]
}

/// The equations solved for $(p', n', s')$.
pub fn solved(modified: bool) -> Vec<Atom> {
    solve_linear(&equations(modified), &["dp", "dn", "ds"])
}

/// The memoir's route for the ν correction (n° 73): $+\sum m\,[M'KO'] = \mu\,[S'KO']$,
/// using $\sum m M' = \mu S'$ with $S' = |\Omega(S - O)$.
pub fn correction_nu_via_centre() -> Atom {
    let s_dot = omega_pns().cross(&body::centre_from_contact());
    let k_big = Vector::unit(Trihedron::IJK, 2);
    var("mu") * s_dot.dot(&k_big.cross(&contact_velocity()))
}

/// The memoir's route for the σ correction (n° 73), using $j' = pk - Ir$:
/// $\sum m M'|(\partial M/\partial\sigma)' =
/// p\sum m[k(M-O)M'] - r\sum m[I(M-O)M'] + \sum m[M'jO']$, the first two sums being the components on k and I of the momentum
/// moment `h` (Cr and Ap) and the last $\mu[S'jO']$. Returns the correction (sign changed)
/// and the last term.
pub fn correction_sigma_via_momentum(h: &Vector) -> (Atom, Atom) {
    let (p, r) = (var("p"), var("n") * cos_t());
    let last = var("mu") * last_term_product(&Vector::unit(Trihedron::Ijk, 1).scale(&Atom::num(0)));
    let k_comp = h.dot(&Vector::unit(Trihedron::Ijk, 2));
    let i_comp = h.dot(&Vector::unit(Trihedron::Ijk, 0));
    (-(p * k_comp - r * i_comp + &last), last)
}

/// The mixed product $[S'jO']$ of the last term of [`correction_sigma_via_momentum`] (before
/// the factor $\mu$), with the centre S moved by `off` from its place in the hoop's plane (zero
/// for the hoop).
pub fn last_term_product(off: &Vector) -> Atom {
    let s_dot = omega_pns().cross(&body::centre_from_contact().add(off));
    let j = Vector::unit(Trihedron::Ijk, 1);
    s_dot.dot(&j.cross(&contact_velocity()))
}
