//! The stability of a steady turn with the handlebar held in the concordance (memoir Part II,
//! ch. IV, n° 101–105), computed now from [`carvallo::bicycle_turn`]: Carvallo's bicycle with
//! the constants of n° 117 ([`Constants::MEMOIR`]) as a nonlinear Carvallo–Whipple model,
//! its steady turns at the handlebar angles and speeds of [`TURNS`], and the characteristic
//! equation (C) of n° 101 with all three coefficients, the rolling speed $s$ held by the
//! pedals as the memoir does (the bearing rate held and free-wheeling beside it).
//!
//! The frame's moment $B$ about its pitch axis is not printed in n° 117 (straight running
//! does not need it); the mapping's value is illustrative, and the n° 105 entries repeat the
//! roots with it halved.
//!
//! The n° 105 roots are also computed for the new bicycle of n° 122 at [`NEW_TURN`] and, as a
//! count of the points where they are real and of opposite signs, across [`GRID_GAMMA`] ×
//! [`GRID_KMH`]. n° 122 gives only its $e$, $\mu$, $l$, $\mu_1$; the other constants are
//! carried over from n° 117 ([`Constants::MEMOIR_NEW`]), and because n° 117's $C$ and $L$ then
//! leave the frame a negative central moment about the vertical, a second variant carries the
//! old frame's central moments over instead ([`new_bicycle_central`]).
//!
//! Verdicts ([`crate::policy`]). The memoir reduces each coefficient to its leading term and
//! calls the rest negligible, "of the second order in the angles θ, γ": an approximation it
//! declares ([`crate::policy::approx`]). An approximate value is therefore `rounding` when its
//! relative difference from the exact coefficient is below that declared order,
//! $\theta_0^2 + \gamma^2$ (stated in each note with the difference itself), `agrees` only
//! when exact, and `derivation-differs` beyond the order. Signs and the nature of the roots are
//! claims ([`crate::policy::claim`]).

use std::collections::BTreeMap;

use carvallo::bicycle_straight::{Constants, Equations};
use carvallo::bicycle_turn::{FallEquation, Hold, LockedSteer, SteadyTurn};

use crate::entry::{Derived, Entry, Memoir, Verdict};
use crate::policy::rel_diff;
use crate::policy::{self, number};

/// The steady turns of the concordance: handlebar angle γ (degrees) and speed (km/h), the
/// memoir's 20 and 10 km/h of n° 88.
pub const TURNS: [(f64, f64); 3] = [(5.0, 20.0), (10.0, 20.0), (5.0, 10.0)];

fn label(gdeg: f64, kmh: f64) -> String {
    format!("gamma = {gdeg}°, {kmh} km/h")
}

fn approx(
    section: &str,
    quantity: String,
    memoir: f64,
    derived: f64,
    order: f64,
    note: String,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    Entry {
        section: section.into(),
        quantity,
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict: policy::approx(rel, order, Verdict::DerivationDiffers),
        note: format!(
            "{note}; relative difference {rel:.3e} against the declared second order theta0^2 + gamma^2 = {order:.3e}"
        ),
    }
}

/// `less than {bound:e}` when |x| is below `bound` (rounding noise, not printed), else x.
fn small(x: f64, bound: f64) -> String {
    if x.abs() < bound {
        format!("less than {bound:e}")
    } else {
        format!("{x:.3e}")
    }
}

fn lambda_plus(c: &FallEquation) -> f64 {
    c.roots[1].re
}

