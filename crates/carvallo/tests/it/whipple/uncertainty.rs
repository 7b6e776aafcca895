//! The uncertainty propagation of `carvallo::whipple::uncertainty` on the benchmark bicycle with
//! the made-up 1 % uncertainties of `data/benchmark-1pct.txt`: exact first derivatives of the
//! weave and capsize speeds against central differences, the first-order standard deviations
//! against a seeded Monte Carlo sample, and the batched windows against the single ones.

use carvallo::whipple::parameter_text::UncertainParams;
use carvallo::whipple::uncertainty::{
    eigenvalue_bands, mean_std, monte_carlo, speed_gradients, windows, windows_unchecked,
};
use carvallo::whipple::{Whipple, WhippleParams, PARAM_NAMES};

fn fixture() -> UncertainParams {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/benchmark-1pct.txt");
    let text = std::fs::read_to_string(path).expect("the fixture exists");
    UncertainParams::from_text(&text).expect("the fixture is valid")
}

#[test]
fn the_fixture_is_the_benchmark_with_one_percent() {
    let u = fixture();
    let bench = WhippleParams::benchmark();
    for (k, name) in PARAM_NAMES.iter().enumerate() {
        let (v, s) = (u.params.values()[k], u.sigma[k]);
        assert!((v - bench.values()[k]).abs() <= 1e-15 * v.abs(), "{name}");
        let want = match *name {
            "g" => 0.01,
            "lambda" => 0.005,
            _ => 0.01 * v.abs(),
        };
        assert!((s - want).abs() <= 1e-12 * want, "{name}: {s} vs {want}");
    }
}

/// The dual-number derivatives agree with central differences (relative step 1e-5 of each
/// parameter) to 1e-8 of the largest derivative: the differences' own truncation and rounding
/// errors are about 1e-9 here (measured 9.7e-10 at most, d weave / d IHxz).
#[test]
fn speed_derivatives_match_central_differences() {
    let p = WhippleParams::benchmark();
    let g = speed_gradients(&p);
    let weave = g.weave.expect("the benchmark weaves");
    let capsize = g.capsize.expect("the benchmark capsizes");
    let w = Whipple::new(p.clone()).stability_window();
    assert_eq!(Some(weave.speed), w.weave_speed);
    assert_eq!(Some(capsize.speed), w.capsize_speed);
    let scale_w = weave.grad.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let scale_c = capsize.grad.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, name) in PARAM_NAMES.iter().enumerate() {
        let x = p.values()[k];
        let h = 1e-5 * x.abs();
        let at = |dx: f64| {
            let mut v = *p.values();
            v[k] = x + dx;
            // Unchecked: a step may cross a triangle inequality (IFyy = 2 IFxx nearly).
            windows_unchecked(&[v]).remove(0)
        };
        let (plus, minus) = (at(h), at(-h));
        let fd =
            |a: Option<f64>, b: Option<f64>| (a.expect("speed") - b.expect("speed")) / (2.0 * h);
        let fd_w = fd(plus.weave_speed, minus.weave_speed);
        let fd_c = fd(plus.capsize_speed, minus.capsize_speed);
        assert!(
            (weave.grad[k] - fd_w).abs() <= 1e-8 * scale_w,
            "weave d/d{name}: {} vs {fd_w}",
            weave.grad[k]
        );
        assert!(
            (capsize.grad[k] - fd_c).abs() <= 1e-8 * scale_c,
            "capsize d/d{name}: {} vs {fd_c}",
            capsize.grad[k]
        );
    }
    // A known sign: more trail raises the capsize speed of the benchmark bicycle.
    assert!(capsize.grad[1] > 0.0);
}

