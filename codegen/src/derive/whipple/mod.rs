//! The Carvallo–Whipple bicycle (rear wheel R, rear frame with rider B, front frame H, front
//! wheel F; knife-edge wheels rolling without slipping on flat ground), linearised exactly about
//! upright straight running at speed $v$, with the 25 parameters of the 2007 benchmark
//! (Meijaard, Papadopoulos, Ruina, Schwab, Proc. R. Soc. A 463, Table 1) kept as symbols.
//!
//! The emitted $M$, $C_1$, $K_0$, $K_2$ of
//! $M\ddot q + v C_1 \dot q + (g K_0 + v^2 K_2) q = f$, $q = (\varphi, \delta)$ (lean, steer),
//! come from the mechanics engine ([`linearised`]): the bicycle's description
//! ([`description`]) derived by Kane's method and by Carvallo's modified Lagrange equations,
//! each linearised about the upright motion, the two routes equal entry by entry exactly
//! (`kane_equals_lagrange`). The modified Lagrange equations are also linearised part by part
//! ([`linearised::Origins`]): the momentum's derivative and Carvallo's correction add up to
//! Kane's terms (`lagrange_split`), and the plain Lagrange term $-\mathrm{d}T/\mathrm{d}q$ put in
//! place of the correction is compared with it (`plain_lagrange_phi`, `plain_lagrange_delta`,
//! a finding: it is right for the lean at the linear level, not for the steer, as n° 71 says it
//! need not be). The hand-written series derivation that preceded the engine is gone; its
//! matrices are frozen, with today's, in `codegen/tests/fixtures/whipple_linear.ir`, which the
//! regenerated matrices must equal at 256 bits. Nothing is transcribed from the paper: its
//! published numbers are the test oracle (`tests/tests/whipple_benchmark.rs`,
//! `codegen/tests/derive/whipple_linear.rs`), and so are the fifteen BicycleParameters sets.
//!
//! Outputs: the sixteen matrix entries `m11` … `k2_22` (parameters only) and the coefficients
//! `a0` … `a4` of the characteristic polynomial
//! $\det(M s^2 + v C_1 s + g K_0 + v^2 K_2) = a_4 s^4 + a_3 s^3 + a_2 s^2 + a_1 s + a_0$, written
//! as polynomials in the input $v$ whose coefficients are products of the matrix entries (so
//! that the emission's common-subexpression sharing reuses the entries). No matrix is inverted.
//! The transfer functions from the roll and steer torques to lean and steer share that
//! denominator; their numerators `tf_{output}_{input}_{k}` (the adjugate of the same matrix
//! polynomial, coefficients of $s^k$, [`tf_numerators`]) are outputs too, and so are the
//! coefficients `cl_a{k}_{j}` of $v^j s^k$ in the characteristic polynomial of the closed loop
//! of a state feedback $u = -Kx$ ([`closed_loop_poly`]), whose eight gains ([`GAINS`]) are
//! inputs of the model beside $v$.

pub mod linearised;
pub mod nonlinear;

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};

use crate::cas::subst;
use crate::cas::{cos_t, is_zero, simplify, sin_t, var};
use crate::{Check, Derivation, Formula};

/// Parameter names, in order: the benchmark's Table 1 (with `lambda` the steer axis tilt).
pub const PARAMS: [&str; 26] = [
    "w", "c", "lambda", "g", "rR", "mR", "IRxx", "IRyy", "xB", "zB", "mB", "IBxx", "IByy", "IBzz",
    "IBxz", "xH", "zH", "mH", "IHxx", "IHyy", "IHzz", "IHxz", "rF", "mF", "IFxx", "IFyy",
];

/// Stand-in symbol for $\sin\lambda$.
pub const SIN_LAMBDA: &str = "sin_lambda";
/// Stand-in symbol for $\cos\lambda$.
pub const COS_LAMBDA: &str = "cos_lambda";

/// Brings an expression in the stand-ins $\sin\lambda$, $\cos\lambda$ to the reduced normal form
/// (one fraction, numerator reduced with $\sin^2\lambda + \cos^2\lambda = 1$).
pub fn reduce(e: &Atom) -> Atom {
    let a = subst(e, SIN_LAMBDA, &sin_t());
    let a = subst(&a, COS_LAMBDA, &cos_t());
    let a = simplify(&a);
    let a = subst(&a, "sin_theta", &var(SIN_LAMBDA));
    subst(&a, "cos_theta", &var(COS_LAMBDA))
}