/// Entries of one steady turn.
fn turn_entries(bike: &LockedSteer, gdeg: f64, kmh: f64, e: &mut Vec<Entry>) -> Result<(), String> {
    let k = *bike.constants();
    let (gamma, v) = (gdeg.to_radians(), kmh / 3.6);
    let t: SteadyTurn = bike.steady_turn(gamma, v).map_err(|x| x.to_string())?;
    let c = bike.fall_equation(&t, Hold::Rolling).map_err(|x| x.to_string())?;
    let cb = bike.fall_equation(&t, Hold::BearingRate).map_err(|x| x.to_string())?;
    let w = bike.free_wheel(&t).map_err(|x| x.to_string())?;
    let at = label(gdeg, kmh);
    let th = t.lean;
    let order = th * th + gamma * gamma;
    let weight = k.g * (k.mu * k.h + 2.0 * k.mu1 * k.r);
    // (3)' and (2) of n° 86 bis against the exact steady turn.
    if let Some(memoir_lean) = bike.memoir_lean(gamma, v) {
        e.push(approx(
            "86",
            format!("lean theta0 of a steady turn, hands held (rad), reconstructed, {at}"),
            memoir_lean,
            th,
            order,
            format!(
                "memoir (reconstructed, not printed: the memoir gives no number for this turn): (3)' of n° 86 bis, tan(theta) = -(R/l)(R s^2/g) tan(alpha), alpha of n° 57 at theta (eta = 25°), evaluated here at a turn of our choosing, so the verdict judges the approximation the memoir declares (policy approx), never a printed digit; derived: the lean that balances the lean row of the nonlinear model (Newton, residual {} N m, pitch {:.3e} rad, hands' torque {:.4} N m, pedal torque {} N m); (3)' keeps only the frame's centrifugal term: it drops the wheels' gyroscopic 2 B1 s n, the wheels' weight 2 mu1 R and the weight moment g Q of the front contact's trail and the frame's e (the n° 117 coefficient B)",
                small(t.lean_residual, 1e-12),
                t.pitch,
                t.hands_torque,
                small(t.pedal_torque, 1e-12)
            ),
        ));
    }
    let memoir_n = bike.memoir_yaw_rate(gamma, v, th);
    e.push(approx(
        "86",
        format!("turning rate n of a steady turn (1/s), reconstructed, {at}"),
        memoir_n,
        t.yaw_rate,
        order,
        "memoir (reconstructed, not printed): (2) of n° 86, n = (R/l) s tan(alpha) at the exact lean, evaluated here at a turn of our choosing (policy approx); derived: the yaw rate of the nonlinear model's rolling constraints".into(),
    ));
    // (C) itself.
    e.push(Entry {
        section: "101".into(),
        quantity: format!("characteristic equation (C) with the handlebar held and s held, {at}"),
        memoir: Memoir::Formula(
            "(df/dp') lambda^2 + (df/dp) lambda + df/dtheta = 0 (df/dp not evaluated)".into(),
        ),
        derived: Derived::Numbers(BTreeMap::from([
            ("dfdpp".to_string(), c.dfdpp),
            ("dfdp".to_string(), c.dfdp),
            ("dfdtheta".to_string(), c.dfdtheta),
            ("bearing_held_dfdp".to_string(), cb.dfdp),
            ("bearing_held_dfdpp".to_string(), cb.dfdpp),
        ])),
        rel_diff: None,
        verdict: policy::claim(c.dfdpp.is_finite() && c.dfdp.is_finite() && c.dfdtheta.is_finite(), Verdict::DerivationDiffers),
        note: format!(
            "f is the lean row of the nonlinear model with the steer row dropped (the hands hold gamma) and the rear-wheel row dropped (the pedals hold the rolling speed s on the ground; the bearing rate then follows the lean rate); df/dp' = M11 + M13 dU/dp exact, df/dp and df/dtheta by central differences with Richardson's extrapolation (the two levels differ by {}); with the bearing rate held instead (bearing_held_*) df/dtheta is the same, lean {th:.5} rad, pitch {:.3e} rad",
            small(c.error, 1e-5),
            t.pitch
        ),
    });
    // n° 102: df/dp' against A + 2 A1.
    let a2 = k.a2;
    e.push(approx(
        "102",
        format!("df/dp' (kg m^2), {at}"),
        a2,
        c.dfdpp,
        order,
        format!(
            "memoir: df/dp' = A with the wheels' A1 merged into it ('A + A1 + a little'; n° 117 writes A + 2 A1 = {a2}: the frame's A = {:.3} and A1 = 3/2 mu1 R^2 = {:.3} for each wheel); derived: M11 + M13 dU/dp of the model",
            a2 - 3.0 * k.mu1 * k.r * k.r,
            1.5 * k.mu1 * k.r * k.r
        ),
    ));
    // n° 103: dn/dtheta.
    if let Ok((model, memoir)) = bike.yaw_rate_derivative(&t) {
        e.push(approx(
            "103",
            format!("dn/dtheta at fixed gamma and s (1/s per rad), {at}"),
            memoir,
            model,
            order,
            format!(
                "memoir: (R/l) s d tan(alpha)/d theta with the part in d eta/d theta dropped as negligible (n° 103, first remark); derived: Richardson differences of the model's yaw rate along the lean (s held); both are small, as the memoir says: dn/dtheta times theta0 is {:.2} % of n",
                100.0 * (model * th / t.yaw_rate).abs()
            ),
        ));
    }
    // n° 104: df/dtheta.
    let memoir_dth = -weight * th.cos();
    e.push(approx(
        "104",
        format!("df/dtheta (N m), {at}"),
        memoir_dth,
        c.dfdtheta,
        order,
        format!(
            "memoir: -mu g h cos(theta0) with mu h increased by the wheels' 2 mu1 R, -(mu h + 2 mu1 R) g cos(theta0); derived: the whole coefficient; its gravity part is {:.3} N m, its centrifugal part {:.3} N m",
            c.dfdtheta_gravity,
            c.dfdtheta_centrifugal()
        ),
    ));
    e.push(approx(
        "104",
        format!("gravity part of df/dtheta (N m), {at}"),
        memoir_dth,
        c.dfdtheta_gravity,
        order,
        "memoir: the gravity terms reduced to -(mu h + 2 mu1 R) g cos(theta0) (the frame's e d eta/d theta terms and the front wheel's form dropped); derived: the derivative of the model's forcing at zero speeds along the contact".into(),
    ));
    let ratio = c.dfdtheta_centrifugal() / c.dfdtheta_gravity;
    let tan2 = th.tan().powi(2);
    e.push(Entry {
        section: "104".into(),
        quantity: format!("centrifugal part / gravity part of df/dtheta, {at}"),
        memoir: Memoir::Number(tan2),
        derived: Derived::Number(ratio),
        rel_diff: Some(rel_diff(ratio, tan2)),
        verdict: policy::finding(Verdict::DerivationDiffers),
        note: format!(
            "memoir: tan^2(theta0), the ratio of the leading centrifugal term mu R h s n sin(theta) to the gravity term, by (3)'; derived: the ratio of the whole centrifugal part (the frame's, the wheels' gyroscopic terms, the dn/dtheta term and the pitch), {} and of the second order as the memoir says, but not equal to tan^2(theta0): the other centrifugal terms are of the same order. At this lean the whole makes df/dtheta {:.1} % larger than its gravity part",
            if ratio > 0.0 {
                "of the sign of the gravity part (destabilising too)"
            } else {
                "of the opposite sign to the gravity part (stabilising)"
            },
            100.0 * ratio
        ),
    });
    // n° 105: roots.
    let rest = bike
        .steady_turn(gamma, 0.0)
        .and_then(|r| bike.fall_equation(&r, Hold::Rolling))
        .map_err(|x| x.to_string())?;
    let without_dfdp = (-c.dfdtheta / c.dfdpp).sqrt();
    // The frame's B is not in n° 117: the same turn with the central pitch moment halved.
    let ibyy = k.whipple_values().iter().find(|(n, _)| *n == "IByy").map_or(f64::NAN, |x| x.1);
    let half =
        LockedSteer::with_pitch_moment(k, 0.5 * ibyy).map_err(|x| x.to_string()).and_then(|b| {
            let t = b.steady_turn(gamma, v).map_err(|x| x.to_string())?;
            b.fall_equation(&t, Hold::Rolling).map_err(|x| x.to_string())
        })?;
    e.push(Entry {
        section: "105".into(),
        quantity: format!("roots of (C) with the handlebar held (1/s), {at}"),
        memoir: Memoir::Formula(
            "real and of opposite signs: unstable, whatever the speed; df/dp lambda 'peu important'; about the instability at rest".into(),
        ),
        derived: Derived::Numbers(BTreeMap::from([
            ("lambda_minus".to_string(), c.roots[0].re),
            ("lambda_plus".to_string(), lambda_plus(&c)),
            ("lambda_plus_without_dfdp".to_string(), without_dfdp),
            ("lambda_plus_at_rest".to_string(), lambda_plus(&rest)),
            ("bearing_held_lambda_plus".to_string(), lambda_plus(&cb)),
            ("half_pitch_moment_lambda_plus".to_string(), lambda_plus(&half)),
            ("free_wheel_lambda_minus".to_string(), w.roots[0].re),
            ("free_wheel_lambda_plus".to_string(), w.roots[2].re),
        ])),
        rel_diff: None,
        verdict: policy::claim(c.saddle() && cb.saddle() && half.saddle() && w.roots[2].re > 0.0, Verdict::DerivationDiffers),
        note: format!(
            "df/dp' > 0 and df/dtheta < 0: real roots of opposite signs (also with the bearing rate held; free-wheeling, the cubic has a zero root, |lambda| {}, the family of turns in the speed, and one of each sign); df/dp moves lambda_plus by {:.2} % (second order {:.2} %), and lambda_plus is {:.2} % from the one at rest with the same gamma; the frame's B is not in n° 117 (the mapping's central I_Byy = I_Bxx + I_Bzz = {ibyy:.3} kg m^2, illustrative): with it halved the roots stay real and of opposite signs (half_pitch_moment_*)",
            small(w.roots[1].norm(), 1e-9),
            100.0 * (lambda_plus(&c) / without_dfdp - 1.0),
            100.0 * order,
            100.0 * (lambda_plus(&c) / lambda_plus(&rest) - 1.0)
        ),
    });
    Ok(())
}

