//! The quartic root solvers on the hard suite against the 256-bit reference roots.
//!
//! Tolerances (relative, floored at eps times the largest root, see
//! `quartic::max_rel_error`): well-conditioned cases 1e-13 for every `f64` method; clustered
//! and near-double roots move by about eps^(1/k) under rounding of the coefficients (k the
//! cluster size), so plain `f64` methods get 1e-5 there; on the spread magnitudes Ferrari's
//! shift by $c_3/4c_4 \approx 2.5\cdot10^4$ wipes out the digits of the root $10^{-4}$ and its
//! two Newton steps recover them only to about 500 ulps (measured 1.2e-13), so 1e-12 there;
//! the companion matrix's eigenvalues are backward stable, accurate to about eps times the
//! matrix's norm in absolute terms, so the root near zero at the capsize speed (below eps
//! times the largest root, where the metric measures in units of that floor) comes out with an
//! absolute error of about one floor unit (measured 1.02): 16 units allowed there; the compensated Aberth iteration
//! evaluates the polynomial to about eps^2 and must reach the correctly rounded roots, 1e-15
//! everywhere. Carvallo's root squaring gives moduli only and cannot split a cluster: it must
//! be accurate on separated moduli and is recorded as failing on the cluster.

use carvallo::quartic::{self, hard_suite};

fn hard(name: &str) -> bool {
    name.starts_with("clustered") || name.starts_with("near-double") || name.contains("bifurcation")
}

#[test]
fn every_solver_meets_its_tolerance_on_the_suite() {
    for case in hard_suite() {
        let (reference, conv) = quartic::reference_roots(&case.coeffs, 256);
        assert!(conv < 1e-60, "{}: reference did not converge ({conv:e})", case.name);
        let tol = if hard(case.name) {
            1e-5
        } else if case.name.starts_with("spread") {
            1e-12
        } else {
            1e-13
        };
        let mut results = vec![
            ("ferrari", Some(quartic::ferrari(&case.coeffs))),
            ("aberth", Some(quartic::aberth(&case.coeffs))),
            ("companion", quartic::companion(&case.coeffs)),
        ];
        for (name, roots) in results.drain(..) {
            match roots {
                Some(r) => {
                    let e = quartic::max_rel_error(&r, &reference);
                    let capsize = case.name.contains("capsize") && name == "companion";
                    let tol = if capsize { 16.0 } else { tol };
                    assert!(e <= tol, "{} by {name}: {e:e}", case.name);
                }
                None => assert_eq!(case.name, "x^4 + 1", "{name} failed on {}", case.name),
            }
        }
        let e = quartic::max_rel_error(&quartic::aberth_compensated(&case.coeffs), &reference);
        assert!(e <= 1e-15, "{} by compensated aberth: {e:e}", case.name);
    }
}

#[test]
fn root_squaring_finds_separated_moduli_and_fails_on_a_cluster() {
    for case in hard_suite() {
        let (reference, _) = quartic::reference_roots(&case.coeffs, 256);
        let e = quartic::max_rel_error_moduli(&quartic::graeffe_moduli(&case.coeffs), &reference);
        match case.name {
            "well separated real" | "spread 1e-4, -1, 1e2, 1e5" => {
                assert!(e <= 1e-12, "{}: {e:e}", case.name)
            }
            name if name.starts_with("clustered") => {
                assert!(e > 1e-4, "the cluster cannot be split by squaring: {e:e}")
            }
            _ => {}
        }
    }
}
