//! Steady states, stability and skidding (memoir n° 8–12 and n° 76–77).
//!
//! A steady state has p = 0 and constant θ, n, s; (E) is the value of p' there (n° 8). The
//! stability first member is obtained by n° 76–77: linearise system (2) written as
//! $\theta'' = P$, $n' = N$, $s' = S$ about the steady state, build the characteristic
//! determinant in λ, divide by λ² and keep the constant term; n° 9's route ($-p''/p$ at
//! p = 0) must give the same. The skid tendency (n° 10) comes from the inertia force of the
//! centre, and n° 11 sums the moments about OI of the inertia forces of the points of the
//! hoop split into entrainment (rotation nK about the vertical through the conversion centre),
//! relative (rotation sj about S) and compound centrifugal forces.

use symbolica::atom::{Atom, AtomCore};

use super::body;
use crate::cas::{cos_t, is_zero, simplify, sin_t, var};
use crate::cas::{det3, subst};
use crate::mechanics::frame::{time_derivative, Trihedron, Vector};

fn d(f: &Atom, x: &str) -> Atom {
    f.derivative(var(x).get_symbol().expect("symbol"))
}

/// ∂/∂θ with the stand-ins.
fn d_theta(f: &Atom) -> Atom {
    super::lagrange::d_theta(f)
}

/// (E): p' at p = 0 from $p' = P(\theta, p, n, s)$.
pub fn equilibrium(pns: &[Atom]) -> Atom {
    simplify(&subst(&pns[0], "p", &Atom::num(0)))
}

/// The characteristic determinant of n° 76–77 for system (2), as a polynomial in `lambda`.
pub fn characteristic_determinant(pns: &[Atom]) -> Atom {
    let l = var("lambda");
    let at0 = |e: &Atom| simplify(&subst(e, "p", &Atom::num(0)));
    // Equations g_i = X_i' - F_i with X'' = dp (θ'' ), X' = p, U = (n, s), U' = (dn, ds).
    let g = [var("dp") - &pns[0], var("dn") - &pns[1], var("ds") - &pns[2]];
    let mut m: Vec<Vec<Atom>> = Vec::new();
    for gi in &g {
        let x_col =
            at0(&d(gi, "dp")) * l.pow(Atom::num(2)) + at0(&d(gi, "p")) * &l + at0(&d_theta(gi));
        let n_col = at0(&d(gi, "dn")) * &l + at0(&d(gi, "n"));
        let s_col = at0(&d(gi, "ds")) * &l + at0(&d(gi, "s"));
        m.push(vec![x_col, n_col, s_col]);
    }
    det3(&m).expand()
}

/// Coefficients of $\lambda^0 \dots \lambda^4$ of the determinant, simplified.
pub fn lambda_coefficients(det: &Atom) -> Vec<Atom> {
    let l = var("lambda");
    let mut out = vec![Atom::num(0); 5];
    for (key, coeff) in det.coefficient_list::<u8>(std::slice::from_ref(&l)) {
        let k = (0..5).find(|k| key == l.pow(Atom::num(*k as i64))).unwrap_or(0);
        out[k] = &out[k] + coeff;
    }
    out.iter().map(simplify).collect()
}

/// Stability first member by n° 76–77: the constant term after dividing the characteristic
/// determinant by λ² (that is, its λ² coefficient, provided the λ⁰ and λ¹ coefficients vanish,
/// which is returned as the flag).
pub fn stability_by_determinant(pns: &[Atom]) -> (Atom, bool, Vec<Atom>) {
    let coeffs = lambda_coefficients(&characteristic_determinant(pns));
    let factor = is_zero(&coeffs[0]) && is_zero(&coeffs[1]);
    (coeffs[2].clone(), factor, coeffs)
}

/// n° 9's route: $-p''/p$ at p = 0, with $p'' = dP/dt$ along the motion given by `rates`
/// (the derivatives of the variables of P, keyed by the names `dp`, `dq`, `dr`, `dn`, `ds`).
pub fn minus_p2_over_p(p_dot: &Atom, rates: &[(&str, Atom)]) -> Atom {
    let mut p2 = time_derivative(p_dot);
    for (name, value) in rates {
        p2 = subst(&p2, name, value);
    }
    let f1 = simplify(&(p2 / var("p")));
    simplify(&-subst(&f1, "p", &Atom::num(0)))
}