/// The steady-turn stability entries, computed now (upright running first, then [`TURNS`]).
pub fn entries() -> Vec<Entry> {
    let mut e = Vec::new();
    let bike = match LockedSteer::new(Constants::MEMOIR) {
        Ok(b) => b,
        Err(err) => {
            e.push(failure(&err.to_string()));
            return e;
        }
    };
    // Upright straight running at 20 km/h: the memoir's -724 of n° 117/118 and the linear model.
    let upright =
        bike.steady_turn(0.0, 20.0 / 3.6).and_then(|t| bike.fall_equation(&t, Hold::Rolling));
    match (upright, Equations::via_whipple(&Constants::MEMOIR)) {
        (Ok(c), Ok(lin)) => {
            e.push(number(
                "104",
                "df/dtheta upright, -(mu h + 2 mu1 R) g (N m)",
                -724.0,
                0,
                c.dfdtheta,
                &format!(
                    "n° 117/118 print A = -724; derived from the nonlinear model at 20 km/h upright (the linear model's lean row gives g K0_11 = {:.4}, the two paths differ by {})",
                    lin.k0[0][0],
                    small(c.dfdtheta - lin.k0[0][0], 1e-9)
                ),
            ));
            e.push(number(
                "102",
                "df/dp' upright (kg m^2)",
                Constants::MEMOIR.a2,
                6,
                c.dfdpp,
                &format!(
                    "A + 2 A1 = 100 of n° 117; derived from the nonlinear model upright (df/dp {}: zero by symmetry)",
                    small(c.dfdp, 1e-9)
                ),
            ));
        }
        (Err(err), _) => e.push(failure(&err.to_string())),
        (_, Err(err)) => e.push(failure(&err.to_string())),
    }
    for (gdeg, kmh) in TURNS {
        if let Err(err) = turn_entries(&bike, gdeg, kmh, &mut e) {
            e.push(failure(&err));
        }
    }
    if let Err(err) = new_bicycle_roots(&bike, &mut e) {
        e.push(failure(&err));
    }
    e.push(new_bicycle_grid());
    e
}