/// Exact test that an expression in the stand-ins vanishes.
pub fn vanishes(e: &Atom) -> bool {
    let a = subst(e, SIN_LAMBDA, &sin_t());
    is_zero(&subst(&a, COS_LAMBDA, &cos_t()))
}

/// Replaces the stand-ins by `sin(lambda)`, `cos(lambda)`.
pub fn to_lambda(e: &Atom) -> Atom {
    let a = subst(e, SIN_LAMBDA, &var("sin(lambda)"));
    subst(&a, COS_LAMBDA, &var("cos(lambda)"))
}

/// The derived matrices, reduced, in the stand-ins.
#[derive(Clone)]
pub struct Matrices {
    /// Mass matrix.
    pub m: [[Atom; 2]; 2],
    /// Velocity-proportional matrix.
    pub c1: [[Atom; 2]; 2],
    /// Gravity stiffness.
    pub k0: [[Atom; 2]; 2],
    /// Velocity-squared stiffness.
    pub k2: [[Atom; 2]; 2],
}

/// [`check`] with the outcome of the same check on a perturbed derived side (issue 38,
/// [`crate::falsify`]).
pub(super) fn check_perturbed(
    id: &str,
    statement: &str,
    holds: bool,
    detail: String,
    perturbed: crate::Perturbed,
) -> Check {
    with_perturbation(check(id, statement, holds, detail), Some(perturbed))
}

pub(super) use crate::falsify::with_perturbation;

/// A check of the linear model's section.
pub(super) fn check(id: &str, statement: &str, holds: bool, detail: String) -> Check {
    Check {
        perturbed: None,
        section: "linear".to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds,
        detail,
    }
}

/// The lean and steer coordinates, in the order of the matrices' rows and columns.
pub const Q: [&str; 2] = ["phi", "delta"];

