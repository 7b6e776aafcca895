//! The memoir's claims on the bicycle's steady states with hands and without (n° 79–100),
//! checked now: the inertia terms term by term by point masses ([`super::inertia_terms`]), the
//! reduction of the equilibrium equation to the hoop's and the unicycle's with the generated
//! programs of the three models, the orders of the kinematic coefficients, the signs of the
//! steady turn in the nonlinear model ([`carvallo::bicycle_turn`]) and the bound of n° 89 at
//! exact steady turns. Listed in [`super::steady::INVENTORY`].

use carvallo::bicycle_geometry::Geometry;
use carvallo::bicycle_kinematics::Kinematics;
use carvallo::bicycle_steady::{BicycleParams, BicycleSteady, SteadyState};
use carvallo::bicycle_straight::Constants;
use carvallo::bicycle_turn::LockedSteer;
use carvallo::hoop::Hoop;
use carvallo::unicycle::{Rider, Unicycle, Wheel};
use carvallo::whipple::steady_turn::{hands_free::HandsFree, TurnSolver};
use carvallo::whipple::Whipple;

use super::inertia_terms::{frame_terms_with, wheel_terms_with, Route, RING, STATES};
use crate::claims::Claim;
use crate::entry::Verdict;
use crate::policy::{self, rel_diff, AGREEMENT_TOLERANCE};
use crate::sample::Rng;

/// Seed of the reduction points of n° 85.
pub const SEED_85: u64 = 0x6e38_352d_6865_6c70;
/// Points of the reduction of n° 85.
pub const POINTS_85: usize = 48;
/// The steady turns (handlebar angle in degrees, speed in km/h) of the sign and bound checks:
/// the memoir's 20 and 10 km/h of n° 88, both signs of γ.
pub const TURNS: [(f64, f64); 6] =
    [(5.0, 20.0), (10.0, 20.0), (5.0, 10.0), (-5.0, 20.0), (-10.0, 20.0), (-5.0, 10.0)];

/// A perturbation of the derived side at run time (issue 38): the named rows of the generated
/// `bicycle_steady` program (or of the generated relations (I)) scaled by `factor`, the fall
/// equation then recomputed from its six rows. `None` is the model as derived.
#[derive(Clone, Copy, Debug)]
struct Scaled {
    rows: &'static [&'static str],
    factor: f64,
}

/// The centrifugal (inertia) rows of the fall equation, n° 81-83.
const CENTRIFUGAL: &[&str] = &["fall_rear", "fall_front", "fall_frame"];

/// The rows of the fall equation (n° 84): inertia rows minus gravity rows.
const FALL_ROWS: [(&str, f64); 6] = [
    ("fall_rear", 1.0),
    ("fall_front", 1.0),
    ("fall_frame", 1.0),
    ("fall_grav_rear", -1.0),
    ("fall_grav_front", -1.0),
    ("fall_grav_frame", -1.0),
];

/// The output `name` of the generated program at `x`, under the perturbation `scaled`.
fn output(
    bike: &BicycleSteady,
    x: &SteadyState,
    name: &str,
    scaled: Option<Scaled>,
) -> Option<f64> {
    let Some(sc) = scaled else {
        return bike.output(x, name);
    };
    if name == "fall_equilibrium" {
        return FALL_ROWS
            .iter()
            .map(|(row, sign)| output(bike, x, row, scaled).map(|v| sign * v))
            .sum();
    }
    let v = bike.output(x, name)?;
    Some(if sc.rows.contains(&name) { v * sc.factor } else { v })
}

/// A generated quantity `value` named `name` under the perturbation `scaled`.
fn scaled_value(name: &str, value: f64, scaled: Option<Scaled>) -> f64 {
    match scaled {
        Some(sc) if sc.rows.contains(&name) => value * sc.factor,
        _ => value,
    }
}

/// `claims` with, for each of `ids`, the same check on the perturbed derived side (the claim
/// of the same id in `perturbed`) recorded as its falsification.
fn falsified(claims: Vec<Claim>, perturbed: &[Claim], ids: &[(&str, &str)]) -> Vec<Claim> {
    claims
        .into_iter()
        .map(|c| match ids.iter().find(|(id, _)| *id == c.id) {
            Some((_, what)) => match perturbed.iter().find(|p| p.id == c.id) {
                Some(p) => c.falsified_by(what, p.clone()),
                None => c,
            },
            None => c,
        })
        .collect()
}

/// The exact steady state of the generated `bicycle_steady` program at lean `theta`, steer
/// `gamma` and rolling rate `s`, the geometry and kinematics of n° 43–66 solved for the old
/// bicycle of n° 52.
pub fn exact_state(theta: f64, gamma: f64, s: f64) -> Option<SteadyState> {
    let geo = Geometry::old_model();
    let kin = Kinematics::old_model();
    let c = geo.solve(theta, gamma).ok()?;
    let fw = geo.front_wheel(theta, gamma, c.sigma, c.mu);
    let r = kin.relations(theta, gamma).ok()?;
    Some(SteadyState {
        theta,
        theta1: -fw.beta,
        alpha: fw.alpha,
        eta: c.sigma,
        omega: c.mu,
        s,
        s1: r.steady_sigma1_rate * s,
        n: r.steady_n * s,
        deta: r.d_eta_d_theta,
        dnu: r.d_nu_d_theta,
        deta_g: r.d_eta_d_gamma,
        dnu_g: r.d_nu_d_gamma,
        p: 0.0,
        deta_t: 0.0,
    })
}

fn worst(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(0.0f64, |m, v| if v.is_nan() { f64::NAN } else { m.max(v) })
}

/// Whether each of the six symbolic checks `frame_83_term1` … `frame_83_term6` of
/// `generated/bicycle_steady.checks.tsv` holds (empty when a check is missing).
fn symbolic_83() -> Vec<bool> {
    let checks = carvallo::artifacts::parse_checks(carvallo::artifacts::BICYCLE_STEADY.checks)
        .unwrap_or_default();
    (1..=6)
        .map_while(|k| {
            let id = format!("frame_83_term{k}");
            checks.iter().find(|c| c.id == id).map(|c| c.holds)
        })
        .collect()
}

/// The symbolic check `id` of `generated/bicycle_steady.checks.tsv`: (holds, detail); `None`
/// when it is missing.
fn steady_check(id: &str) -> Option<(bool, String)> {
    let checks = carvallo::artifacts::parse_checks(carvallo::artifacts::BICYCLE_STEADY.checks)
        .unwrap_or_default();
    checks.into_iter().find(|c| c.id == id).map(|c| (c.holds, c.detail))
}

/// Whether the engine's check `id` of `generated/whipple.checks.tsv` holds (false when missing).
fn engine_check(id: &str) -> bool {
    carvallo::artifacts::parse_checks(carvallo::artifacts::WHIPPLE.checks)
        .unwrap_or_default()
        .iter()
        .any(|c| c.id == id && c.holds)
}