/// The turn at which the n° 105 roots are computed for the new bicycle of n° 122: handlebar
/// angle γ (degrees) and speed (km/h).
pub const NEW_TURN: (f64, f64) = (5.0, 20.0);

/// The handlebar angles (degrees) of the new bicycle's grid.
pub const GRID_GAMMA: [f64; 3] = [2.0, 5.0, 10.0];

/// The speeds (km/h) of the new bicycle's grid.
pub const GRID_KMH: [f64; 4] = [10.0, 15.0, 20.0, 25.0];

/// The new bicycle of n° 122 with the frame's central moments of the old one carried over
/// instead of its moments about the rear contact: the memoir gives the new $e$, $\mu$, $l$,
/// $\mu_1$ only, and [`Constants::MEMOIR_NEW`] keeps n° 117's $A + 2A_1$, $C$, $L$, which with
/// the new $\mu e^2 = 7.84 > C = 4$ leave the frame a negative central moment $C - \mu e^2$
/// about the vertical. Here $A + 2A_1 = I_{Bxx} + \mu h^2 + 3\mu_1R^2$, $C = I_{Bzz} + \mu e^2$
/// and $L = I_{Bxz} + \mu eh$ with the old bicycle's central $I_{Bxx}$, $I_{Bzz}$, $I_{Bxz}$.
pub fn new_bicycle_central() -> Constants {
    let (o, n) = (Constants::MEMOIR, Constants::MEMOIR_NEW);
    let ibxx = o.a2 - 3.0 * o.mu1 * o.r * o.r - o.mu * o.h * o.h;
    let ibzz = o.c - o.mu * o.e * o.e;
    let ibxz = o.ll - o.mu * o.e * o.h;
    Constants {
        a2: ibxx + n.mu * n.h * n.h + 3.0 * n.mu1 * n.r * n.r,
        c: ibzz + n.mu * n.e * n.e,
        ll: ibxz + n.mu * n.e * n.h,
        ..n
    }
}