/// The checks on the modified Lagrange equations' parts and on the yaw rate
/// ([`linearised::Origins`]), against Kane's matrices `kane`.
// Rows and columns index the matrices and the coordinates' names together.
#[allow(clippy::needless_range_loop)]
pub fn origin_checks(kane: &Matrices, parts: &linearised::Origins, checks: &mut Vec<Check>) {
    let yaw = &parts.yaw_rate;
    let cos_w = var(COS_LAMBDA) / var("w");
    let expected = [Atom::num(0), var("v") * &cos_w, Atom::num(0), var("c") * &cos_w];
    let perturbed =
        crate::falsify::perturb(yaw, |d| d.iter().zip(&expected).all(|(d, e)| vanishes(&(d - e))));
    checks.push(check_perturbed(
        "yaw_rate",
        "the yaw rate from the front wheel's rolling is, at first order, psi' = (v delta + c delta') cos(lambda) / w (the engine's dependent speed psid linearised)",
        yaw.iter().zip(&expected).all(|(d, e)| vanishes(&(d - e))),
        format!(
            "coefficients of phi, delta, phi', delta': {}",
            yaw.iter().map(|e| reduce(e).to_string()).collect::<Vec<_>>().join("; ")
        ),
        perturbed,
    ));
    // Momentum plus correction is the generalised inertia force (a check of the split: Kane's
    // matrices come from the other route).
    let (v, v2) = (var("v"), var("v").pow(Atom::num(2)));
    // The split's entries that do not add up, with the momentum's rate entries of the
    // modified Lagrange route given (the derived side of the check).
    let split = |momentum_rate: &[[Atom; 2]; 2]| {
        let mut bad = Vec::new();
        for r in 0..2 {
            for c in 0..2 {
                let rate =
                    &momentum_rate[r][c] + &parts.correction_rate[r][c] - &v * &kane.c1[r][c];
                let angle = &parts.momentum_angle[r][c] + &parts.correction_angle[r][c]
                    - &v2 * &kane.k2[r][c];
                if !vanishes(&rate) || !vanishes(&angle) {
                    bad.push(format!("({}, {})", Q[r], Q[c]));
                }
            }
        }
        bad
    };
    let split_bad = split(&parts.momentum_rate);
    let flat: Vec<Atom> = parts.momentum_rate.iter().flatten().cloned().collect();
    let perturbed = crate::falsify::perturb(&flat, |d| {
        split(&[[d[0].clone(), d[1].clone()], [d[2].clone(), d[3].clone()]]).is_empty()
    });
    checks.push(check_perturbed(
        "lagrange_split",
        "the momentum's derivative (dT/dq')' and Carvallo's correction -sum m M'|(dM/dq)' of the modified Lagrange equations, linearised apart, add up to Kane's v C1 (rates) and v^2 K2 (angles), entry by entry, exactly",
        split_bad.is_empty(),
        if split_bad.is_empty() { String::new() } else { format!("differ: {}", split_bad.join(", ")) },
        perturbed,
    ));
    let Some(plain) = &parts.plain else { return };
    // A term in place of Carvallo's correction minus the correction, row `r`: rates and
    // angles of lean and steer, then the value at the reference.
    let against = |r: usize, rate: &[[Atom; 2]; 2], angle: &[[Atom; 2]; 2], value: &Atom| {
        (0..2)
            .flat_map(|c| {
                [
                    &rate[r][c] - &parts.correction_rate[r][c],
                    &angle[r][c] - &parts.correction_angle[r][c],
                ]
            })
            .chain([value - &plain.values[0][r]])
            .collect::<Vec<Atom>>()
    };
    for r in 0..2 {
        let diff = against(r, &plain.rate, &plain.angle, &plain.values[1][r]);
        let holds = diff.iter().all(vanishes);
        // Where the plain equation agrees, one of its terms scaled: it must then differ.
        // The plain terms in the order of `diff`; the first that is not a literal zero.
        let terms = [&plain.rate[r][0], &plain.angle[r][0], &plain.rate[r][1], &plain.angle[r][1]];
        let perturbed = if holds {
            terms.iter().position(|t| !t.is_zero()).map(|k| {
                crate::falsify::perturb_one(terms[k], |d| vanishes(&(&diff[k] - terms[k] + d)))
            })
        } else {
            // Where it differs (as n° 71 says the steer's must), the plain terms replaced by
            // Carvallo's correction, rates, angles and value: it must then agree.
            let corrected =
                against(r, &parts.correction_rate, &parts.correction_angle, &plain.values[0][r]);
            Some(crate::Perturbed {
                what: "the plain term -dT/dq replaced by Carvallo's correction (its rates, angles and value): the modified Lagrange equation itself".into(),
                holds: corrected.iter().all(vanishes),
            })
        };
        checks.push(with_perturbation(check(
            &format!("plain_lagrange_{}", Q[r]),
            &format!("the plain Lagrange equation of {} (-dT/dq, the pitch following through the front contact, in place of Carvallo's -sum m M'|(dM/dq)') equals Kane's generalised inertia force at first order, identically in the lean, steer, their rates and v (informative: not required to hold)", Q[r]),
            holds,
            if holds {
                String::new()
            } else {
                format!(
                    "plain minus Carvallo's term (rates and angles of lean, steer; value): {}",
                    diff.iter().map(|e| reduce(e).to_string()).collect::<Vec<_>>().join("; ")
                )
            },
        ), perturbed));
    }
    let perturbed =
        crate::falsify::perturb_one(&kane.k0[0][1], |d| vanishes(&(d - &kane.k0[1][0])));
    checks.push(check_perturbed(
        "k0_symmetric",
        "K0 is symmetric (a Hessian)",
        vanishes(&(&kane.k0[0][1] - &kane.k0[1][0])),
        format!("k0_12 = {}; k0_21 = {}", kane.k0[0][1], kane.k0[1][0]),
        perturbed,
    ));
}

fn mix(a: &[[Atom; 2]; 2], b: &[[Atom; 2]; 2]) -> Atom {
    &a[0][0] * &b[1][1] + &b[0][0] * &a[1][1] - &a[0][1] * &b[1][0] - &b[0][1] * &a[1][0]
}

fn det(a: &[[Atom; 2]; 2]) -> Atom {
    &a[0][0] * &a[1][1] - &a[0][1] * &a[1][0]
}

