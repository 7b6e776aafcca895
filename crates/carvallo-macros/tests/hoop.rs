//! Scenes over the real hoop model, `generated/hoop.ir` (written by `cargo xtask regen`).
//!
//! The whole-model scene must reproduce the IR's reference interpreter bit for bit; specialised
//! scenes (parameters fixed, a few outputs) must be smaller and agree with the interpreter to
//! rounding; and the energy output is checked against the closed form of the contract,
//! $T + V = \mu R^2 (\tfrac34 p^2 + q^2 + \tfrac14 r^2) + \mu g R \cos\theta$ with
//! $q = s + n \sin\theta$, $r = n \cos\theta$.

use carvallo_ir::Program;

carvallo_macros::scene! {
    /// Every output of the hoop, nothing fixed.
    pub mod hoop_full {
        model: hoop,
    }

    /// The steady-state window of n° 8–9: radius and gravity fixed, (E) and (S) only.
    pub mod hoop_window {
        model: hoop,
        fixed: { R: 0.5, g: 9.81 },
        outputs: [equilibrium, stability],
    }

    /// The total energy only.
    pub mod hoop_energy {
        model: hoop,
        outputs: [energy],
    }
}

/// Relative tolerance for values computed with different but equivalent roundings (folded
/// constants): a few hundred ulps, far below any physical effect and far above the roundings
/// of formulas of this size.
const REL_TOL: f64 = 1e-13;

fn program() -> Program {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../generated/hoop.ir");
    let text = std::fs::read_to_string(path).expect("generated/hoop.ir is readable");
    Program::parse(&text).expect("generated/hoop.ir parses")
}

/// A fixed grid of states away from the singular cos θ = 0 and sin θ = 0.
fn states() -> Vec<[f64; 6]> {
    let thetas = [-1.2, -0.4, 0.3, 0.9, 1.4];
    let rates = [-3.0, -0.5, 0.0, 0.8, 2.5];
    let mut out = Vec::new();
    for (i, &theta) in thetas.iter().enumerate() {
        for (j, &p) in rates.iter().enumerate() {
            let pick = |k: usize| rates[(i + j * 2 + k) % rates.len()];
            out.push([theta, p, pick(1), pick(2), pick(3), pick(4)]);
        }
    }
    out
}

fn index(names: &[&str], name: &str) -> usize {
    names.iter().position(|n| *n == name).unwrap_or_else(|| panic!("no {name}"))
}

#[test]
fn scenes_follow_the_contract_and_shrink() {
    assert_eq!(hoop_full::MODEL, "hoop");
    assert_eq!(hoop_full::PARAMS, ["R", "g", "mu"]);
    assert_eq!(hoop_full::INPUTS, ["theta", "p", "q", "r", "n", "s"]);
    assert_eq!(hoop_full::OP_COUNT, hoop_full::SOURCE_OP_COUNT);
    for name in ["pqr_dp", "pns_dp", "energy", "equilibrium", "stability", "skid"] {
        assert!(hoop_full::OUTPUTS.contains(&name), "{name} missing");
    }

    // (E) and (S) depend on θ, s, n only; μ drops out, R and g are folded in.
    assert_eq!(hoop_window::OUTPUTS, ["equilibrium", "stability"]);
    assert!(hoop_window::PARAMS.is_empty());
    assert!(hoop_window::INPUTS.iter().all(|i| ["theta", "n", "s"].contains(i)));
    assert_eq!(hoop_window::FIXED, [("R", 0.5), ("g", 9.81)]);
    const { assert!(hoop_window::OP_COUNT < hoop_full::OP_COUNT / 3) };
    const { assert!(hoop_energy::OP_COUNT < hoop_full::OP_COUNT / 2) };
    assert_eq!(hoop_energy::PARAMS, ["R", "g", "mu"]);
}

#[test]
fn whole_model_equals_the_interpreter_bit_for_bit() {
    let p = program();
    for state in states() {
        for params in [[0.5, 9.81, 2.0], [1.3, 1.0, 0.25]] {
            let want = p.eval_f64(&params, &state).expect("interpreter runs");
            let mut args = [0.0; 9];
            args[..3].copy_from_slice(&params);
            args[3..].copy_from_slice(&state);
            let got = hoop_full::eval_array(&args);
            for (k, name) in hoop_full::OUTPUTS.iter().enumerate() {
                let same =
                    got[k].to_bits() == want[k].to_bits() || (got[k].is_nan() && want[k].is_nan());
                assert!(
                    same,
                    "{name} at {args:?}: generated {} vs interpreter {}",
                    got[k], want[k]
                );
            }
        }
    }
}

#[test]
fn specialised_scene_agrees_with_the_interpreter() {
    let p = program();
    let (e, s) = (index(hoop_full::OUTPUTS, "equilibrium"), index(hoop_full::OUTPUTS, "stability"));
    for [theta, pr, q, r, n, s_rate] in states() {
        let want = p.eval_f64(&[0.5, 9.81, 1.0], &[theta, pr, q, r, n, s_rate]).expect("runs");
        let mut args = hoop_window::Args::default();
        for (i, name) in hoop_window::INPUTS.iter().enumerate() {
            let v = match *name {
                "theta" => theta,
                "n" => n,
                "s" => s_rate,
                other => panic!("unexpected input {other}"),
            };
            let mut a = args.to_array();
            a[i] = v;
            args = hoop_window::Args::from_array(a);
        }
        let got = hoop_window::eval(&args);
        for (what, g, w) in
            [("equilibrium", got.equilibrium, want[e]), ("stability", got.stability, want[s])]
        {
            // Scale: the largest term of (E) and (S) is of order g/R + n² + s².
            let scale = 9.81 / 0.5 + n * n + s_rate * s_rate;
            assert!(
                (g - w).abs() <= REL_TOL * scale,
                "{what} at θ={theta} n={n} s={s_rate}: {g} vs {w}"
            );
        }
    }
}

#[test]
fn energy_matches_the_closed_form() {
    for state in states() {
        let [theta, p, _, _, n, s] = state;
        for (r_, g, mu) in [(0.5, 9.81, 2.0), (1.3, 1.0, 0.25)] {
            let q = s + n * theta.sin();
            let r = n * theta.cos();
            let want =
                mu * r_ * r_ * (0.75 * p * p + q * q + 0.25 * r * r) + mu * g * r_ * theta.cos();
            let args = hoop_energy::Args::from_array({
                let mut a = [0.0; hoop_energy::Args::LEN];
                for (i, name) in hoop_energy::PARAMS.iter().chain(hoop_energy::INPUTS).enumerate() {
                    a[i] = match *name {
                        "R" => r_,
                        "g" => g,
                        "mu" => mu,
                        "theta" => theta,
                        "p" => p,
                        "n" => n,
                        "s" => s,
                        other => panic!("energy should not depend on {other}"),
                    };
                }
                a
            });
            let got = hoop_energy::eval(&args).energy;
            let scale = mu * r_ * r_ * (p * p + s * s + n * n) + mu * g * r_;
            assert!((got - want).abs() <= REL_TOL * scale, "energy at {state:?}: {got} vs {want}");
        }
    }
}