/// n° 98: a sideways shift of the body, by two independent derivations: the memoir's bicycle
/// in his variables with the loaded frame's centre of gravity off its plane, and the mechanics
/// engine's Carvallo–Whipple bicycle with the rear body turned by ε about the ground trace OI,
/// by Kane's method; each claim states the perturbed description that breaks the engine's
/// check (a negative control recorded at regeneration).
fn lateral_shift_claims() -> Vec<Claim> {
    let how = "derived symbolically twice. (1) In the memoir's variables (codegen/src/derive/bicycle/steady/mod.rs): the whole loaded frame translated by y_c along j (sum m y = mu y_c, sum m x y = mu e y_c, sum m y z = mu h y_c, sum m y^2 + mu y_c^2), the steady rows of the fall equation (n° 83-84) and of the handlebar equation (n° 91-93) recomputed and compared with the unshifted ones, exactly and at first order in theta, alpha, n, d eta/d theta, d eta/d gamma and y_c (generated/bicycle_steady.checks.tsv, check";
    // The claim with the engine's verdict `engine_ok` (its own check, or the negative
    // control's outcome on the perturbed description).
    let claim = |id: &str,
                 check: &str,
                 engine: &str,
                 says: &str,
                 reading: &str,
                 engine_ok: bool| {
        let (holds, detail) = steady_check(check).unwrap_or((false, "check missing".into()));
        let kane = format!("kane_shift_{engine}");
        let exact = detail.rsplit_once("exact change ").map_or("", |(_, e)| e).to_string();
        Claim::new(
            id,
            "98",
            says,
            &format!("{how} {check}). (2) By the mechanics engine (codegen/src/derive/whipple/linearised.rs, shift_checks): the Carvallo-Whipple bicycle's description with the rear body (frame and rider) turned by epsilon about the rear frame's ground trace OI, derived by Kane's method and linearised in lean, steer, speeds and epsilon about upright running, symbolic in the 25 parameters (generated/whipple.checks.tsv, check {kane}; the modified Lagrange equations equal Kane's on the unshifted bicycle, check kane_equals_lagrange). Agrees when both derivations hold"),
            &[
                ("check_holds", f64::from(u8::from(holds))),
                ("engine_checks_hold", f64::from(u8::from(engine_ok))),
            ],
            policy::claim(holds && engine_ok, Verdict::DerivationDiffers),
            &format!("{reading}; exact change with the shift: {exact}"),
        )
    };
    // Each claim with the description that breaks the engine's check: the negative control
    // recorded at regeneration holds when the perturbed description fails that check.
    let with_control = |id: &str,
                        check: &str,
                        engine: &str,
                        says: &str,
                        reading: &str,
                        control: &str,
                        what: &str| {
        let own =
            claim(id, check, engine, says, reading, engine_check(&format!("kane_shift_{engine}")));
        let broken = engine_check(control);
        own.falsified_by(
            &format!("the engine's description perturbed: {what} (re-derived at regeneration; generated/whipple.checks.tsv, negative control {control})"),
            claim(id, check, engine, says, reading, !broken),
        )
    };
    vec![
        with_control(
            "steady-shift-gravity-moment",
            "shift_fall_gravity",
            "gravity",
            "With the body moved sideways by the angle epsilon, the gravity moment of the fall equation mu g h sin(theta) becomes mu g h sin(theta + epsilon).",
            "exactly mu g (h sin(theta) + y_c cos(theta)) = mu g sqrt(h^2 + y_c^2) sin(theta + epsilon) with tan(epsilon) = y_c/h: the memoir's form holds with h read as the distance of the centre of gravity from the trace OI, and at first order in epsilon as printed; the engine's bicycle gives epsilon's coefficient in the lean row -g mB zB, the loaded frame's mu g h",
            "shift_gravity_breaks_with_axle",
            "the body turned about the axis through the rear wheel's centre instead of the ground trace OI",
        ),
        with_control(
            "steady-shift-centrifugal-moment",
            "shift_fall_inertia",
            "centrifugal",
            "The moment of the centrifugal force in the fall equation is not changed sensibly by the sideways shift of the body.",
            "holds at first order: the change is of the second order (y_c times n, n^2 or the angles); in the engine's bicycle epsilon's coefficient in the lean row does not depend on the speed",
            "shift_centrifugal_breaks_with_steer",
            "the shift also turning the handlebar by epsilon about the steering axis",
        ),
        with_control(
            "steady-shift-handlebar-unchanged",
            "shift_steer_unchanged",
            "handlebar",
            "The handlebar equation is not changed by the sideways shift of the body (the frame's terms come from the virtual velocities dM/d eta, dM/d nu, whose variations are negligible).",
            "its frame gravity term is unchanged exactly and its inertia terms change by the third-order -mu e (d eta/d gamma) n^2 y_c sin(theta) cos(theta) only; in the engine's bicycle epsilon's coefficient in the steer row vanishes",
            "shift_handlebar_breaks_with_whole_frame",
            "the steering axis and the front frame carried by the shifted body (the whole frame turned about OI)",
        ),
    ]
}