/// The characteristic polynomial's coefficients $a_0, \dots, a_4$ as polynomials in $v$:
/// with $A = M$, $B = vC_1$, $C = gK_0 + v^2K_2$ and
/// $m(X, Y) = X_{11}Y_{22} + Y_{11}X_{22} - X_{12}Y_{21} - Y_{12}X_{21}$,
/// $\det(As^2 + Bs + C) = s^4\det A + s^3 m(A,B) + s^2(m(A,C) + \det B) + s\,m(B,C) + \det C$.
pub fn char_poly(m: &Matrices) -> [Atom; 5] {
    let (v, g) = (var("v"), var("g"));
    let v2 = v.pow(Atom::num(2));
    [
        g.pow(Atom::num(2)) * det(&m.k0)
            + &g * &v2 * mix(&m.k0, &m.k2)
            + v.pow(Atom::num(4)) * det(&m.k2),
        &v * &g * mix(&m.c1, &m.k0) + v.pow(Atom::num(3)) * mix(&m.c1, &m.k2),
        &g * mix(&m.m, &m.k0) + &v2 * (mix(&m.m, &m.k2) + det(&m.c1)),
        &v * mix(&m.m, &m.c1),
        det(&m.m),
    ]
}

/// The names of the two inputs (generalised forces) and two outputs (coordinates) of the
/// transfer functions, in the order of $q = (\varphi, \delta)$ and $f = (T_\varphi, T_\delta)$.
pub const TF_SIGNALS: [&str; 2] = ["roll", "steer"];

/// The numerators of the transfer functions from the torques to the coordinates.
///
/// With $P(s) = M s^2 + v C_1 s + g K_0 + v^2 K_2$ the Laplace transform of the equations from
/// rest is $P(s)\,q(s) = f(s)$, so $q = \operatorname{adj}P(s)\,f / \det P(s)$: the transfer
/// function from input $j$ to output $i$ is $N_{ij}(s)/\det P(s)$ with
/// $N = \operatorname{adj}P = \begin{pmatrix} P_{22} & -P_{12} \\ -P_{21} & P_{11}\end{pmatrix}$
/// and $\det P(s) = \sum_k a_k s^k$ the characteristic polynomial ([`char_poly`]). Each
/// $N_{ij}$ is returned as its coefficients of $s^0, s^1, s^2$, polynomials in $v$ whose
/// coefficients are the matrix entries. The rate outputs are $s\,N_{ij}$ (no new formula).
pub fn tf_numerators(m: &Matrices) -> [[[Atom; 3]; 2]; 2] {
    let (v, g) = (var("v"), var("g"));
    let v2 = v.pow(Atom::num(2));
    let entry = |r: usize, c: usize, sign: i64| -> [Atom; 3] {
        let k = Atom::num(sign);
        [&k * (&g * &m.k0[r][c] + &v2 * &m.k2[r][c]), &k * &v * &m.c1[r][c], &k * &m.m[r][c]]
    };
    [[entry(1, 1, 1), entry(0, 1, -1)], [entry(1, 0, -1), entry(0, 0, 1)]]
}

/// The check that [`tf_numerators`] and [`char_poly`] fit: with generic symbols for the sixteen
/// matrix entries, $N(s)\,P(s) = \det P(s)\, I$ identically in $s$, $v$, $g$ and the entries.
#[allow(clippy::needless_range_loop)]
fn tf_check() -> Check {
    let gm = generic_matrices();
    let (s, v, g) = (var("s"), var("v"), var("g"));
    let poly = |c: &[Atom]| -> Atom {
        c.iter().enumerate().fold(Atom::num(0), |acc, (k, a)| acc + a * s.pow(Atom::num(k as i64)))
    };
    let p: [[Atom; 2]; 2] = std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            &gm.m[r][c] * s.pow(Atom::num(2))
                + &v * &gm.c1[r][c] * &s
                + &g * &gm.k0[r][c]
                + v.pow(Atom::num(2)) * &gm.k2[r][c]
        })
    });
    let n = tf_numerators(&gm);
    let det_p = poly(&char_poly(&gm));
    // Whether N P = det(P) I with the numerators `n`, and the last residual that is not zero.
    let residual = |n: &[[[Atom; 3]; 2]; 2]| -> (bool, Atom) {
        let mut worst = Atom::num(0);
        let mut holds = true;
        for i in 0..2 {
            for j in 0..2 {
                let np = (poly(&n[i][0]) * &p[0][j] + poly(&n[i][1]) * &p[1][j]).expand();
                let want = if i == j { det_p.expand() } else { Atom::num(0) };
                let diff = (np - want).expand();
                if !is_zero(&diff) {
                    holds = false;
                    worst = diff;
                }
            }
        }
        (holds, worst)
    };
    let (holds, worst) = residual(&n);
    // The derived side: N_11's constant coefficient, perturbed.
    let perturbed = crate::falsify::perturb_one(&n[0][0][0], |d| {
        let mut m = n.clone();
        m[0][0][0] = d.clone();
        residual(&m).0
    });
    check_perturbed(
        "transfer_adjugate",
        "the transfer-function numerators N (the adjugate of P(s) = M s^2 + v C1 s + g K0 + v^2 K2) and the characteristic polynomial sum a_k s^k satisfy N P = det(P) I identically in s, v, g and generic matrix entries",
        holds,
        format!("residual: {worst}"),
        perturbed,
    )
}