fn central_frame_moments(k: &Constants) -> (f64, f64, f64) {
    let get =
        |name: &str| k.whipple_values().iter().find(|(n, _)| *n == name).map_or(f64::NAN, |x| x.1);
    (get("IBxx"), get("IBzz"), get("IBxz"))
}

/// The roots (C) of n° 105 for the new bicycle of n° 122 at [`NEW_TURN`].
fn new_bicycle_roots(old: &LockedSteer, e: &mut Vec<Entry>) -> Result<(), String> {
    let (gdeg, kmh) = NEW_TURN;
    let (gamma, v) = (gdeg.to_radians(), kmh / 3.6);
    let k = Constants::MEMOIR_NEW;
    let roots = |b: &LockedSteer, speed: f64, hold: Hold| {
        b.steady_turn(gamma, speed)
            .and_then(|t| b.fall_equation(&t, hold))
            .map_err(|x| x.to_string())
    };
    let bike = LockedSteer::new(k).map_err(|x| x.to_string())?;
    let t = bike.steady_turn(gamma, v).map_err(|x| x.to_string())?;
    let c = bike.fall_equation(&t, Hold::Rolling).map_err(|x| x.to_string())?;
    let cb = bike.fall_equation(&t, Hold::BearingRate).map_err(|x| x.to_string())?;
    let w = bike.free_wheel(&t).map_err(|x| x.to_string())?;
    let rest = roots(&bike, 0.0, Hold::Rolling)?;
    let (ibxx, ibzz, ibxz) = central_frame_moments(&k);
    let half = LockedSteer::with_pitch_moment(k, 0.5 * (ibxx + ibzz))
        .map_err(|x| x.to_string())
        .and_then(|b| roots(&b, v, Hold::Rolling))?;
    let central = new_bicycle_central();
    let cc = LockedSteer::new(central)
        .map_err(|x| x.to_string())
        .and_then(|b| roots(&b, v, Hold::Rolling))?;
    let oc = roots(old, v, Hold::Rolling)?;
    let without_dfdp = (-c.dfdtheta / c.dfdpp).sqrt();
    let all = [&c, &cb, &half, &cc, &oc];
    e.push(Entry {
        section: "105".into(),
        quantity: format!("roots of (C), handlebar held (1/s), new bicycle of n° 122, {}", label(gdeg, kmh)),
        memoir: Memoir::Formula("real and of opposite signs: unstable, whatever the speed (n° 105; n° 122 discusses only the straight running of the new bicycle)".into()),
        derived: Derived::Numbers(BTreeMap::from([
            ("lambda_minus".to_string(), c.roots[0].re),
            ("lambda_plus".to_string(), lambda_plus(&c)),
            ("lambda_plus_without_dfdp".to_string(), without_dfdp),
            ("lambda_plus_at_rest".to_string(), lambda_plus(&rest)),
            ("bearing_held_lambda_plus".to_string(), lambda_plus(&cb)),
            ("half_pitch_moment_lambda_plus".to_string(), lambda_plus(&half)),
            ("central_moments_lambda_plus".to_string(), lambda_plus(&cc)),
            ("old_bicycle_lambda_plus".to_string(), lambda_plus(&oc)),
            ("free_wheel_lambda_minus".to_string(), w.roots[0].re),
            ("free_wheel_lambda_plus".to_string(), w.roots[2].re),
        ])),
        rel_diff: None,
        verdict: policy::claim(all.iter().all(|x| x.saddle()) && w.roots[2].re > 0.0, Verdict::DerivationDiffers),
        note: format!(
            "the new bicycle of n° 122 gives e = {}, mu = {} (1/2 mu = 32; the OCR prints 3,2), l = {}, mu1 = {}; carried over from n° 117: R = {}, c1 = {}, eta = 25°, h = {}, A + 2 A1 = {}, C = {}, L = {}, g = {}, and the frame's pitch moment (not printed for either bicycle; the mapping's central I_Byy = I_Bxx + I_Bzz = {:.3} kg m^2, halved in half_pitch_moment_*). With C and L carried over the frame's central moments are I_Bxx = {ibxx:.3}, I_Bzz = C - mu e^2 = {ibzz:.3}, I_Bxz = {ibxz:.3} kg m^2: I_Bzz < 0 is no mass distribution, so central_moments_* carries the old frame's central moments over instead (A + 2 A1 = {:.4}, C = {:.4}, L = {:.4}). with s held df/dp' = {:.3} > 0 and df/dtheta = {:.2} < 0: real roots of opposite signs, as in every variant (bearing rate held, halved pitch moment, central moments, and the old bicycle at the same turn, old_bicycle_*); free-wheeling, one root of each sign and |lambda| of the zero root {}; lean {:.5} rad",
            k.e, k.mu, k.l, k.mu1, k.r, k.c1, k.h, k.a2, k.c, k.ll, k.g,
            ibxx + ibzz,
            central.a2, central.c, central.ll,
            c.dfdpp, c.dfdtheta,
            small(w.roots[1].norm(), 1e-9),
            t.lean
        ),
    });
    Ok(())
}

