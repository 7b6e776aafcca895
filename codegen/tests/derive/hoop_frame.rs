//! Unit checks of the moving-trihedron rules (memoir n° 3, formulas (4)–(6)) against the
//! printed formulas, of Grassmann's product and of the exact trigonometric reduction, and of the
//! circle means used to sum over the hoop's points (n° 4).

use carvallo_codegen::cas::{cos_t, expr, from_trig, is_zero, sin_t, var};
use carvallo_codegen::derive::hoop::body::{circle_mean, cos_phi, sin_phi};
use carvallo_codegen::mechanics::frame::{Trihedron, Vector};
use symbolica::atom::{Atom, AtomCore};

fn ijk(a: &str, b: &str, c: &str) -> Vector {
    Vector::new(Trihedron::Ijk, from_trig(&expr(a)), from_trig(&expr(b)), from_trig(&expr(c)))
}

fn same(a: &Vector, b: &Vector) -> bool {
    a.sub(b).is_zero()
}

fn formula_4_derivatives_of_i_and_j_big() {
    let (p, n) = (var("p"), var("n"));
    let i = Vector::unit(Trihedron::IJK, 0);
    let j_big = Vector::unit(Trihedron::IJK, 1);
    // I' = Jn = n(j cos θ − k sin θ) = r(j − k tan θ) with r = n cos θ.
    let di = i.derivative(&p, &n);
    assert!(same(&di, &j_big.scale(&n)));
    assert!(same(&di, &ijk("0", "n*cos(theta)", "-n*sin(theta)")));
    let r_form = ijk("0", "r", "-r*tan(theta)")
        .map(|c| c.replace(var("r").to_pattern()).with((var("n") * cos_t()).to_pattern()));
    assert!(same(&di, &r_form));
    // J' = −In.
    let dj = j_big.derivative(&p, &n);
    assert!(same(&dj, &i.scale(&-n.clone())));
}

fn formula_5_derivatives_of_j_and_k() {
    let (p, n) = (var("p"), var("n"));
    let dj = Vector::unit(Trihedron::Ijk, 1).derivative(&p, &n);
    let dk = Vector::unit(Trihedron::Ijk, 2).derivative(&p, &n);
    assert!(same(&dj, &ijk("-n*cos(theta)", "0", "p")));
    assert!(same(&dk, &ijk("n*sin(theta)", "-p", "0")));
    // r-forms: j' = pk − Ir, k' = −pj + I r tan θ.
    let r = var("n") * cos_t();
    assert!(same(&dj, &Vector::new(Trihedron::Ijk, -r.clone(), Atom::num(0), p.clone())));
    assert!(same(
        &dk,
        &Vector::new(Trihedron::Ijk, r * sin_t() / cos_t(), -p.clone(), Atom::num(0))
    ));
}

fn formula_6_derivative_of_phi() {
    let (p, n) = (var("p"), var("n"));
    let phi = Vector::new(Trihedron::IJK, p.clone(), Atom::num(0), n.clone());
    let expected = Vector::new(Trihedron::IJK, var("dp"), &p * &n, var("dn"));
    assert!(same(&phi.derivative(&p, &n), &expected));
    // The same vector given in OIjk has the same derivative.
    let phi_ijk = phi.to(Trihedron::Ijk);
    assert!(same(&phi_ijk.derivative(&p, &n), &expected));
}

fn grassmann_products_of_units() {
    let i = Vector::unit(Trihedron::IJK, 0);
    let j_big = Vector::unit(Trihedron::IJK, 1);
    let k_big = Vector::unit(Trihedron::IJK, 2);
    assert!(same(&i.cross(&j_big), &k_big));
    let j = Vector::unit(Trihedron::Ijk, 1);
    let k = Vector::unit(Trihedron::Ijk, 2);
    assert!(same(&i.cross(&j), &k));
    // n° 5: |Kk = I sin θ, hence |kK = −I sin θ.
    assert!(same(&k_big.cross(&k), &i.scale(&sin_t())));
    assert!(same(&k.cross(&k_big), &i.scale(&-sin_t())));
    assert!(!same(&k.cross(&k_big), &i.scale(&sin_t())));
}

fn trig_reduction_is_exact() {
    let e = from_trig(&expr("sin(theta)^4 + 2*sin(theta)^2*cos(theta)^2 + cos(theta)^4 - 1"));
    assert!(is_zero(&e));
    let t = from_trig(&expr("tan(theta)*cos(theta) - sin(theta)"));
    assert!(is_zero(&t));
    assert!(!is_zero(&from_trig(&expr("sin(theta)^2 - 1"))));
}

fn circle_means_are_exact() {
    // Means over the circle used for the sums over the hoop's points (n° 4).
    let cases = [
        ("cos_phi^2", 1, 2),
        ("sin_phi^2", 1, 2),
        ("cos_phi^4", 3, 8),
        ("cos_phi^2*sin_phi^2", 1, 8),
        ("cos_phi*sin_phi", 0, 1),
        ("sin_phi^3", 0, 1),
        ("7", 7, 1),
    ];
    for (text, num, den) in cases {
        let got = circle_mean(&expr(text));
        assert_eq!(got, Atom::num(num) / Atom::num(den), "mean of {text}");
    }
    // (1 + sin φ)² has mean 3/2 (the distance² to O of a point, over R²).
    let e = (Atom::num(1) + sin_phi()).pow(Atom::num(2)) + cos_phi().pow(Atom::num(2));
    assert_eq!(circle_mean(&e), Atom::num(2));
}

#[test]
fn circle_means_are_exact_test() {
    crate::on_symbolica_thread(circle_means_are_exact);
}

#[test]
fn formula_4_derivatives_of_i_and_j_big_test() {
    crate::on_symbolica_thread(formula_4_derivatives_of_i_and_j_big);
}

#[test]
fn formula_5_derivatives_of_j_and_k_test() {
    crate::on_symbolica_thread(formula_5_derivatives_of_j_and_k);
}

#[test]
fn formula_6_derivative_of_phi_test() {
    crate::on_symbolica_thread(formula_6_derivative_of_phi);
}

#[test]
fn grassmann_products_of_units_test() {
    crate::on_symbolica_thread(grassmann_products_of_units);
}

#[test]
fn trig_reduction_is_exact_test() {
    crate::on_symbolica_thread(trig_reduction_is_exact);
}