/// The gains of the state feedback $u = -K x$, inputs of the model: `k_{input}_{state}` is the
/// entry of $K$ in the row of the input (`roll` or `steer` torque) and the column of the state
/// (`roll`, `steer`, `roll_rate`, `steer_rate`). The balance-assist law $T_\delta = -k\dot\varphi$
/// is `k_steer_roll_rate = k`.
pub const GAINS: [&str; 8] = [
    "k_roll_roll",
    "k_roll_steer",
    "k_roll_roll_rate",
    "k_roll_steer_rate",
    "k_steer_roll",
    "k_steer_steer",
    "k_steer_roll_rate",
    "k_steer_steer_rate",
];

/// The sixteen generic symbols that stand for the entries of $M$, $C_1$, $K_0$, $K_2$ while the
/// polynomial structure in $s$, $v$ and the gains is worked out.
fn generic_matrices() -> Matrices {
    let generic = |prefix: &str| -> [[Atom; 2]; 2] {
        std::array::from_fn(|r| {
            std::array::from_fn(|c| var(&format!("{prefix}{}{}", r + 1, c + 1)))
        })
    };
    Matrices { m: generic("gm"), c1: generic("gc"), k0: generic("gk"), k2: generic("gl") }
}

/// $\det(A s^2 + B s + C)$ as its coefficients of $s^0 \dots s^4$:
/// $[\det C,\ m(B, C),\ m(A, C) + \det B,\ m(A, B),\ \det A]$.
fn quartic_of(a: &[[Atom; 2]; 2], b: &[[Atom; 2]; 2], c: &[[Atom; 2]; 2]) -> [Atom; 5] {
    [det(c), mix(b, c), mix(a, c) + det(b), mix(a, b), det(a)]
}