/// n° 105 across [`GRID_GAMMA`] × [`GRID_KMH`] for the new bicycle of n° 122: the count of
/// grid points where the roots of (C) are real and of opposite signs.
fn new_bicycle_grid() -> Entry {
    let total = GRID_GAMMA.len() * GRID_KMH.len();
    let mut count = [0usize; 3];
    let mut failed = Vec::new();
    let mut range = (f64::INFINITY, f64::NEG_INFINITY);
    let bikes = [LockedSteer::new(Constants::MEMOIR_NEW), LockedSteer::new(new_bicycle_central())];
    for gdeg in GRID_GAMMA {
        for kmh in GRID_KMH {
            let (gamma, v) = (gdeg.to_radians(), kmh / 3.6);
            for (n, hold, bike) in [
                (0, Hold::Rolling, &bikes[0]),
                (1, Hold::BearingRate, &bikes[0]),
                (2, Hold::Rolling, &bikes[1]),
            ] {
                let c = match bike {
                    Ok(b) => b.steady_turn(gamma, v).and_then(|t| b.fall_equation(&t, hold)),
                    Err(err) => Err((*err).into()),
                };
                match c {
                    Ok(c) if c.saddle() => {
                        count[n] += 1;
                        if n == 0 {
                            range = (range.0.min(lambda_plus(&c)), range.1.max(lambda_plus(&c)));
                        }
                    }
                    Ok(_) => {}
                    Err(err) => failed.push(format!("{}: {err}", label(gdeg, kmh))),
                }
            }
        }
    }
    let fmt = |x: &[f64]| x.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(", ");
    Entry {
        section: "105".into(),
        quantity: "roots of (C) real and of opposite signs across a grid, new bicycle of n° 122".into(),
        memoir: Memoir::Formula("real and of opposite signs: unstable, whatever the speed".into()),
        derived: Derived::Numbers(BTreeMap::from([
            ("grid_points".to_string(), total as f64),
            ("saddle_points".to_string(), count[0] as f64),
            ("bearing_held_saddle_points".to_string(), count[1] as f64),
            ("central_moments_saddle_points".to_string(), count[2] as f64),
            ("lambda_plus_min".to_string(), range.0),
            ("lambda_plus_max".to_string(), range.1),
        ])),
        rel_diff: None,
        verdict: policy::claim(count.iter().all(|c| *c == total), Verdict::DerivationDiffers),
        note: format!(
            "gamma = {} degrees × {} km/h, the constants of the previous entry (C and L of n° 117 carried over; central_moments_*: the old frame's central moments carried over); a point counts when (C) has real roots of opposite signs; lambda_plus_* are the range of the positive root with s held{}",
            fmt(&GRID_GAMMA),
            fmt(&GRID_KMH),
            if failed.is_empty() { String::new() } else { format!("; failed: {}", failed.join("; ")) }
        ),
    }
}

fn failure(why: &str) -> Entry {
    Entry {
        section: "105".into(),
        quantity: "steady turn with the handlebar held".into(),
        memoir: Memoir::Formula("unstable".into()),
        derived: Derived::Number(f64::NAN),
        rel_diff: None,
        verdict: policy::finding(Verdict::DerivationDiffers),
        note: format!("the computation failed: {why}"),
    }
}

/// The memoir's claims checked in this report ([`crate::claims`]).
pub fn claims() -> Vec<crate::claims::Claim> {
    Vec::new()
}

/// The memoir's assertions in this report's sections, n° by n°, with how each is covered.
pub const INVENTORY: &[crate::claims::Assertion] = &[];