/// n° 81–83, 99: the inertia terms term by term, the point velocities from the kinematics
/// `route` (the memoir's in the report).
fn inertia_claims(route: Route) -> Vec<Claim> {
    let f = frame_terms_with(route);
    let w = wheel_terms_with(route);
    let tol = 1e-10;
    let mut out = Vec::new();
    let how_frame = format!("the loaded frame as 8 point masses symmetric about its plane (e, h, A, B, C, L computed from them), velocities M' = I R (s + eta') + |Psi (M - O) of n° 99, virtual velocity dM/dtheta = |I(M - O) - (d eta/d theta)|j(M - S) + (d nu/d theta)|K(M - O) of n° 83 differentiated exactly (I' = J n, j' = |Phi j); each of the six parallelepiped sums taken point by point against the printed term, at {STATES} seeded arbitrary states (theta, p, n, s, eta', d eta/d theta, d nu/d theta and the rates of the last two drawn freely: these are identities) and {STATES} steady ones (p = eta' = 0 and both rates zero, the underlined terms dropped); tolerance {tol:e} relative");
    out.push(Claim::new(
        "steady-frame-decomposition",
        "83",
        "The sum m M'|(dM/d theta)' of the loaded frame splits into exactly six terms: the first line's three parallelepipeds and [I O' M'] vanish.",
        &how_frame,
        &[("max_rel_six_terms_vs_whole_sum", f.decomposition)],
        policy::claim(f.decomposition <= tol, Verdict::DerivationDiffers),
        "the six computed terms sum to the whole sum m M'|(dM/d theta)' at every state, underlined terms included",
    ));
    let names =
        |ks: &[usize]| ks.iter().map(|k| format!("({})", k + 1)).collect::<Vec<_>>().join(", ");
    let failing =
        |v: &[f64; 6]| (0..6).filter(|&k| v[k].is_nan() || v[k] > tol).collect::<Vec<usize>>();
    let bad_steady = failing(&f.steady);
    let bad_whole = failing(&f.whole);
    let bad_fixed = failing(&f.corrected);
    let mut ev: Vec<(String, f64)> = Vec::new();
    for k in 0..6 {
        ev.push((format!("max_rel_term{}_steady", k + 1), f.steady[k]));
    }
    ev.push(("max_rel_term4_corrected".into(), f.corrected[3]));
    let ev_ref: Vec<(&str, f64)> = ev.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    out.push(Claim::new(
        "steady-frame-six-terms-steady",
        "83",
        "The steady parts of the six terms (1)-(6) of the loaded frame as printed in n° 83 (the underlined terms dropped).",
        &how_frame,
        &ev_ref,
        policy::claim(bad_steady.is_empty(), if bad_steady == [3] && f.corrected[3] <= tol { Verdict::MemoirError } else { Verdict::DerivationDiffers }),
        &format!(
            "steady parts that do not agree: {}. Term (4), read with mu R e sin(theta) where the OCR prints mu R sin(theta) (dimension), has the steady part (d eta/d theta) n^2 cos(theta)(L cos(theta) - mu R e sin(theta)) where the points give (d eta/d theta) n^2 cos^2(theta)(mu R e - L) (the corrected form agrees to {:.1e}): this one term is the whole error of the loaded frame's row in the tables of n° 85 and 94 (entries there). It is of the third order in the angles, so the reductions of n° 86 and 95 are unaffected",
            if bad_steady.is_empty() { "none".to_string() } else { names(&bad_steady) },
            f.corrected[3]
        ),
    ));
    let mut ev: Vec<(String, f64)> = Vec::new();
    for k in 0..6 {
        ev.push((format!("max_rel_term{}_printed", k + 1), f.whole[k]));
        ev.push((format!("max_rel_term{}_corrected", k + 1), f.corrected[k]));
    }
    ev.push(("max_rel_printed_sum".into(), f.sum_whole));
    // The same six terms derived symbolically (generated checks `frame_83_term1` … `term6`).
    let symbolic = symbolic_83();
    let symbolic_bad: Vec<usize> = (0..6).filter(|&k| symbolic.get(k) != Some(&true)).collect();
    ev.push(("symbolic_terms_holding".into(), (6 - symbolic_bad.len()) as f64));
    let ev_ref: Vec<(&str, f64)> = ev.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    let how_unsteady = format!("{how_frame}; and independently, symbolically: each term derived from its definition with symbolica in any motion (generated/bicycle_steady.checks.tsv, checks frame_83_term1 to frame_83_term6, their sum frame_83_six_terms_sum and its steady part frame_83_steady), the two routes must name the same failing terms");
    let routes_agree = symbolic.len() == 6 && symbolic_bad == bad_whole;
    out.push(Claim::new(
        "steady-frame-six-terms-unsteady",
        "83",
        "The six terms (1)-(6) of the loaded frame as printed in n° 83 with their underlined (non-steady) parts, the sum m M'|(dM/d theta)' the stability of n° 100-105 starts from.",
        &how_unsteady,
        &ev_ref,
        policy::claim(bad_whole.is_empty() && routes_agree, if bad_fixed.is_empty() && routes_agree { Verdict::MemoirError } else { Verdict::DerivationDiffers }),
        &format!(
            "terms that do not agree as printed: {}; with the corrections below every term agrees{}. (3), (4), (6) carry L with the sign opposite to the one of n° 99-100 (2 T0 = ... - 2 L p n cos(theta), dT0/dp = A p - L n cos(theta), both agreeing with the derivation for L = sum m z x): the moment of momentum about O has the k-component C n cos(theta) - L p, printed L p + C n cos(theta) in (3) and (6), and (4) has -L p^2 and L cos(theta) for +L p^2 and -L cos(theta); (4) also has the wrong steady term above; (5) lacks -B eta' (its bracket's eta' coefficient is mu R (2h - R) - B). Terms (1) and (2) hold whole",
            if bad_whole.is_empty() { "none".to_string() } else { names(&bad_whole) },
            if bad_fixed.is_empty() { String::new() } else { format!(" except {}", names(&bad_fixed)) }
        ),
    ));
    let how_wheel = format!("each wheel a ring of {RING} equal masses (its moments about the contact point are then exactly 3/2, 2, 1/2 mu1 R^2, checked to {:.1e}), velocities M' = |Omega(M - O) of a rolling wheel (n° 2, 5); the sums taken point by point at {STATES} seeded arbitrary and {STATES} steady states; tolerance {tol:e} relative", w.ring_moments);
    out.push(Claim::new(
        "steady-rear-wheel-terms",
        "81",
        "The rear wheel's sum m M'|(dM/d theta)' is B1 s n cos(theta) + (B1 - C1) n^2 sin(theta) cos(theta) plus the underlined (d nu/d theta)'[B1 s sin(theta) + (C1 cos^2 + B1 sin^2) n] + mu1 R^2 p s (d nu/d theta) cos(theta), which vanishes in a steady state.",
        &how_wheel,
        &[("max_rel_whole", w.rear_whole), ("max_rel_term2", w.rear_term2), ("ring_moments_max_rel", w.ring_moments)],
        policy::claim(w.rear_whole <= tol && w.rear_term2 <= tol, Verdict::DerivationDiffers),
        "the printed formula holds at every state, non-steady part included; the parallelepiped [Theta M' M'] is zero as the memoir says",
    ));
    let front_ok_steady = w.front_printed_steady <= tol && w.front_route <= tol;
    out.push(Claim::new(
        "steady-front-wheel-terms",
        "82",
        "The front wheel's sum m M'|(dM/d theta)' is (2) mu1 R^2 p1 s1 [Theta1 I1 j1] + (3) Theta1'|(A1 p1 I1 + B1 q1 j1 + C1 r1 k1) with Theta1' of (1'), and in a steady state (cos(alpha) - sin(alpha) cos(theta) d eta/d theta)[B1 s1 n cos(theta1) + (B1 - C1) n^2 sin(theta1) cos(theta1)].",
        &format!("{how_wheel}; the front wheel's axes at a free heading alpha and lean theta1 (n° 58), Theta1 = I - j d eta/d theta + K d nu/d theta + j1 d sigma1/d theta with its exact derivative (j1' = |(I1 p1 + K n1) j1) or with the printed (1')"),
        &[
            ("max_rel_route_exact_theta1_dot", w.front_route),
            ("max_rel_printed_steady", w.front_printed_steady),
            ("max_rel_printed_whole", w.front_printed_whole),
            ("max_rel_sign_of_j1_term_flipped", w.front_sign_corrected),
        ],
        policy::claim(front_ok_steady && w.front_printed_whole <= tol, Verdict::MemoirError),
        "the route (2) + (3) holds at every state with the exact Theta1' (term (2) with R^2, the OCR reads one R), and the steady result holds; but (1') writes (-p1 k1 + I1 n1 cos(theta1)) d sigma1/d theta where the derivative of + j1 d sigma1/d theta is (+p1 k1 - I1 n1 cos(theta1)) d sigma1/d theta (the sign copied from the frame's -j d eta/d theta term just before it); with that sign flipped the printed non-steady sum holds. The slip is harmless in a steady state (p1 = 0 and the I1 component meets J1 at right angles), which is all the memoir uses it for",
    ));
    out.push(Claim::new(
        "steady-wheel-kinetic-energies",
        "99",
        "The doubled kinetic energies of the wheels are 2 T1 = A1 p^2 + B1 (s + n sin(theta))^2 + C1 n^2 cos^2(theta) and 2 T2 the same with the front wheel's p1, s1, n1, theta1.",
        &how_wheel,
        &[("max_rel", w.kinetic)],
        policy::claim(w.kinetic <= tol, Verdict::DerivationDiffers),
        "sum m M'^2 of the rings against the printed forms, both wheels, arbitrary and steady states",
    ));
    out
}

