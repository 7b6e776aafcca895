//! Table 3 of `carvallo bench`: the quartic root solvers of [`carvallo::numerics::quartic`] on
//! the hard suite ([`hard_suite`]: its polynomial cases and the benchmark bicycle's
//! characteristic polynomial at its weave, capsize and bifurcation speeds), against the 256-bit
//! roots.

use std::hint::black_box;

use carvallo::numerics::quartic::{self, Case, C64};
use carvallo::whipple::{Whipple, WhippleParams};
use rayon::prelude::*;

use super::measure::{time_ns, Config, Row, REFERENCE_BITS};

/// The hard suite of the quartic solvers: [`quartic::polynomial_suite`] and the benchmark
/// bicycle's $a_0, \dots, a_4$ at its weave, capsize and bifurcation speeds.
pub fn hard_suite() -> Vec<Case> {
    let w = Whipple::new(WhippleParams::benchmark());
    let win = w.stability_window();
    let at = |v: Option<f64>| w.char_poly(v.unwrap_or(f64::NAN));
    let vd = w.bifurcation().map(|(v, _)| v);
    let mut suite = quartic::polynomial_suite();
    suite.extend([
        Case { name: "bicycle at v = 5 m/s", coeffs: w.char_poly(5.0) },
        Case { name: "bicycle at the weave speed", coeffs: at(win.weave_speed) },
        Case { name: "bicycle at the capsize speed", coeffs: at(win.capsize_speed) },
        Case { name: "bicycle at the bifurcation", coeffs: at(vd) },
    ]);
    suite
}

/// Table 3.
pub(super) fn quartic_rows(cfg: &Config, rows: &mut Vec<Row>) {
    let suite = hard_suite();
    let refs: Vec<([C64; 4], f64)> =
        suite.par_iter().map(|c| quartic::reference_roots(&c.coeffs, REFERENCE_BITS)).collect();
    type Solver = fn(&[f64; 5]) -> Option<[C64; 4]>;
    let methods: [(&str, Solver); 4] = [
        ("ferrari + newton", |c| Some(quartic::ferrari(c))),
        ("companion eigenvalues", quartic::companion),
        ("aberth", |c| Some(quartic::aberth(c))),
        ("aberth compensated", |c| Some(quartic::aberth_compensated(c))),
    ];
    for (name, f) in methods {
        let mut worst = 0.0f64;
        let mut per_case = Vec::new();
        for (case, (r, _)) in suite.iter().zip(&refs) {
            match f(&case.coeffs) {
                Some(z) => {
                    let e = quartic::max_rel_error(&z, r);
                    worst = worst.max(e);
                    per_case.push(format!("{}: {e:.0e}", case.name));
                }
                None => per_case.push(format!("{}: did not converge", case.name)),
            }
        }
        let t = time_ns(cfg.min_time, || {
            suite.iter().fold(0.0, |acc, c| acc + f(black_box(&c.coeffs)).map_or(0.0, |z| z[0].re))
        });
        rows.push(Row {
            section: "quartic",
            name: format!("{} polynomials", suite.len()),
            method: name.into(),
            ops: None,
            ns: Some(t / suite.len() as f64),
            max_rel_err: Some(worst),
            note: per_case.join("; "),
        });
    }
    let mut worst = 0.0f64;
    let mut per_case = Vec::new();
    for (case, (r, _)) in suite.iter().zip(&refs) {
        let e = quartic::max_rel_error_moduli(&quartic::graeffe_moduli(&case.coeffs), r);
        worst = worst.max(e);
        per_case.push(format!("{}: {e:.0e}", case.name));
    }
    let t = time_ns(cfg.min_time, || {
        suite.iter().map(|c| quartic::graeffe_moduli(black_box(&c.coeffs))[0]).sum::<f64>()
    });
    rows.push(Row {
        section: "quartic",
        name: format!("{} polynomials (moduli only)", suite.len()),
        method: "graeffe root squaring (Carvallo)".into(),
        ops: None,
        ns: Some(t / suite.len() as f64),
        max_rel_err: Some(worst),
        note: per_case.join("; "),
    });
    let conv = refs.iter().map(|r| r.1).fold(0.0, f64::max);
    rows.push(Row {
        section: "quartic",
        name: "reference".into(),
        method: format!("aberth at {REFERENCE_BITS} bits"),
        ops: None,
        ns: None,
        max_rel_err: None,
        note: format!("largest last relative correction {conv:.1e}"),
    });
}

#[cfg(test)]
mod tests {
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

    use super::*;

    fn hard(name: &str) -> bool {
        name.starts_with("clustered")
            || name.starts_with("near-double")
            || name.contains("bifurcation")
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
            let e =
                quartic::max_rel_error_moduli(&quartic::graeffe_moduli(&case.coeffs), &reference);
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
}