/// The closed loop of the state feedback $u = -Kx$, $K = (K_p\ K_d)$ ([`GAINS`]):
/// $M\ddot q + (vC_1 + K_d)\dot q + (gK_0 + v^2K_2 + K_p)q = 0$. Its characteristic polynomial
/// $\sum_k a^{cl}_k s^k$ has coefficients that are polynomials in $v$; returned as
/// `[k][j]`, the coefficient of $v^j$ in $a^{cl}_k$ ($j \le 4 - k$), polynomials in the gains
/// and `g` with the entries of `m` as coefficients. Worked out on [`generic_matrices`] (so the
/// expansion in $v$ never multiplies out the entries' own formulas), then the entries of `m`
/// substituted.
#[allow(clippy::needless_range_loop)]
pub fn closed_loop_poly(m: &Matrices) -> Vec<Vec<Atom>> {
    let gm = generic_matrices();
    let (v, g) = (var("v"), var("g"));
    let gain = |input: usize, state: usize| var(GAINS[4 * input + state]);
    let b: [[Atom; 2]; 2] =
        std::array::from_fn(|r| std::array::from_fn(|c| &v * &gm.c1[r][c] + gain(r, 2 + c)));
    let c: [[Atom; 2]; 2] = std::array::from_fn(|r| {
        std::array::from_fn(|col| {
            &g * &gm.k0[r][col] + v.pow(Atom::num(2)) * &gm.k2[r][col] + gain(r, col)
        })
    });
    let poly = quartic_of(&gm.m, &b, &c);
    let v_sym = v.get_symbol().expect("symbol");
    let mut fact = Atom::num(1);
    let mut out = Vec::new();
    for (k, a) in poly.iter().enumerate() {
        let mut coefs = Vec::new();
        let mut d = a.expand();
        for j in 0..=(4 - k) {
            if j > 0 {
                d = d.derivative(v_sym).expand();
                fact = &fact * Atom::num(j as i64);
            }
            coefs.push((subst(&d, "v", &Atom::num(0)) / &fact).expand());
        }
        fact = Atom::num(1);
        out.push(coefs);
    }
    let names = [("gm", &m.m), ("gc", &m.c1), ("gk", &m.k0), ("gl", &m.k2)];
    out.into_iter()
        .map(|coefs| {
            coefs
                .into_iter()
                .map(|mut e| {
                    for (prefix, mat) in names {
                        for r in 0..2 {
                            for col in 0..2 {
                                let name = format!("{prefix}{}{}", r + 1, col + 1);
                                e = subst(&e, &name, &mat[r][col]);
                            }
                        }
                    }
                    e
                })
                .collect()
        })
        .collect()
}

/// The checks of [`closed_loop_poly`] on the generic entries: its coefficients reassembled,
/// $\sum_{k,j} a^{cl}_{kj} v^j s^k$, equal the determinant of
/// $M s^2 + (vC_1 + K_d)s + gK_0 + v^2K_2 + K_p$ multiplied out directly, and with every gain
/// zero each $\sum_j a^{cl}_{kj}v^j$ is the open-loop coefficient $a_k$ of [`char_poly`].
fn closed_loop_checks() -> Vec<Check> {
    let gm = generic_matrices();
    let cl = closed_loop_poly(&gm);
    let (s, v, g) = (var("s"), var("v"), var("g"));
    let gain = |input: usize, state: usize| var(GAINS[4 * input + state]);
    let p: [[Atom; 2]; 2] = std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            &gm.m[r][c] * s.pow(Atom::num(2))
                + (&v * &gm.c1[r][c] + gain(r, 2 + c)) * &s
                + &g * &gm.k0[r][c]
                + v.pow(Atom::num(2)) * &gm.k2[r][c]
                + gain(r, c)
        })
    });
    // The two residuals with the closed-loop coefficients `cl` (the derived side).
    let open = char_poly(&gm);
    let residuals = |cl: &[Vec<Atom>]| -> (Atom, Atom) {
        let mut rebuilt = Atom::num(0);
        for (k, coefs) in cl.iter().enumerate() {
            for (j, a) in coefs.iter().enumerate() {
                rebuilt += a * v.pow(Atom::num(j as i64)) * s.pow(Atom::num(k as i64));
            }
        }
        let diff = (det(&p) - rebuilt).expand();
        let mut open_diff = Atom::num(0);
        for (k, coefs) in cl.iter().enumerate() {
            let mut a = coefs
                .iter()
                .enumerate()
                .fold(Atom::num(0), |acc, (j, c)| acc + c * v.pow(Atom::num(j as i64)));
            for name in GAINS {
                a = subst(&a, name, &Atom::num(0));
            }
            let d = (a - &open[k]).expand();
            if !is_zero(&d) {
                open_diff = d;
            }
        }
        (diff, open_diff)
    };
    let (diff, open_diff) = residuals(&cl);
    // The derived side perturbed: the coefficient of v^0 s^0, a symbol of it scaled.
    let with_first = |d: &Atom| {
        let mut c = cl.clone();
        c[0][0] = d.clone();
        residuals(&c)
    };
    let poly_perturbed = crate::falsify::perturb_one(&cl[0][0], |d| is_zero(&with_first(d).0));
    let open_perturbed = crate::falsify::perturb_one(&cl[0][0], |d| is_zero(&with_first(d).1));
    vec![
        check_perturbed(
            "closed_loop_poly",
            "the closed-loop characteristic polynomial's coefficients (of v^j s^k) reassemble det(M s^2 + (v C1 + Kd) s + g K0 + v^2 K2 + Kp) for the state feedback u = -K x, K = (Kp Kd), identically in s, v, g, the eight gains and generic matrix entries",
            is_zero(&diff),
            format!("residual: {diff}"),
            poly_perturbed,
        ),
        check_perturbed(
            "closed_loop_open",
            "with every gain zero the closed-loop coefficients are the open-loop characteristic polynomial a0 ... a4",
            is_zero(&open_diff),
            format!("residual: {open_diff}"),
            open_perturbed,
        ),
    ]
}