/// n° 85: the bicycle's equilibrium equation reduces to the hoop's and to the unicycle's.
fn reduction_claim(scaled: Option<Scaled>) -> Claim {
    let mut rng = Rng(SEED_85);
    let (mut hoop_d, mut uni_d, mut hoop_m, mut uni_m) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for _ in 0..POINTS_85 {
        let radius = rng.uniform(0.3, 0.7);
        let wheel_mass = rng.uniform(1.0, 8.0);
        let m = wheel_mass * radius * radius;
        let c = rng.uniform(3.0, 15.0);
        let a = rng.uniform(40.0, 120.0);
        let p = BicycleParams {
            radius,
            g: rng.uniform(5.0, 15.0),
            mass: rng.uniform(40.0, 100.0),
            e: rng.uniform(0.0, 0.4),
            h: rng.uniform(0.8, 1.3),
            a,
            b: a + rng.uniform(-c, c),
            c,
            l_product: rng.uniform(-10.0, 10.0),
            wheel_mass,
            a1: 1.5 * m,
            b1: 2.0 * m,
            c1: 0.5 * m,
            wheelbase: rng.uniform(0.9, 1.3),
            offset: rng.uniform(0.0, 0.1),
        };
        let Ok(bike) = BicycleSteady::new(p) else {
            return failed_reduction();
        };
        let x = SteadyState {
            theta: rng.uniform(-0.6, 0.6),
            theta1: rng.uniform(-0.6, 0.6),
            alpha: rng.uniform(-0.6, 0.6),
            eta: rng.uniform(0.2, 0.6),
            omega: rng.uniform(0.0, 0.5),
            s: rng.uniform(2.0, 30.0),
            s1: rng.uniform(2.0, 30.0),
            n: rng.uniform(-2.0, 2.0),
            // the memoir's limit: d eta/d theta = d nu/d theta = 0
            deta: 0.0,
            dnu: 0.0,
            ..SteadyState::default()
        };
        let o = |name: &str| output(&bike, &x, name, scaled).unwrap_or(f64::NAN);
        let (Ok(hoop), Ok(uni)) = (
            Hoop::new(p.radius, p.wheel_mass, p.g),
            Unicycle::new(
                p.radius,
                p.g,
                Rider { mass: p.mass, height: p.h, a: p.a, b: p.b, c: p.c, l: p.l_product },
                Wheel { mass: p.wheel_mass, a1: p.a1, b1: p.b1, c1: p.c1 },
            ),
        ) else {
            return failed_reduction();
        };
        // (E) of the hoop is p' at p = 0: times A1 it is the rear wheel's moment (N m).
        let hoop_eq = p.a1 * hoop.equilibrium(x.theta, x.s, x.n);
        let uni_eq = uni.equilibrium(x.theta, x.s, x.n);
        let rear = o("fall_rear") - o("fall_grav_rear");
        let rear_frame = rear + o("fall_frame") - o("fall_grav_frame");
        let rear_m = o("memoir_fall_rear") - o("memoir_fall_grav_rear");
        let rear_frame_m = rear_m + o("memoir_fall_frame") - o("memoir_fall_grav_frame");
        hoop_d = worst([hoop_d, rel_diff(rear, hoop_eq)]);
        uni_d = worst([uni_d, rel_diff(rear_frame, uni_eq)]);
        hoop_m = worst([hoop_m, rel_diff(rear_m, hoop_eq)]);
        uni_m = worst([uni_m, rel_diff(rear_frame_m, uni_eq)]);
    }
    let holds = [hoop_d, uni_d, hoop_m, uni_m].iter().all(|v| *v <= AGREEMENT_TOLERANCE);
    Claim::new(
        "steady-reduces-to-hoop-and-unicycle",
        "85",
        "'On retrouve l'équation d'équilibre du cerceau en négligeant les termes qui proviennent de la roue directrice et du cadre. En négligeant la roue directrice seulement, on obtient une équation qui reproduit celle du monocycle quand on fait d eta/d theta = 0, d nu/d theta = 0.'",
        &format!("generated bicycle_steady: (fall_rear - fall_grav_rear) against A1 times the generated hoop (E) of n° 8 (p' at p = 0), and (fall_rear + fall_frame - fall_grav_rear - fall_grav_frame) against the generated unicycle (E) of n° 29 with the rider's constants mu, h, A, B, C, L set to the loaded frame's and the wheel's to the rear wheel's; the same with the memoir's printed rows (memoir_fall_*); {POINTS_85} seeded points (hoop wheels of 1-8 kg and 0.3-0.7 m, frames of 40-100 kg, |theta| <= 0.6, s 2-30/s, |n| <= 2), d eta/d theta = d nu/d theta = 0; agreement within {AGREEMENT_TOLERANCE:e} relative"),
        &[
            ("max_rel_rear_vs_hoop", hoop_d),
            ("max_rel_rear_frame_vs_unicycle", uni_d),
            ("max_rel_printed_rear_vs_hoop", hoop_m),
            ("max_rel_printed_rear_frame_vs_unicycle", uni_m),
        ],
        policy::claim(holds, Verdict::DerivationDiffers),
        "holds exactly, derived and printed rows alike (the printed frame row's error sits in d eta/d theta terms, which the limit removes); the hoop's equation is recovered with the wheel's own A1 as the factor of p'",
    )
}

fn failed_reduction() -> Claim {
    Claim::new(
        "steady-reduces-to-hoop-and-unicycle",
        "85",
        "The bicycle's equilibrium equation reduces to the hoop's and the unicycle's.",
        "construction of the models failed",
        &[],
        Verdict::DerivationDiffers,
        "a model could not be built from the seeded constants",
    )
}

/// n° 86 and 95: the orders of the kinematic coefficients, by halving the angles, for the
/// geometry `geo` (the old bicycle of n° 52 in the report).
fn order_claims(geo: Geometry) -> Vec<Claim> {
    let kin = Kinematics::new(geo);
    let eps = 0.02;
    // a steady-turn-like position: gamma opposite to theta (n° 97)
    let at = |k: f64| kin.relations(k * eps, -k * eps).ok();
    let y_at = |k: f64| {
        let (t, g) = (k * eps, -k * eps);
        geo.solve(t, g).ok().map(|c| geo.front_wheel(t, g, c.sigma, c.mu).contact[1])
    };
    let (Some(r1), Some(r2), Some(y1), Some(y2), Ok(r0)) =
        (at(1.0), at(2.0), y_at(1.0), y_at(2.0), kin.relations(0.0, 0.0))
    else {
        return Vec::new();
    };
    let ratio = |a: f64, b: f64| b / a;
    let ry = ratio(y1, y2);
    let rdeta = ratio(r1.d_eta_d_theta, r2.d_eta_d_theta);
    let rdnu = ratio(r1.d_nu_d_theta, r2.d_nu_d_theta);
    let rdeta_g = ratio(r1.d_eta_d_gamma, r2.d_eta_d_gamma);
    let rdnu_g = ratio(r1.d_nu_d_gamma, r2.d_nu_d_gamma);
    let near = |r: f64, target: f64| (r - target).abs() <= 0.05 * target;
    // the factor (R sin(omega) - c)/l of y at theta = 0, largest at gamma = 0 (omega = eta0)
    let sg = (10f64).to_radians();
    let factor = geo
        .solve(0.0, sg)
        .map(|c| -geo.front_wheel(0.0, sg, c.sigma, c.mu).contact[1] / (geo.wheelbase() * sg.sin()))
        .unwrap_or(f64::NAN);
    let bound = (geo.radius() * geo.sigma0().sin() - geo.offset()) / geo.wheelbase();
    let how = format!("generated relations (I) of n° 66 and the exact contact (old bicycle of n° 52) at theta = {eps} rad, gamma = -{eps} rad and at twice both: a quantity of order k grows by 2^k (tolerance 5 %)");
    let c86 = Claim::new(
        "steady-orders-fall",
        "86",
        "y is of the first order with the small factor (R sin(omega) - c)/l < 0,07; d eta/d theta is of the first order and d nu/d theta of the second.",
        &how,
        &[
            ("growth_y", ry),
            ("growth_d_eta_d_theta", rdeta),
            ("growth_d_nu_d_theta", rdnu),
            ("y_factor_at_theta0_gamma10", factor),
            ("y_factor_bound_R_sin_eta0_minus_c_over_l", bound),
        ],
        policy::claim(near(ry, 2.0) && near(rdeta, 2.0) && near(rdnu, 4.0) && factor < bound, Verdict::DerivationDiffers),
        "holds; the factor's bound is 0.0733 (printed 0,07)",
    );
    let c95 = Claim::new(
        "steady-orders-handlebar",
        "95",
        "d eta/d gamma is of the first order and d nu/d gamma of order zero (n° 66).",
        &how,
        &[
            ("growth_d_eta_d_gamma", rdeta_g),
            ("growth_d_nu_d_gamma", rdnu_g),
            ("d_eta_d_gamma_upright", r0.d_eta_d_gamma),
            ("d_nu_d_gamma_upright", r0.d_nu_d_gamma),
        ],
        policy::claim(near(rdeta_g, 2.0) && near(rdnu_g, 1.0) && r0.d_eta_d_gamma.abs() < 1e-12 && r0.d_nu_d_gamma.abs() > 0.01, Verdict::DerivationDiffers),
        "holds: d eta/d gamma vanishes upright and grows linearly, d nu/d gamma is (R sin(eta0) - c)/l upright",
    );
    vec![c86, c95]
}

/// Steady turns of the nonlinear model `bike` at [`TURNS`]: (gamma, speed m/s, lean, yaw
/// rate).
fn turns(bike: &LockedSteer) -> Option<Vec<(f64, f64, f64, f64)>> {
    TURNS
        .iter()
        .map(|&(gdeg, kmh)| {
            let t = bike.steady_turn(gdeg.to_radians(), kmh / 3.6).ok()?;
            Some((t.gamma, t.speed, t.lean, t.yaw_rate))
        })
        .collect()
}