/// Inertia force of the centre in the steady state, $-\mu S''$ (n° 10), in OIJK.
pub fn centre_inertia_force() -> Vector {
    let omega = super::omega_pns();
    let s_dot = omega.cross(&body::centre_from_contact());
    let s_ddot = s_dot.derivative(&var("p"), &var("n"));
    let steady = |e: &Atom| {
        let e = subst(e, "dp", &Atom::num(0));
        let e = subst(&e, "dn", &Atom::num(0));
        let e = subst(&e, "ds", &Atom::num(0));
        simplify(&subst(&e, "p", &Atom::num(0)))
    };
    s_ddot.scale(&-var("mu")).to(Trihedron::IJK).map(steady)
}

/// Skid tendency D (n° 10): component on J of the centre's inertia force over the weight μg.
pub fn skid() -> Atom {
    simplify(&(centre_inertia_force().comps[1].clone() / (var("mu") * var("g"))))
}

/// The moments about OI of n° 11 (each a mass sum), in the order: entrainment centrifugal
/// force, compound centrifugal force, relative centrifugal force, weight.
pub fn direct_moments() -> [Atom; 4] {
    let d_mo = body::point_from_contact();
    let (n, s, r) = (var("n"), var("s"), var("R"));
    let k_big = Vector::unit(Trihedron::IJK, 2);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let i = Vector::unit(Trihedron::Ijk, 0);
    // Conversion centre C = O + J Rs/n: the point of the ground with velocity 0 under nK.
    let c_from_o = Vector::new(Trihedron::IJK, Atom::num(0), &r * &s / &n, Atom::num(0));
    let m_from_c = d_mo.sub(&c_from_o);
    let w_entr = k_big.scale(&n);
    let f_entr = w_entr.cross(&w_entr.cross(&m_from_c)).scale(&Atom::num(-1));
    let m_from_s = d_mo.sub(&body::centre_from_contact());
    let w_rel = j.scale(&s);
    let v_rel = w_rel.cross(&m_from_s);
    let f_cor = w_entr.cross(&v_rel).scale(&Atom::num(-2));
    let about_oi = |f: &Vector| simplify(&body::mass_sum(&d_mo.cross(f).dot(&i)));
    let weight = super::motion::weight_moment().dot(&i);
    [about_oi(&f_entr), about_oi(&f_cor), rolling_moment(&w_rel), simplify(&weight)]
}

/// The moment about OI of the centrifugal forces of the rolling rotation `w_rel` (the hoop's
/// own is $s\,j$, [`direct_moments`]' third) about the centre S, summed over the hoop.
pub fn rolling_moment(w_rel: &Vector) -> Atom {
    let d_mo = body::point_from_contact();
    let i = Vector::unit(Trihedron::Ijk, 0);
    let m_from_s = d_mo.sub(&body::centre_from_contact());
    let f_rel = w_rel.cross(&w_rel.cross(&m_from_s)).scale(&Atom::num(-1));
    simplify(&body::mass_sum(&d_mo.cross(&f_rel).dot(&i)))
}

/// n° 11: the sum of the moments about OI divided by μR².
pub fn equilibrium_direct() -> Atom {
    let m = direct_moments();
    let total = &m[0] + &m[1] + &m[2] + &m[3];
    simplify(&(total / (var("mu") * var("R").pow(Atom::num(2)))))
}

/// n° 12's change of units: g/R = 1 (g replaced by R, which then cancels).
pub fn normalise(e: &Atom) -> Atom {
    simplify(&subst(e, "g", &var("R")))
}

/// n° 12's (E): (3/2)·E with g/R = 1 divided by (3/2) sin θ cos θ.
pub fn equilibrium_n12(e: &Atom) -> Atom {
    simplify(&(normalise(e) / (sin_t() * cos_t())))
}