/// First order against 20 000 seeded samples. The sample's standard deviation has a relative
/// standard error of about 1/sqrt(2n) = 0.5 %; the first-order approximation itself misses the
/// curvature of the speeds (measured: 0.04 % and 0.6 % on the standard deviations, the weave
/// speed's mean 0.08 standard deviations above the nominal one, a second-order bias; the mean's
/// standard error is 0.007 of them). Stated tolerance: the standard deviations agree to 3 %,
/// the means to 0.25 standard deviations.
#[test]
fn first_order_agrees_with_monte_carlo() {
    let u = fixture();
    let g = speed_gradients(&u.params);
    let mc = monte_carlo(&u, 20_000, 0x1897);
    for (name, first, sample) in [
        ("weave", g.weave.expect("weave"), &mc.weave),
        ("capsize", g.capsize.expect("capsize"), &mc.capsize),
    ] {
        let (mean, std, n) = mean_std(sample);
        assert_eq!(n, 20_000, "{name}: every sample has the speed");
        let sd = first.std(&u.sigma);
        eprintln!(
            "{name}: nominal {} mean {mean} first-order std {sd} sample std {std}",
            first.speed
        );
        assert!((std - sd).abs() <= 0.03 * sd, "{name}: std {std} vs first order {sd}");
        assert!((mean - first.speed).abs() <= 0.25 * sd, "{name}: mean {mean} vs {}", first.speed);
    }
    // The same seed gives the same sample.
    assert_eq!(monte_carlo(&u, 100, 0x1897), monte_carlo(&u, 100, 0x1897));
}

#[test]
fn batched_windows_equal_the_single_ones() {
    let u = fixture();
    let designs = carvallo::whipple::uncertainty::sample_designs(&u, 300, 3);
    let valid: Vec<[f64; 26]> =
        designs.into_iter().filter(|d| WhippleParams::from_values(*d).is_ok()).collect();
    // About half the samples break IFyy <= 2 IFxx (0.28 against 0.281).
    assert!(valid.len() > 50, "{} valid", valid.len());
    let batch = windows(&valid).expect("valid designs");
    for (d, w) in valid.iter().zip(&batch) {
        let p = WhippleParams::from_values(*d).expect("valid");
        assert_eq!(*w, Whipple::new(p).stability_window());
    }
    let mut bad = valid.clone();
    bad[7][10] = -1.0;
    let (row, err) = windows(&bad).unwrap_err();
    assert_eq!(row, 7);
    assert_eq!(err.to_string(), "invalid mB -1.0: must be positive");
}

#[test]
fn eigenvalue_bands_contain_the_nominal_curve() {
    let u = fixture();
    let speeds: Vec<f64> = (0..=20).map(|i| 0.5 * i as f64).collect();
    let b = eigenvalue_bands(&u, &speeds, 500, 11, 0.025, 0.975);
    assert_eq!(b.nominal.len(), speeds.len());
    let bench = Whipple::new(WhippleParams::benchmark());
    for (j, &v) in speeds.iter().enumerate() {
        let mut re: Vec<f64> = bench.eigenvalues(v).iter().map(|e| e.re).collect();
        re.sort_by(f64::total_cmp);
        for (k, r) in re.iter().enumerate() {
            assert!((b.nominal[j][k] - r).abs() <= 1e-12 * r.abs().max(1.0));
            assert!(b.lower[j][k] <= b.upper[j][k]);
            assert!(
                b.lower[j][k] - 1e-9 <= b.nominal[j][k] && b.nominal[j][k] <= b.upper[j][k] + 1e-9,
                "speed {v}, rank {k}: {} not in [{}, {}]",
                b.nominal[j][k],
                b.lower[j][k],
                b.upper[j][k]
            );
        }
    }
    // Zero uncertainty: the band collapses onto the nominal curve.
    let exact = UncertainParams::exact(WhippleParams::benchmark());
    let z = eigenvalue_bands(&exact, &speeds, 20, 1, 0.025, 0.975);
    assert_eq!(z.lower, z.nominal);
    assert_eq!(z.upper, z.nominal);
}