/// n° 86 bis, 87, 88, 89, 96, 97: signs and sizes of the steady turn, for the geometry `geo`,
/// the nonlinear model `bike` and the first-order model's constants `params` (the old bicycle
/// of n° 52, n° 117's constants and those of n° 96 in the report).
fn turn_claims(geo: Geometry, bike: Option<&LockedSteer>, params: BicycleParams) -> Vec<Claim> {
    let mut out = Vec::new();
    let Some(ts) = bike.and_then(turns) else {
        return out;
    };
    // n° 86 bis: alpha and n opposite to theta; lean left, handlebar left, turn left.
    let mut all = true;
    let mut min_margin = f64::INFINITY;
    let mut alphas = Vec::new();
    for &(gamma, _, lean, n) in &ts {
        let alpha = geo
            .solve(lean, gamma)
            .map(|c| geo.front_wheel(lean, gamma, c.sigma, c.mu).alpha)
            .unwrap_or(f64::NAN);
        alphas.push(alpha);
        all &= alpha * lean < 0.0 && n * lean < 0.0 && gamma * n > 0.0;
        min_margin = min_margin.min((alpha * lean).abs().min((n * lean).abs()));
    }
    out.push(Claim::new(
        "steady-turns-toward-the-lean",
        "86 bis",
        "alpha and n have the sign opposite to theta: 'si la bicyclette penche à gauche, le cavalier doit ramener à lui la main gauche et la bicyclette converge alors à gauche'.",
        "the steady turns of the nonlinear Carvallo-Whipple model with the handlebar held (carvallo::bicycle_turn, constants of n° 117; Newton on the lean row) at gamma = ±5°, ±10° and 20, 10 km/h; alpha of n° 57 at the turn's (theta, gamma) from the exact contact; signs in Carvallo's conventions (theta > 0 leans right, gamma, alpha, n > 0 turn left)",
        &[
            ("turns", ts.len() as f64),
            ("lean_at_gamma_plus5_20kmh", ts[0].2),
            ("yaw_rate_at_gamma_plus5_20kmh", ts[0].3),
            ("alpha_at_gamma_plus5_20kmh", alphas[0]),
            ("smallest_product_magnitude", min_margin),
        ],
        policy::claim(all, Verdict::DerivationDiffers),
        "holds exactly (not only at first order): at every turn the bicycle leans, steers and turns to the same side, alpha and n of the sign opposite to theta",
    ));
    // n° 89: the bound epsilon < (e/h)(c/l) at exact steady turns.
    let (e, h) = (0.20, 1.0);
    let bound = e / h * geo.offset() / geo.wheelbase();
    let mut eps = Vec::new();
    for &(gamma, _, lean, _) in &ts {
        let v = geo
            .solve(lean, gamma)
            .map(|c| {
                let [x, y] = geo.front_wheel(lean, gamma, c.sigma, c.mu).contact;
                (e / h * y / (x * lean.sin())).abs()
            })
            .unwrap_or(f64::NAN);
        eps.push(v);
    }
    let fast = worst([eps[0], eps[1], eps[3], eps[4]]);
    let slow = worst([eps[2], eps[5]]);
    out.push(Claim::new(
        "steady-neglected-term-bound",
        "89",
        "The relative size of the neglected -mu g e cos(theta) d eta/d theta is below (e/h)(c/l) = 0,015, because y/sin(theta) is 'une petite fraction de c - R sin(omega), surtout aux grandes vitesses'.",
        "epsilon = (e/h) y/(x sin(theta)) (printed (1) of n° 89, symbolic check epsilon_89) with x, y of the exact front contact (old bicycle of n° 52) at the lean and handlebar angle of the nonlinear model's steady turns of claim steady-turns-toward-the-lean; e = 0.20 m, h = 1 m as in n° 89",
        &[
            ("bound", bound),
            ("largest_epsilon_20kmh", fast),
            ("largest_epsilon_10kmh", slow),
            ("epsilon_gamma5_20kmh", eps[0]),
            ("epsilon_gamma5_10kmh", eps[2]),
        ],
        policy::claim(fast <= bound && slow <= bound, Verdict::MemoirError),
        &format!(
            "at 20 km/h the bound holds ({fast:.4}); at 10 km/h it does not ({slow:.4} > {bound:.4}): sin(gamma)/sin(theta) is about |tan(alpha)/tan(theta)|, which the memoir takes from n° 88 as 0,035 at 20 km/h where it is 0.35 (1.4 at 10 km/h), so y/sin(theta) is not a small fraction of c - R sin(omega) at moderate speed. The conclusion that the term is negligible still holds in these turns (epsilon of a few per cent)"
        ),
    ));
    // n° 97: both wheels lean to the same side.
    let mut same = true;
    let mut ratios = Vec::new();
    for &(gamma, _, lean, _) in &ts {
        let r = geo
            .solve(lean, gamma)
            .map(|c| -geo.front_wheel(lean, gamma, c.sigma, c.mu).beta / lean)
            .unwrap_or(f64::NAN);
        same &= r > 0.0;
        ratios.push(r);
    }
    let bike = BicycleSteady::new(params);
    let first_order = bike.map(|b| b.theta1_over_theta(25f64.to_radians())).unwrap_or(f64::NAN);
    out.push(Claim::new(
        "steady-wheels-lean-alike",
        "97",
        "'Je trouve bien, comme il était à prévoir, une valeur de theta1 de même signe que theta: les deux roues doivent pencher du même côté dans une conversion.'",
        "theta1 = -beta of n° 57 from the exact contact at the nonlinear model's steady turns (claim steady-turns-toward-the-lean), and the generated first-order ratio theta1_over_theta of the handlebar equation (memoir's constants of n° 96)",
        &[
            ("smallest_theta1_over_theta_exact", ratios.iter().copied().fold(f64::INFINITY, f64::min)),
            ("largest_theta1_over_theta_exact", ratios.iter().copied().fold(0.0, f64::max)),
            ("theta1_over_theta_first_order", first_order),
        ],
        policy::claim(same && first_order > 0.0, Verdict::DerivationDiffers),
        "holds: theta1/theta is positive, and above 1, in every turn (the front wheel leans more, n° 97's geometric statement)",
    ));
    // n° 96: omega <= eta in the steady turns, on the side of gamma the model's steady turns
    // take (gamma opposite to theta at every turn above, n° 97).
    let opposite_turns = ts.iter().filter(|&&(gamma, _, lean, _)| gamma * lean < 0.0).count();
    let side = if opposite_turns == ts.len() { -1.0 } else { 1.0 };
    let mut max_excess = f64::NEG_INFINITY;
    let mut cases = 0usize;
    for it in 0..=8 {
        for ig in 0..=12 {
            let theta = (5.0 * it as f64).to_radians();
            let gamma = side * (5.0 * ig as f64).to_radians();
            if let Ok(c) = geo.solve(theta, gamma) {
                max_excess = max_excess.max(c.mu - geo.sigma0());
                cases += 1;
            }
        }
    }
    let opposite = geo.solve(0.3, 0.3).map(|c| c.mu - geo.sigma0()).unwrap_or(f64::NAN);
    out.push(Claim::new(
        "steady-omega-below-eta",
        "96",
        "mu (e/R)(R sin(omega) - c)/l has the upper limit mu (e/R)(R sin(eta) - c)/l: omega does not exceed eta = 25°.",
        "the exact contact angle omega (mu of ch. I) of the old bicycle of n° 52 on the grid theta = 0..40°, gamma = 0..-60° by 5°, against eta0 = 25°: gamma opposite to theta, the side the nonlinear model's steady turns take (every turn of claim steady-turns-toward-the-lean has gamma opposite to theta, n° 97; were one on the other side, the grid would be gamma = 0..60°)",
        &[
            ("cases", cases as f64),
            ("steady turns with gamma opposite to theta", opposite_turns as f64),
            ("largest_omega_minus_eta_rad", max_excess),
            ("omega_minus_eta_at_theta_gamma_0_3_same_sign", opposite),
        ],
        policy::claim(cases > 0 && max_excess <= 1e-12, Verdict::DerivationDiffers),
        "holds wherever gamma and theta have opposite signs, which the steady turns have; with both of one sign omega exceeds eta (last number), a position no steady turn with hands takes",
    ));
    out
}