/// Derives the model's formulas and checks.
#[allow(clippy::needless_range_loop)]
pub fn derive() -> Result<Derivation> {
    let mut checks = Vec::new();
    let (mats, parts) = linearised::matrices(&mut checks)?;
    origin_checks(&mats, &parts, &mut checks);
    linearised::shift_checks(&mut checks, &mats)?;
    let mut formulas = Vec::new();
    let names = [
        ("m", &mats.m, "mass matrix M (kg m^2)"),
        ("c1_", &mats.c1, "velocity-proportional matrix C1 (kg m)"),
        ("k0_", &mats.k0, "gravity stiffness K0 (kg m)"),
        ("k2_", &mats.k2, "velocity-squared stiffness K2 (kg)"),
    ];
    for (prefix, mat, what) in names {
        for r in 0..2 {
            for c in 0..2 {
                formulas.push(Formula {
                    name: format!("{prefix}{}{}", r + 1, c + 1),
                    section: "linear".to_string(),
                    description: format!(
                        "entry ({}, {}) of the {what}, rows (lean, steer) equations, columns (lean, steer)",
                        r + 1,
                        c + 1
                    ),
                    expr: to_lambda(&mat[r][c]),
                });
            }
        }
    }
    for (k, a) in char_poly(&mats).iter().enumerate() {
        formulas.push(Formula {
            name: format!("a{k}"),
            section: "linear".to_string(),
            description: format!(
                "coefficient of s^{k} in det(M s^2 + v C1 s + g K0 + v^2 K2), a polynomial in v"
            ),
            expr: to_lambda(a),
        });
    }
    checks.push(tf_check());
    let tf = tf_numerators(&mats);
    for (i, out) in TF_SIGNALS.iter().enumerate() {
        for (j, input) in TF_SIGNALS.iter().enumerate() {
            for (k, coef) in tf[i][j].iter().enumerate() {
                formulas.push(Formula {
                    name: format!("tf_{out}_{input}_{k}"),
                    section: "linear".to_string(),
                    description: format!(
                        "coefficient of s^{k} in the numerator of the transfer function from the {input} torque to the {out} angle (entry ({}, {}) of adj(M s^2 + v C1 s + g K0 + v^2 K2)); the denominator is the characteristic polynomial a0 ... a4",
                        i + 1,
                        j + 1
                    ),
                    expr: to_lambda(coef),
                });
            }
        }
    }
    checks.extend(closed_loop_checks());
    for (k, coefs) in closed_loop_poly(&mats).iter().enumerate() {
        for (j, coef) in coefs.iter().enumerate() {
            formulas.push(Formula {
                name: format!("cl_a{k}_{j}"),
                section: "linear".to_string(),
                description: format!(
                    "coefficient of v^{j} s^{k} in the closed-loop characteristic polynomial det(M s^2 + (v C1 + Kd) s + g K0 + v^2 K2 + Kp) of the state feedback u = -K x, K = (Kp Kd) with the gains k_<input>_<state> as inputs"
                ),
                expr: to_lambda(coef),
            });
        }
    }
    ensure!(
        checks.iter().all(|c| c.holds || c.id.starts_with("plain_lagrange")),
        "whipple checks failed: {:?}",
        checks.iter().filter(|c| !c.holds).map(|c| &c.id).collect::<Vec<_>>()
    );
    Ok(Derivation {
        model: "whipple".to_string(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        // The inputs: the forward speed, then the feedback gains, which only the closed-loop
        // coefficients `cl_a{k}_{j}` read.
        inputs: std::iter::once("v").chain(GAINS).map(str::to_string).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("whipple"),
        horner_schemes: Vec::new(),
    })
}
pub mod description;
pub mod lean_rider;