/// The speeds' derivatives from the generated derivative code equal those of dual numbers
/// run through the IR interpreter (no source transformation), on the benchmark and on every
/// shipped bicycle with a rider, parameter by parameter, to 1e-12 of the largest.
#[test]
fn generated_speed_derivatives_equal_the_interpreted_dual_numbers() {
    use carvallo::whipple::uncertainty::{speed_gradients_by, Derivatives};
    let mut designs = vec![("benchmark".to_string(), WhippleParams::benchmark())];
    let mut rng = carvallo::numerics::rng::SplitMix64(354);
    for k in 0..40 {
        // Designs within ±10 % of the benchmark (g kept), the valid ones.
        let mut v = *WhippleParams::benchmark().values();
        for (i, x) in v.iter_mut().enumerate() {
            if PARAM_NAMES[i] != "g" {
                *x *= rng.uniform(0.9, 1.1);
            }
        }
        if let Ok(p) = WhippleParams::from_values(v) {
            designs.push((format!("random design {k}"), p));
        }
    }
    assert!(designs.len() >= 8, "too few valid random designs: {}", designs.len());
    let mut worst: f64 = 0.0;
    for (name, p) in &designs {
        let a = speed_gradients_by(p, Derivatives::Generated);
        let b = speed_gradients_by(p, Derivatives::Interpreted);
        for (which, x, y) in [("weave", &a.weave, &b.weave), ("capsize", &a.capsize, &b.capsize)] {
            let (Some(x), Some(y)) = (x, y) else {
                assert_eq!(
                    x.is_some(),
                    y.is_some(),
                    "{name}: {which} speed exists by one route only"
                );
                continue;
            };
            assert_eq!(x.speed.to_bits(), y.speed.to_bits(), "{name}: {which} speed");
            let scale = y.grad.iter().fold(0.0f64, |m, g| m.max(g.abs()));
            for (k, (gx, gy)) in x.grad.iter().zip(&y.grad).enumerate() {
                let err = (gx - gy).abs() / scale;
                worst = worst.max(err);
                assert!(err <= 1e-12, "{name}: d {which} / d {}: {gx} vs {gy}", PARAM_NAMES[k]);
            }
        }
    }
    eprintln!(
        "generated vs interpreted speed derivatives over {} designs: worst {worst:.2e}",
        designs.len()
    );
}

/// The generated derivatives of the matrices equal 256-bit central differences of
/// `generated/whipple.ir` (step 2^-100 relative), every entry and parameter.
#[test]
fn generated_matrix_derivatives_equal_256_bit_differences() {
    use carvallo::whipple::uncertainty::{matrices_jacobian_scene as scene, WHIPPLE_IR};
    let p = WhippleParams::benchmark();
    let at = |name: &str| p.get(name).expect("a parameter");
    let out = scene::eval(&scene::Args::from_fn(at));
    let jac = scene::jacobian(&out);
    let program = carvallo_ir::Program::parse(WHIPPLE_IR)
        .expect("parses")
        .select_outputs(&scene::JACOBIAN_OF)
        .expect("the matrices");
    let params: Vec<f64> = program.params.iter().map(|n| at(n)).collect();
    let inputs = vec![0.0; program.inputs.len()];
    let mut worst: f64 = 0.0;
    for (c, x) in scene::JACOBIAN_WRT.iter().enumerate() {
        let fd = if program.params.iter().any(|n| n == x) {
            carvallo_ir::hp::derivative(&program, &params, &inputs, x, 256).expect("difference")
        } else {
            vec![0.0; scene::JACOBIAN_OF.len()]
        };
        for (r, o) in scene::JACOBIAN_OF.iter().enumerate() {
            let err = (jac[r][c] - fd[r]).abs() / fd[r].abs().max(1e-3);
            worst = worst.max(err);
            assert!(err <= 1e-13, "d {o} / d {x}: {} vs 256-bit {}", jac[r][c], fd[r]);
        }
    }
    eprintln!("matrix derivatives vs 256-bit differences: worst {worst:.2e}");
}