/// n° 79, 86 bis, 87, 88: the handlebar's and the pedals' actions.
fn action_claims(scaled: Option<Scaled>) -> Vec<Claim> {
    let mut out = Vec::new();
    let Ok(bike) = BicycleSteady::new(BicycleParams::memoir()) else {
        return out;
    };
    let r = bike.params().radius;
    let s20 = 20.0 / 3.6 / r;
    let gamma = 10f64.to_radians();
    let f = |s: f64| {
        exact_state(0.0, gamma, s)
            .and_then(|x| output(&bike, &x, "fall_equilibrium", scaled))
            .unwrap_or(f64::NAN)
    };
    let (f0, f1, f2) = (f(0.0), f(s20), f(2.0 * s20));
    let growth = (f2 - f0) / (f1 - f0);
    let x = exact_state(0.0, gamma, s20);
    let a = x.and_then(|x| bike.output(&x, "dfdpp_frame")).unwrap_or(f64::NAN);
    // What the memoir infers from the s^2 law (which holds by construction, every steady
    // centrifugal term being a product of two rates ∝ s): the handlebar angle that holds a
    // given lean shrinks with the speed. The exact steady handlebar angle at theta = 5° (gamma
    // of the opposite sign, n° 97) where the steady fall equation vanishes, by bisection.
    let lean = 5f64.to_radians();
    let fall = |g: f64, s: f64| {
        exact_state(lean, g, s)
            .and_then(|x| output(&bike, &x, "fall_equilibrium", scaled))
            .unwrap_or(f64::NAN)
    };
    let holding_angle = |s: f64| {
        let (mut lo, mut hi) = (-0.8, -1e-9);
        let (flo, fhi) = (fall(lo, s), fall(hi, s));
        let product = flo * fhi;
        if product.is_nan() || product >= 0.0 {
            return f64::NAN;
        }
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if fall(mid, s) * flo > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let (g10, g20, g40) = (holding_angle(s20 / 2.0), holding_angle(s20), holding_angle(2.0 * s20));
    // Second route: n° 88's first-order law tan(alpha)/tan(theta) = -g l/(R s)^2 gives 1/4 when
    // the speed doubles; the exact ratio must be within the declared second order of it.
    let first_order = bike.tan_alpha_over_tan_theta(2.0 * s20) / bike.tan_alpha_over_tan_theta(s20);
    let ratio = g40 / g20;
    let order = lean * lean + g20 * g20;
    out.push(Claim::new(
        "steady-handlebar-action-grows-with-speed",
        "86 bis",
        "An error of the handlebar angle gives the centrifugal force a preponderance the larger the greater the speed: 'aux grandes vitesses, le guidon doit être manœuvré avec précaution', the handlebar moved imperceptibly.",
        "what the memoir infers, not the s^2 law itself (every steady centrifugal term is a product of two rates ∝ s, so f(2 s) - f(0) = 4 (f(s) - f(0)) by construction; shown as evidence at theta = 0, gamma = 10°): the handlebar angle gamma that holds a lean of 5° in a steady turn, where the generated steady fall equation (fall_equilibrium, exact geometry and kinematics of n° 43-66, memoir's constants) vanishes, bisected at 10, 20 and 40 km/h; it must shrink with the speed, and its ratio between 40 and 20 km/h must be within the declared second order theta^2 + gamma^2 of n° 88's first-order 1/4 (ratio_88)",
        &[
            ("moment_at_rest_N_m", f0),
            ("moment_20kmh_N_m", f1),
            ("growth_when_speed_doubles", growth),
            ("gamma holding 5° at 10 km/h (rad)", g10),
            ("gamma holding 5° at 20 km/h (rad)", g20),
            ("gamma holding 5° at 40 km/h (rad)", g40),
            ("gamma ratio 40/20 km/h", ratio),
            ("first-order ratio (n° 88)", first_order),
        ],
        policy::claim(
            g10.abs() > g20.abs() && g20.abs() > g40.abs() && (ratio - first_order).abs() <= order,
            Verdict::DerivationDiffers,
        ),
        &format!(
            "holds: the handlebar angle that holds a 5° lean falls from {:.2}° at 10 km/h to {:.2}° at 20 km/h and {:.2}° at 40 km/h, the ratio {ratio:.3} when the speed doubles against n° 88's first-order 1/4 (within theta^2 + gamma^2 = {order:.3}); the moment's growth of exactly 4 is the construction of the centrifugal terms, not the evidence",
            g10.to_degrees(),
            g20.to_degrees(),
            g40.to_degrees()
        ),
    ));
    out.push(Claim::new(
        "steady-abrupt-handlebar-throws-outward",
        "87",
        "A rider who turns the handlebar to the left without leaning 'sera jeté à terre sur sa droite'.",
        "sign of the generated fall equation f = (dT/dp)' (centrifugal minus gravity rows, the memoir's (δθ) of n° 80) at the exact upright state theta = 0 with the handlebar turned left (gamma = +10°) at 20 km/h, with the frame's coefficient of p' (dfdpp_frame) positive: then p' > 0, the lean grows to the right (theta > 0)",
        &[("f_N_m", f1), ("coefficient_of_p_prime_kg_m2", a)],
        policy::claim(f1 > 0.0 && a > 0.0, Verdict::DerivationDiffers),
        "holds: the centrifugal moment of a left turn taken upright throws the bicycle to the right, at a rate growing as s^2 (claim steady-handlebar-action-grows-with-speed)",
    ));
    let q = bike.tan_alpha_over_tan_theta(s20 / 2.0) / bike.tan_alpha_over_tan_theta(s20);
    out.push(Claim::new(
        "steady-gravity-quadrupled-at-half-speed",
        "88",
        "'Pour une vitesse moitié moindre, 10 km à l'heure, l'influence de la pesanteur est quadruplée.'",
        "generated ratio_88 = tan(alpha)/tan(theta) along (3)' at 10 and 20 km/h (memoir's constants). Holds by construction because the generated ratio_88 is the closed form -g l/(R s)^2 of n° 88, whose ratio at half the speed is 4 whatever the constants: the check shows that the derivation gives n° 88's s^-2 law, which the claim restates",
        &[("ratio_10_over_20", q)],
        policy::claim((q - 4.0).abs() <= 1e-12, Verdict::DerivationDiffers),
        "holds (the ratio is -g l/(R s)^2); the values themselves are ten times the printed ones (entries of n° 88)",
    ));
    // n° 79: the pedals' torque acts on the wheel's rotation relative to the frame, sigma + eta.
    let kin = Kinematics::old_model();
    let turn = LockedSteer::new(Constants::MEMOIR)
        .ok()
        .and_then(|b| b.steady_turn(5f64.to_radians(), 20.0 / 3.6).ok());
    let (deta_t, deta_g) =
        turn.and_then(|t| kin.relations(t.lean, t.gamma).ok()).map_or((f64::NAN, f64::NAN), |r| {
            (
                scaled_value("d_eta_d_theta", r.d_eta_d_theta, scaled),
                scaled_value("d_eta_d_gamma", r.d_eta_d_gamma, scaled),
            )
        });
    let upright =
        kin.relations(0.0, 0.0).map_or(f64::NAN, |r| r.d_eta_d_theta.abs() + r.d_eta_d_gamma.abs());
    out.push(Claim::new(
        "steady-pedals-enter-the-rolling-equation-only",
        "79",
        "'L'action sur les pédales entre seulement dans l'équation de marche; l'action sur le guidon entre dans l'équation de guidon seule.'",
        "virtual work of the actions: the handlebar torque acts on the fork's rotation relative to the frame, delta gamma itself; the pedals' torque Q acts on the rear wheel's rotation relative to the frame, which n° 68 gives as delta sigma + delta eta, so its generalised forces are Q, Q d eta/d theta, Q d eta/d gamma on (sigma, theta, gamma); d eta/d theta and d eta/d gamma from the generated relations (I) of n° 66 at the nonlinear model's steady turn gamma = 5°, 20 km/h",
        &[
            ("d_eta_d_theta_in_turn", deta_t),
            ("d_eta_d_gamma_in_turn", deta_g),
            ("sum_of_both_upright", upright),
        ],
        policy::claim(deta_t.abs() < 1e-12 && deta_g.abs() < 1e-12, Verdict::MemoirError),
        "holds for the handlebar; for the pedals only upright and straight: off it the pedal torque enters the fall equation as Q d eta/d theta and the handlebar equation as Q d eta/d gamma (first order in the angles), by the memoir's own rule of n° 68 (the bearings turn by delta sigma + delta eta). In the steady states of n° 80-98 the pedals give no torque (no resistance in the model), so the conclusions there are unaffected; in the stability of n° 100-105, where the pedals hold s, the term belongs to the fall equation",
    ));
    out
}

/// n° 86: the leading inertia term.
fn leading_term_claim(scaled: Option<Scaled>) -> Option<Claim> {
    let bike = BicycleSteady::new(BicycleParams::memoir()).ok()?;
    let p = bike.params();
    let t = LockedSteer::new(Constants::MEMOIR)
        .ok()?
        .steady_turn(5f64.to_radians(), 20.0 / 3.6)
        .ok()?;
    let x = exact_state(t.lean, t.gamma, t.speed / p.radius)?;
    let o = |name: &str| output(&bike, &x, name, scaled).unwrap_or(f64::NAN);
    let lead = p.mass * p.radius * p.h * x.s * x.n * x.theta.cos();
    let centrifugal = o("fall_rear") + o("fall_front") + o("fall_frame");
    let rest = centrifugal - lead;
    let front = o("fall_front");
    let share = (rest / lead).abs();
    Some(Claim::new(
        "steady-leading-inertia-term",
        "86",
        "'Le terme le plus important de l'inertie vient du cadre monté; c'est mu R h s n cos(theta)'; the front wheel's terms are small.",
        "the generated steady centrifugal rows (fall_rear + fall_front + fall_frame, memoir's constants with the illustrative frame moments) at the exact state of the nonlinear model's steady turn gamma = 5°, 20 km/h (geometry and kinematics of n° 43-66 solved at its lean)",
        &[
            ("leading_term_N_m", lead),
            ("other_centrifugal_terms_over_leading", share),
            ("front_wheel_over_leading", (front / lead).abs()),
        ],
        policy::claim(share < 0.5, Verdict::DerivationDiffers),
        "holds: the other centrifugal terms together are a fraction of the leading one, mostly the wheels' gyroscopic B1 s n (the memoir merges the rear wheel's into mu R h by 'changing slightly the constants')",
    ))
}

/// n° 86: « cette quantité [y/l] est diminuée quand le cadre prend une inclinaison θ ».
fn y_with_lean_claim(turn_side: f64) -> Claim {
    let geo = Geometry::old_model();
    let l = geo.wheelbase();
    let y = |theta: f64, gamma: f64| {
        geo.solve(theta, gamma)
            .map(|c| geo.front_wheel(theta, gamma, c.sigma, c.mu).contact[1] / l)
            .unwrap_or(f64::NAN)
    };
    let mut ev: Vec<(String, f64)> = Vec::new();
    // The steady turn leans the frame to the side opposite to γ in these variables (the
    // turn toward the lean, n° 86 bis, 97: the position of steady-orders-fall); the other side
    // is shown beside.
    let (mut turn_cases, mut turn_smaller, mut other_larger) = (0usize, 0usize, 0usize);
    for gdeg in [5.0f64, 10.0] {
        let g = gdeg.to_radians();
        let upright = y(0.0, g);
        ev.push((format!("y/l at θ = 0, γ = {gdeg}°"), upright));
        for tdeg in [-20.0f64, -10.0, -5.0, 5.0, 10.0, 20.0] {
            let v = y(tdeg.to_radians(), g);
            if tdeg * turn_side > 0.0 {
                turn_cases += 1;
                turn_smaller += usize::from(v.abs() < upright.abs());
            } else {
                other_larger += usize::from(v.abs() > upright.abs());
            }
            ev.push((format!("y/l at θ = {tdeg}°, γ = {gdeg}°"), v));
        }
    }
    ev.push(("leans of the steady turn (θ opposite to γ)".to_string(), turn_cases as f64));
    ev.push(("of these with |y/l| below upright".to_string(), turn_smaller as f64));
    ev.push(("leans to the other side with |y/l| above upright".to_string(), other_larger as f64));
    let evr: Vec<(&str, f64)> = ev.iter().map(|(a, b)| (a.as_str(), *b)).collect();
    Claim::new(
        "steady-y-smaller-when-leaning",
        "86",
        "y/l = -((R sin ω - c)/l) sin γ with the frame vertical (n° 34), and « cette quantité est diminuée quand le cadre prend une inclinaison θ ».",
        "the exact front contact y = J|OM of the generated geometry (the old bicycle of n° 52, contact equations of n° 54 solved by Newton) at γ = 5° and 10°, θ = 0 and ±5°, ±10°, ±20°: |y/l| against its upright value. Judged in the position n° 86 studies, the steady turn, which leans the frame to the side opposite to γ in these variables (the position of steady-orders-fall); holds if |y/l| is below its upright value at every such lean",
        &evr,
        policy::claim(turn_cases > 0 && turn_smaller == turn_cases, Verdict::DerivationDiffers),
        "holds in the steady turn: leaning into the turn diminishes |y/l| (by 3 to 24 % at 5° to 20°). Leaning to the other side increases it, so the statement is about the turn's side, not any lean",
    )
}

/// n° 97: « il serait impossible d'effectuer une conversion sans les mains » (the rider's
/// centre of gravity kept in the frame's plane), judged on the nonlinear Carvallo–Whipple
/// bicycle with the memoir's constants: its hands-free steady turns (steer torque zero) branch
/// from upright running where $\det(gK_0 + v^2K_2) = 0$.
fn no_hands_claim(constants: Constants) -> Option<Claim> {
    let bike = LockedSteer::new(constants).ok()?;
    let params = bike.model().params().clone();
    let solver = TurnSolver::new(&params).ok()?;
    let hf = HandsFree::new(&solver);
    let branches = hf.branch_speeds(0.0, 20.0);
    let linear = Whipple::new(params).capsize_speed();
    // One hands-free turn at 0.1 rad of lean on the forward family followed from the branch
    // point, re-solved as a steady turn at its speed and lean (its steer torque must vanish).
    let family = branches.first().and_then(|&vb| hf.family(0.0, vb).ok());
    let seed = family.as_ref().and_then(|f| {
        f.points
            .windows(2)
            .find(|w| (w[0].lean - 0.1) * (w[1].lean - 0.1) <= 0.0)
            .map(|w| [w[0].speed, 0.1, w[0].steer])
    });
    let turn = seed.and_then(|z| hf.refine(z));
    let (v1, steer1) = turn.map_or((f64::NAN, f64::NAN), |(z, _)| (z[0], z[2]));
    let torque1 = solver
        .turns(v1, 0.1)
        .ok()
        .and_then(|t| {
            t.turns
                .iter()
                .filter(|t| (t.steer - steer1).abs() < 1e-6)
                .map(|t| t.steer_torque)
                .next()
        })
        .unwrap_or(f64::NAN);
    let vb = branches.first().copied().unwrap_or(f64::NAN);
    let exists = turn.is_some() && torque1.abs() <= 1e-9;
    Some(Claim::new(
        "steady-no-hands-turn-impossible",
        "97",
        "With the centre of gravity kept in the frame's plane, 'il serait impossible d'effectuer une conversion sans les mains': the upright position is the only equilibrium without hands.",
        "the nonlinear Carvallo-Whipple bicycle with the memoir's constants (carvallo::bicycle_turn::LockedSteer, constants of n° 117, as Whipple parameters): the branch points of its hands-free steady turns on upright running (the sign changes of the lean and steer rows' determinant, carvallo::whipple::steady_turn::hands_free, 2000 speed steps to 20 m/s, bisected), beside the same bicycle's capsize speed by the linear model's Hurwitz route (generated/whipple.ir); then one hands-free turn at a lean of 0.1 rad by Newton from the branch point, re-solved by the steady-turn route at its speed and lean, whose steer torque must vanish (1e-9 N m). Holds if no hands-free turn exists",
        &[
            ("forward_branch_speed", vb),
            ("linear_capsize_speed", linear.unwrap_or(f64::NAN)),
            ("turn_speed_at_lean_0_1", v1),
            ("turn_steer_at_lean_0_1", steer1),
            ("turn_steer_torque_at_lean_0_1", torque1),
        ],
        policy::claim(!exists, Verdict::MemoirError),
        "does not hold exactly: the nonlinear bicycle turns without hands, its forward hands-free family branching from upright running at the linear model's capsize speed and reaching a lean of 0.1 rad at the speed and steer given. Within the memoir's approximation the conclusion comes from its printed ratio theta1/theta < 1 of n° 96, which drops a factor sin(omega) (see the n° 97 entries): with the factor kept its own first-order equations also give a hands-free speed (the n° 97 entry 'speed of a steady turn without hands', for the steady-state chapter's constants)",
    ))
}

/// n° 117's bicycle with its weight reversed, g = -9.81 m/s^2: a model ingredient's sign
/// flipped (the weight then pulls the frame back upright, as a pendulum's below its support),
/// which [`Constants::validate`] refuses and [`LockedSteer::new_unchecked`] builds.
pub(crate) const WEIGHT_REVERSED: Constants =
    Constants { g: -Constants::MEMOIR.g, ..Constants::MEMOIR };

/// The words stating [`WEIGHT_REVERSED`].
pub(crate) const WEIGHT_REVERSED_TEXT: &str = "the weight reversed in the nonlinear model, g = -9.81 m/s^2 instead of 9.81 (n° 117's bicycle otherwise; the lean is then restored by gravity, as a pendulum's below its support)";

/// The claims of n° 79–100.
pub fn claims() -> Vec<Claim> {
    const FLIPPED: &str = "the centrifugal rows of the generated fall equation (fall_rear, fall_front, fall_frame) scaled by -1, the fall equation recomputed from its rows";
    let flipped = action_claims(Some(Scaled { rows: CENTRIFUGAL, factor: -1.0 }));
    let sigma_alone =
        action_claims(Some(Scaled { rows: &["d_eta_d_theta", "d_eta_d_gamma"], factor: 0.0 }));
    let actions = falsified(
        action_claims(None),
        &flipped,
        &[
            ("steady-handlebar-action-grows-with-speed", FLIPPED),
            ("steady-abrupt-handlebar-throws-outward", FLIPPED),
        ],
    );
    let actions = falsified(
        actions,
        &sigma_alone,
        &[(
            "steady-pedals-enter-the-rolling-equation-only",
            "d eta/d theta and d eta/d gamma of the generated relations (I) scaled by 0: the rear wheel turning by delta sigma alone relative to the frame, as the memoir's statement assumes",
        )],
    );
    let (pedals, actions): (Vec<Claim>, Vec<Claim>) =
        actions.into_iter().partition(|c| c.section == "79");
    let mut c = pedals;
    // The point sums with the contacts sliding sideways (rolling without sliding dropped), and
    // with the front wheel's axle rate of the sign of the memoir's (1').
    const SLIP: &str = "the contacts sliding sideways at 0.1 m/s along J (rolling without sliding dropped: O' and O1' gain 0.1 J, every point of the frame and of the wheels moves with it)";
    let slipping = inertia_claims(Route::LateralSlip(0.1));
    let inertia = falsified(
        inertia_claims(Route::Derived),
        &slipping,
        &[
            ("steady-frame-decomposition", SLIP),
            ("steady-frame-six-terms-steady", SLIP),
            ("steady-frame-six-terms-unsteady", SLIP),
            ("steady-rear-wheel-terms", SLIP),
            ("steady-wheel-kinetic-energies", SLIP),
        ],
    );
    c.extend(falsified(
        inertia,
        &inertia_claims(Route::FrontAxleRateNegated),
        &[(
            "steady-front-wheel-terms",
            "the rate of the front wheel's axle j1 negated in the point velocities' route, j1' = -(I1 p1 + K n1) x j1 (the sign the memoir's (1') gives its d sigma1/d theta term)",
        )],
    ));
    c.push(reduction_claim(None).falsified_by(
        "the generated rear wheel's centrifugal row fall_rear scaled by 1 + 1e-9",
        reduction_claim(Some(Scaled { rows: &["fall_rear"], factor: 1.0 + 1e-9 })),
    ));
    if let (Some(nominal), Some(heavy_front)) = (
        leading_term_claim(None),
        leading_term_claim(Some(Scaled { rows: &["fall_front"], factor: 20.0 })),
    ) {
        c.push(nominal.falsified_by(
            "the generated front wheel's centrifugal row fall_front scaled by 20",
            heavy_front,
        ));
    }
    // The old bicycle of n° 52 with the fork offset c = R sin(sigma0) = 0.1606 m instead of
    // 0.08 m: zero trail, the factor (R sin(omega) - c)/l of n° 86 zero upright.
    const ZERO_TRAIL: &str = "the fork offset c = R sin(sigma0) = 0.1606 m instead of 0.08 m (zero trail: the factor (R sin(omega) - c)/l of y vanishes upright), the old bicycle of n° 52 otherwise";
    let memoir_bike = LockedSteer::new(Constants::MEMOIR).ok();
    let zero_trail = Geometry::new(0.38, 1.10, 0.38 * 25f64.to_radians().sin(), 25f64.to_radians());
    let (order_zero, turn_zero) = match zero_trail {
        Ok(g) => (order_claims(g), turn_claims(g, memoir_bike.as_ref(), BicycleParams::memoir())),
        Err(_) => (Vec::new(), Vec::new()),
    };
    c.extend(falsified(
        order_claims(Geometry::old_model()),
        &order_zero,
        &[("steady-orders-fall", ZERO_TRAIL), ("steady-orders-handlebar", ZERO_TRAIL)],
    ));
    c.push(y_with_lean_claim(-1.0).falsified_by(
        "the steady turn's lean taken on the side of gamma (its sign flipped)",
        y_with_lean_claim(1.0),
    ));
    c.extend(actions);
    // The trail reversed in all three models: the fork offset c = R sin(eta) + 0.1 m, so that
    // R sin(eta) - c = c1 = -0.1 m.
    const TRAIL_REVERSED: &str = "the trail reversed in the geometry, the nonlinear model and the first-order handlebar equation: the fork offset c = R sin(eta) + 0.1 = 0.2606 m instead of 0.08 m (R sin(eta) - c = c1 = -0.1 m instead of 0.08 m); then X = mu (e/R)(R sin(eta) - c)/l lies between -2 mu1 sin(eta) and -mu1 sin(eta) and the first-order theta1/theta = (2 mu1 sin(eta) + X)/(mu1 sin(eta) + X) is negative";
    let reversed_offset = 0.38 * 25f64.to_radians().sin() + 0.1;
    let trail_reversed = match Geometry::new(0.38, 1.10, reversed_offset, 25f64.to_radians()) {
        Ok(g) => turn_claims(
            g,
            LockedSteer::new(Constants { c1: -0.1, ..Constants::MEMOIR }).ok().as_ref(),
            BicycleParams { offset: reversed_offset, ..BicycleParams::memoir() },
        ),
        Err(_) => Vec::new(),
    };
    let turn = falsified(
        falsified(
            turn_claims(Geometry::old_model(), memoir_bike.as_ref(), BicycleParams::memoir()),
            &turn_zero,
            &[("steady-neglected-term-bound", ZERO_TRAIL)],
        ),
        &turn_claims(
            Geometry::old_model(),
            Some(&LockedSteer::new_unchecked(WEIGHT_REVERSED)),
            BicycleParams::memoir(),
        ),
        &[
            ("steady-turns-toward-the-lean", WEIGHT_REVERSED_TEXT),
            ("steady-omega-below-eta", WEIGHT_REVERSED_TEXT),
        ],
    );
    c.extend(falsified(turn, &trail_reversed, &[("steady-wheels-lean-alike", TRAIL_REVERSED)]));
    let negative_trail = Constants { c1: -Constants::MEMOIR.c1, ..Constants::MEMOIR };
    match (no_hands_claim(Constants::MEMOIR), no_hands_claim(negative_trail)) {
        (Some(nominal), Some(perturbed)) => c.push(nominal.falsified_by(
            "the front contact's distance from the steering axis c1 = R sin(eta) - c negated (the trail reversed, a model ingredient changed): no branch point on upright running, no hands-free turn",
            perturbed,
        )),
        (nominal, _) => c.extend(nominal),
    }
    c.extend(lateral_shift_claims());
    c
}
