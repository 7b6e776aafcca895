//! The unicycle's claims (memoir n° 20–42 with n° 74 and n° 78): each conclusion of the
//! memoir checked on the generated full model (`generated/unicycle.ir`: rider and wheel kept
//! apart), on its normalised forms of n° 32–41, on the hoop's model (n° 20, 36) and on the two
//! variants of [`carvallo::unicycle::variants`] (the rider's pitch about the axle, n° 42; the
//! rolling rate held by the pedals, n° 78), or by the elementary kinematics of a rolling wheel
//! and a crank (n° 25–26 bis); and the inventory of every assertion of those sections.

use std::collections::BTreeMap;
use std::f64::consts::PI;

use crate::perturb::{unicycle_eval as eval, unicycle_out as out, Perturbation, Target};
use carvallo::hoop::Hoop;
use carvallo::unicycle::variants::Pitch;
use carvallo::unicycle::{Rider, Unicycle, Wheel};
use carvallo::unicycle_discussion::{
    bisect, curve_n_s, minimum_on_e, n32, s_on_e, trinomial, Point, H_OVER_R,
};

use crate::claims::{Assertion, Claim, Status};
use crate::entry::Verdict;
use crate::policy::{self, rel_diff};

use super::{points, with};

/// The curves of n° 32–41 as [`carvallo::unicycle_discussion`] computes them, but read
/// through [`crate::perturb::unicycle_out`], so that a perturbed `unicycle` program is seen
/// (issue 38); the same formulas, the same evaluation points.
mod read {
    use carvallo::unicycle_discussion::{bisect, minimise, n32};

    use crate::perturb::unicycle_out as out;

    /// s on (N) at θ, the positive root of (E) at n = -s; `None` beyond the asymptote.
    pub(super) fn curve_n_s(theta_deg: f64) -> Option<f64> {
        let e = |s: f64| out(&n32(theta_deg, s, -s), "equilibrium_n32");
        let (e0, e1) = (e(0.0), e(1.0));
        let s2 = -e0 / (e1 - e0);
        (s2.is_finite() && s2 >= 0.0).then(|| s2.sqrt())
    }

    /// s on (E) of n° 32 at θ and n (linear in s).
    pub(super) fn s_on_e(theta_deg: f64, n: f64) -> f64 {
        let e0 = out(&n32(theta_deg, 0.0, n), "equilibrium_n32");
        let e1 = out(&n32(theta_deg, 1.0, n), "equilibrium_n32");
        -e0 / (e1 - e0)
    }

    /// (n0, s0): the smallest s on (E) at θ and its n.
    pub(super) fn minimum_on_e(theta_deg: f64) -> (f64, f64) {
        let n0 = minimise(|n| s_on_e(theta_deg, n), -5.0, -1e-3);
        (n0, s_on_e(theta_deg, n0))
    }

    /// (a, b, c) of the generated trinomial S(n^2) = a m^2 + b m + c of n° 41.
    pub(super) fn trinomial(theta_deg: f64) -> (f64, f64, f64) {
        let t = |m: f64| out(&n32(theta_deg, 0.0, m.sqrt()), "trinomial_n41");
        let (t0, t1, t2) = (t(0.0), t(1.0), t(2.0));
        let a = (t2 - 2.0 * t1 + t0) / 2.0;
        (a, t1 - t0 - a, t0)
    }

    /// The two points (n, s) of the limit of stability at θ; `None` where the trinomial's
    /// roots are not real and positive.
    pub(super) fn stability_limit(theta_deg: f64) -> Option<[(f64, f64); 2]> {
        let (a, b, c) = trinomial(theta_deg);
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 || a == 0.0 {
            return None;
        }
        let roots = [(-b - disc.sqrt()) / (2.0 * a), (-b + disc.sqrt()) / (2.0 * a)];
        if roots.iter().any(|m| *m <= 0.0) {
            return None;
        }
        Some(roots.map(|m| {
            let n = -m.sqrt();
            (n, s_on_e(theta_deg, n))
        }))
    }

    /// The two zeros of the first member of n° 41, -b - 2 sqrt(ac), in degrees.
    pub(super) fn first_member_roots() -> (f64, f64) {
        let first = |th: f64| {
            let (a, b, c) = trinomial(th);
            -b - 2.0 * (a * c).sqrt()
        };
        (bisect(first, 5.0, 30.0), bisect(first, 50.0, 70.0))
    }
}

/// The larger of two numbers, NaN when either is (so that a failed evaluation fails a check
/// instead of being skipped by `f64::max`).
fn mx(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Relative tolerance of the central differences used below (exact for the polynomial
/// dependences in the rates and accelerations; O(h²) ≈ 1e-10 in the angles).
const FD: f64 = 1e-6;

/// The n° 36 example: a rider of 60 kg with its centre of gravity at h = 2.5 R on a hoop wheel
/// of 5 kg and R = 0.5 m, C0 = 0.77 kg m², A = B = 100 kg m² (as the report's n° 36 entries).
fn example(radius: f64, wheel_mass: f64, height: f64, c0: f64, l: f64) -> Option<Unicycle> {
    example_spin(radius, wheel_mass, height, c0, l, HOOP_SPIN)
}

/// The hoop wheel's moment about its axle, B1 = 2 mu1 R^2, in the unit mu1 R^2.
const HOOP_SPIN: f64 = 2.0;

/// The wheel's moment about its axle B1 = mu1 R^2 only: its spin carries no moment of
/// momentum beyond its rolling translation's (the perturbation of the claims that the wheel's
/// spin stabilises).
const FLAT_SPIN: f64 = 1.0;

/// [`example`] with the wheel's moment about its axle `spin` mu1 R^2 ([`HOOP_SPIN`] for the
/// hoop wheel, whose other moments it keeps).
fn example_spin(
    radius: f64,
    wheel_mass: f64,
    height: f64,
    c0: f64,
    l: f64,
    spin: f64,
) -> Option<Unicycle> {
    let rider = Rider { mass: 60.0, height, a: 100.0, b: 100.0, c: c0, l };
    let m = wheel_mass * radius * radius;
    let wheel = Wheel { mass: wheel_mass, a1: 1.5 * m, b1: spin * m, c1: 0.5 * m };
    Unicycle::new(radius, 9.81, rider, wheel).ok()
}

/// The full unicycle at a seeded point `base` (its R, g, rider mu, z, A, B, C and a hoop wheel
/// of mass mu1) with the rider's product of inertia `l`; `None` if the point is not valid.
fn unicycle_at(base: &Point, l: f64) -> Option<Unicycle> {
    let rider =
        Rider { mass: base["mu"], height: base["z"], a: base["A"], b: base["B"], c: base["C"], l };
    Unicycle::new(base["R"], base["g"], rider, Wheel::hoop(base["mu1"], base["R"])).ok()
}

/// The straight-running threshold of the full model in the unit sqrt(g/R) (`NaN` if none).
fn threshold_units(u: &Option<Unicycle>) -> f64 {
    u.as_ref()
        .and_then(|u| u.straight_running_threshold().map(|s| s / u.rate_unit()))
        .unwrap_or(f64::NAN)
}

/// The same in m/s (the rolling speed R s).
fn threshold_speed(u: &Option<Unicycle>) -> f64 {
    u.as_ref()
        .and_then(|u| u.straight_running_threshold().map(|s| s * u.radius()))
        .unwrap_or(f64::NAN)
}

/// The hoop wheel of mass `mass` at a point: mu1, A1, B1, C1 of n° 4.
fn hoop_wheel(p: &Point, mass: f64) -> Point {
    let m = mass * p["R"] * p["R"];
    with(p, &[("mu1", mass), ("A1", 1.5 * m), ("B1", 2.0 * m), ("C1", 0.5 * m)])
}

/// `p` with no rider.
fn no_rider(p: &Point) -> Point {
    with(p, &[("mu", 0.0), ("A", 0.0), ("B", 0.0), ("C", 0.0), ("L", 0.0), ("z", 1.0)])
}

/// The smallest s > 0 with `stability` > 0 at θ = 0, n = 0, in the unit sqrt(g/R).
fn stability_threshold(p: &Point, output: &str) -> f64 {
    let unit = (p["g"] / p["R"]).sqrt();
    let f = |s: f64| out(&with(p, &[("theta", 0.0), ("n", 0.0), ("s", s * unit)]), output);
    if f(1e3) <= 0.0 || f(0.0) >= 0.0 {
        return f64::NAN;
    }
    bisect(f, 0.0, 1e3)
}

/// The two real roots n1 <= n2 of (E) at (θ, s), from the evaluator `e` (a quadratic in n).
fn roots(e: impl Fn(f64) -> f64) -> Option<[f64; 2]> {
    let (c, plus, minus) = (e(0.0), e(1.0), e(-1.0));
    let a = (plus + minus - 2.0 * c) / 2.0;
    let b = (plus - minus) / 2.0;
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (x, y) = (q / a, c / q);
    Some([x.min(y), x.max(y)])
}

/// The roots of the normalised (E) of n° 32 at (θ in degrees, s).
fn roots_n32(theta: f64, s: f64) -> Option<[f64; 2]> {
    roots(|n| out(&n32(theta, s, n), "equilibrium_n32"))
}

fn grid(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> + Clone {
    (0..n).map(move |k| lo + (hi - lo) * k as f64 / (n - 1) as f64)
}

/// Central difference of `f` in `var` at `p`.
fn diff(p: &Point, var: &'static str, h: f64, f: impl Fn(&Point) -> f64) -> f64 {
    super::diff(p, var, h, f)
}

// n° 20 ------------------------------------------------------------------------------------

fn unmounted_is_hoop() -> Claim {
    let (mut worst, mut cases) = (0.0f64, 0usize);
    let mut worst_stab = 0.0f64;
    for base in points(false).iter().take(16) {
        let p = hoop_wheel(&no_rider(base), base["mu1"]);
        let v = eval(&p);
        let Ok(hoop) = Hoop::new(p["R"], p["mu1"], p["g"]) else { continue };
        let [_, dp, dn, ds] = hoop.rhs_pns([p["theta"], p["p"], p["n"], p["s"]]);
        let scale = p["g"] / p["R"];
        for (a, b) in [(v["pns_dp"], dp), (v["pns_dn"], dn), (v["pns_ds"], ds)] {
            worst = mx(worst, (a - b).abs() / scale);
        }
        let (th, s, n) = (p["theta"], p["s"], p["n"]);
        worst_stab = mx(worst_stab, rel_diff(v["stability"], hoop.stability(th, s, n)));
        cases += 1;
    }
    let holds = cases == 16 && worst <= FD && worst_stab <= FD;
    Claim::new(
        "unicycle-unmounted-is-hoop",
        "20",
        "The unmounted unicycle is a hoop and its theory the same (« le monocycle non monté est assimilable à un cerceau et sa théorie est la même »).",
        "The generated full model (n° 22–24) with no rider (mu = A = B = C = L = 0) and the hoop wheel of n° 4 (A1, B1, C1 = 3/2, 2, 1/2 mu1 R^2), at 16 seeded states: its p', n', s' against the hoop's generated right-hand side (n° 7), and its stability first member (n° 76, L = 0) against the hoop's (n° 9). Holds by construction because the derivation builds the unicycle's wheel terms with the hoop's code and both stabilities go through one routine: it shows that no rider term survives at mu = 0, not the hoop's theory a second time.",
        &[("states", cases as f64), ("max_diff_accelerations_in_g_over_R", worst), ("max_rel_diff_stability", worst_stab)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Equal to rounding: the unicycle model contains the hoop. The pedal cranks that change the moments of n° 4 are not modelled (they would change A1, B1, C1 only).",
    )
}

// n° 22 ------------------------------------------------------------------------------------

/// The height above the ground of the point `O + a i + b j + c k` of the unicycle leaning by
/// `theta` about its heading `psi`: i the wheel's forward direction, j its axle, k the unit
/// vector from the contact point O through the wheel's centre (the rider's axis). The frame is
/// built by rotations (heading about the vertical, then the lean about i), not from the
/// printed heights.
fn height(psi: f64, theta: f64, offset: [f64; 3]) -> f64 {
    use nalgebra::{Rotation3, Vector3};
    let frame = Rotation3::from_axis_angle(&Vector3::z_axis(), psi)
        * Rotation3::from_axis_angle(&Vector3::x_axis(), theta);
    (frame * Vector3::new(offset[0], offset[1], offset[2])).z
}

/// The potential energy g (mu h_G + mu1 h_W) from the heights of the rider's centre
/// G = O + z k and of the wheel's centre O + R k, at the lean `theta` and heading `psi`.
fn potential_from_heights(p: &Point, psi: f64, theta: f64) -> f64 {
    let h_g = height(psi, theta, [0.0, 0.0, p["z"]]);
    let h_w = height(psi, theta, [0.0, 0.0, p["R"]]);
    p["g"] * (p["mu"] * h_g + p["mu1"] * h_w)
}

/// The check of n° 22 with the generated program evaluated at the rider's height `z_scale` z
/// (1 for the check itself; the falsification moves the generated side's G along k).
fn weight_work_check(z_scale: f64) -> Claim {
    let (mut worst_v, mut worst_w) = (0.0f64, 0.0f64);
    let mut rng = crate::sample::Rng(super::SEED ^ 22);
    for base in points(false).iter().take(16) {
        let rest = with(base, &[("p", 0.0), ("n", 0.0), ("s", 0.0), ("z", z_scale * base["z"])]);
        let psi = rng.uniform(-PI, PI);
        let th = base["theta"];
        // The generated energy at zero rates against the heights' potential.
        worst_v =
            mx(worst_v, rel_diff(out(&rest, "energy"), potential_from_heights(base, psi, th)));
        // The work of gravity for d(theta), from the heights, against the printed work.
        let h = 1e-5;
        let work = -(potential_from_heights(base, psi, th + h)
            - potential_from_heights(base, psi, th - h))
            / (2.0 * h);
        let printed = (base["mu"] * base["z"] + base["mu1"] * base["R"]) * base["g"] * th.sin();
        worst_w = mx(worst_w, rel_diff(work, printed));
        // Turning (psi) and rolling do not move the heights.
        let turned = potential_from_heights(base, psi + 0.7, th);
        worst_w = mx(worst_w, rel_diff(turned, potential_from_heights(base, psi, th)));
    }
    let holds = worst_v <= 1e-12 && worst_w <= FD;
    Claim::new(
        "unicycle-weight-work",
        "22",
        "The virtual work of gravity is (mu z + mu1 R) g sin(theta) dp for the fall, nothing for the turning and rolling displacements.",
        "An independent route: the heights of the rider's centre G = O + z k and of the wheel's centre O + R k, with k carried by rotation matrices (heading psi about the vertical, then the lean theta), give the potential g (mu h_G + mu1 h_W) at 16 seeded points and seeded headings; it is compared with the generated energy at zero rates (within 1e-12 relative), and its central difference in theta (h = 1e-5, within 1e-6) with the printed work; turning by 0.7 rad leaves it unchanged. The derivation (codegen, unicycle::weight_potential) derives the potential from the same heights with k written on the fixed trihedron and the work as minus its theta-derivative, no longer typing the printed formula; the mechanics engine's unicycle (frames and bodies, codegen/tests/derive/engine_unicycle.rs) derives it a third way and agrees at 256 bits.",
        &[("points", 16.0), ("max_rel_diff_potential", worst_v), ("max_rel_diff_work", worst_w)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The potential energy of the generated model equals g (mu h_G + mu1 h_W) with h_G = z cos(theta), h_W = R cos(theta) from the geometry; it does not depend on the turning and rolling angles, so gravity works only in the fall.",
    )
}

fn weight_work() -> Claim {
    weight_work_check(1.0).falsified_by(
        "the generated energy evaluated with the rider's centre at O + 1.001 z k (z scaled by 1 + 1e-3) while the heights keep G = O + z k",
        weight_work_check(1.0 + 1e-3),
    )
}

// n° 24 ------------------------------------------------------------------------------------

/// Second moments (A, B, C about I, j, k at the contact point) of a uniform vertical cylinder
/// of mass `mu`, radius `r`, length `len`, centre at the height `h` on Ok, by the midpoint
/// rule over its volume (the sums of n° 21).
fn cylinder(mu: f64, r: f64, len: f64, h: f64) -> (f64, f64, f64) {
    let (nr, nt, nz) = (30, 32, 40);
    let (mut sxx, mut syy, mut szz, mut mass) = (0.0, 0.0, 0.0, 0.0);
    for i in 0..nr {
        let rho = r * (i as f64 + 0.5) / nr as f64;
        for j in 0..nt {
            let t = 2.0 * PI * (j as f64 + 0.5) / nt as f64;
            for k in 0..nz {
                let zeta = h - len / 2.0 + len * (k as f64 + 0.5) / nz as f64;
                let w = rho; // the area element rho d(rho) d(t)
                let (xi, eta) = (rho * t.cos(), rho * t.sin());
                sxx += w * xi * xi;
                syy += w * eta * eta;
                szz += w * zeta * zeta;
                mass += w;
            }
        }
    }
    let k = mu / mass;
    let (sxx, syy, szz) = (k * sxx, k * syy, k * szz);
    (syy + szz, szz + sxx, sxx + syy)
}

fn wheel_small() -> Claim {
    wheel_small_for(5.0)
}

/// [`wheel_small`] with a hoop wheel of mass `mu1` (kg; the memoir's 5).
fn wheel_small_for(mu1: f64) -> Claim {
    let (mu, r) = (60.0, 0.5);
    let rc = 1.0 / (2.0 * PI);
    let h = H_OVER_R * r;
    let a1 = 1.5 * mu1 * r * r;
    let mut worst = 0.0f64;
    let mut spread = (f64::INFINITY, 0.0f64);
    for len in grid(1.0, 1.8, 9) {
        let (a, _, _) = cylinder(mu, rc, len, h);
        worst = mx(worst, a1 / a);
        spread = (spread.0.min(a), spread.1.max(a));
    }
    let holds = worst < 0.05 && spread.1 - spread.0 > a1;
    Claim::new(
        "unicycle-wheel-small-against-rider",
        "24",
        "The wheel's mass is small before the rider's and A1 small before A; A varies from one rider to another by more than A1, so A + A1 may be written A.",
        "The memoir's own example (n° 36: rider 60 kg as a uniform cylinder of circumference 1 m, hoop wheel 5 kg of R = 0.5 m, h = 2.5 R of n° 32), the cylinder's A about I at the contact point by the midpoint rule over its volume for lengths 1.0–1.8 m, against A1 = 3/2 mu1 R^2.",
        &[("A1", a1), ("max_A1_over_A", worst), ("A_min", spread.0), ("A_max", spread.1)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "A1/A is below 2 % and A changes by more than A1 between a rider of 1.0 m and one of 1.8 m. The size of the letters is right; what the merge of letters costs is elsewhere (n° 36: the hoop limit; n° 78: the sum of the roots), where the wheel's B1 and mu1 R enter otherwise than A1.",
    )
}

// n° 25 ------------------------------------------------------------------------------------

fn steady_needs_no_motor() -> Claim {
    let (mut worst, mut drift) = (0.0f64, 0.0f64);
    for base in points(false).iter().take(16) {
        let p = with(base, &[("p", 0.0), ("dp", 0.0), ("dn", 0.0), ("ds", 0.0)]);
        let v = eval(&p);
        let scale = (p["mu"] * p["R"] * p["R"] + p["B1"]) * p["g"] / p["R"];
        worst = mx(worst, (v["rider_s"] + v["wheel_s"]).abs() / scale);
    }
    for base in points(false).iter().take(4) {
        // L = 0: with L > 0 the upright running is unstable (n° 78) and the run would fall.
        let Some(u) = unicycle_at(base, 0.0) else { continue };
        let Some(threshold) = u.straight_running_threshold() else { continue };
        let x0 = [0.02, 0.0, 0.0, 3.0 * threshold];
        let x1 = u.simulate(x0, 1e-3, 2000);
        drift = mx(drift, (u.energy(x1) - u.energy(x0)).abs() / u.energy(x0).abs());
    }
    let holds = worst <= 1e-12 && drift <= 1e-8;
    Claim::new(
        "unicycle-steady-needs-no-motor",
        "25",
        "In a steady state (s' = n' = p = 0) the rolling equation (s) gives a motor moment 0, as the theorem of vis viva says.",
        "The generated (s) first member (rider + wheel) at p = p' = n' = s' = 0 at 16 seeded states (relative to (mu R^2 + B1) g/R); and the energy drift of 2 s of RK4 (dt = 1 ms) of the generated full model with no motor moment, for 4 seeded unicycles with hoop wheels and L = 0, from a lean of 0.02 rad at three times the straight-running threshold. Holds by construction because every term of the generated rider's and wheel's shares of (s) carries one of p, p', n', s' and the model has no dissipation, so its energy is conserved whatever its constants: no change of a coefficient or parameter breaks either part (the rider's mass scaled by 1 + 1e-2 in its share of (s), tried, leaves it at 0); only a passive resistance, which the model leaves out, would.",
        &[("max_rel_s_first_member", worst), ("max_rel_energy_drift", drift)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The (s) first member vanishes identically in a steady state, so the motor moment there only balances the passive resistances the model leaves out; the free motion conserves the energy.",
    )
}

/// The height of the total centre of gravity on a slope of angle `i` after the wheel has
/// rolled by `ds` up it, the rider translating with the wheel's centre (n° 22): wheel centre
/// R nu, rider's centre of gravity z nu at the start (nu the slope's normal); or with
/// `horizontal` the cycle advanced horizontally by R ds and raised onto the slope (the rise
/// R ds tan(i) of n° 25's reading) instead of rolling on it.
fn slope_height_with(i: f64, r: f64, z: f64, mu: f64, mu1: f64, ds: f64, horizontal: bool) -> f64 {
    let nu = (-i.sin(), i.cos());
    // The wheel turns by -ds about the contact point: its centre R nu goes to rot(-ds) R nu.
    let (c, s) = (ds.cos(), -ds.sin());
    let (centre, shift) = if horizontal {
        let shift = (r * ds, r * ds * i.tan());
        ((r * nu.0 + shift.0, r * nu.1 + shift.1), shift)
    } else {
        let centre = (r * (c * nu.0 - s * nu.1), r * (s * nu.0 + c * nu.1));
        (centre, (centre.0 - r * nu.0, centre.1 - r * nu.1))
    };
    let rider = (z * nu.0 + shift.0, z * nu.1 + shift.1);
    (mu * rider.1 + mu1 * centre.1) / (mu + mu1)
}

fn slope_moment() -> (Claim, Claim) {
    slope_moment_for(9.81, false)
}

/// [`slope_moment`] with gravity `g` (m/s^2; 9.81), the cycle advanced horizontally when
/// `horizontal` ([`slope_height_with`]).
fn slope_moment_for(g: f64, horizontal: bool) -> (Claim, Claim) {
    let (r, z, mu, mu1) = (0.5, 1.25, 60.0, 5.0);
    let (mut sin_rel, mut tan_rel, mut tan_rel_10) = (0.0f64, 0.0f64, 0.0);
    let mut sign_ok = true;
    let mut count = 0;
    for deg in
        [-20.0, -10.0, -5.0, -2.0, -1.0, 1.0, 2.0, 5.0, 5.710_593_137_499_643, 10.0, 15.0, 20.0]
    {
        let i = f64::to_radians(deg);
        let h = 1e-6;
        let up = slope_height_with(i, r, z, mu, mu1, h, horizontal);
        let down = slope_height_with(i, r, z, mu, mu1, -h, horizontal);
        // The moment the pedals must give: minus the generalised force of gravity for ds.
        let moment = (mu + mu1) * g * (up - down) / (2.0 * h);
        let total = (mu + mu1) * g * r;
        sin_rel = mx(sin_rel, rel_diff(moment, total * i.sin()));
        let t = rel_diff(moment, total * i.tan());
        tan_rel = mx(tan_rel, t);
        if deg == 10.0 {
            tan_rel_10 = t;
        }
        sign_ok &= moment.signum() == i.signum();
        count += 1;
    }
    let tan_holds = tan_rel <= FD;
    let a = Claim::new(
        "unicycle-slope-moment",
        "25",
        "On a slope of angle i the cycle, advancing by R ds, rises by R ds tan(i), so the motor moment is M = mu g R tan(i).",
        "The model has no slope; the generalised force of gravity for the rolling displacement ds on an incline is computed from positions: the wheel turning about its contact point, the rider translating with the wheel's centre (n° 22), the height of the total centre of gravity differenced at ds = ±1e-6 (R = 0.5 m, z = 1.25 m, 60 + 5 kg), for 12 slopes from -20° to 20°, against (mu + mu1) g R sin(i) and against the printed tan(i).",
        &[("slopes", count as f64), ("max_rel_diff_sin", sin_rel), ("max_rel_diff_tan", tan_rel), ("rel_diff_tan_at_10deg", tan_rel_10)],
        policy::claim(tan_holds, Verdict::MemoirError),
        "The moment is mu g R sin(i) (mu the total mass), exactly, whatever the rider's height: rolling by ds the wheel advances R ds along the slope, which rises R ds sin(i); tan(i) would be the rise for a horizontal advance R ds. The memoir's own n° 124 prints + mu g R cos(delta) sin(i) for the same work. The two agree to first order (0.5 % off on a 10 % grade, 1.5 % at 10°).",
    );
    let b = Claim::new(
        "unicycle-slope-sign",
        "25",
        "M has the sign of i: the rider pushes going up a slope and holds back going down.",
        "The sign of the same computed moment for the 12 slopes from -20° to 20°.",
        &[("slopes", count as f64), ("all_signs_of_i", if sign_ok { 1.0 } else { 0.0 })],
        policy::claim(sign_ok, Verdict::DerivationDiffers),
        "Holds with the derived sin(i) as with the printed tan(i).",
    );
    (a, b)
}

// n° 26, 26 bis ------------------------------------------------------------------------------

fn pedal_paradox() -> Claim {
    pedal_paradox_check(1.0)
}

/// The check of [`pedal_paradox`] with the cranks `crank_scale` times as long (1 as built: the
/// pedals within the rim; 2, the falsification: cranks up to 1.9 R, the lowest pedals below
/// the ground line).
fn pedal_paradox_check(crank_scale: f64) -> Claim {
    let mut largest = f64::NEG_INFINITY;
    let mut cases = 0;
    for ratio in grid(0.05 * crank_scale, 0.95 * crank_scale, 19) {
        for alpha in grid(0.0, 2.0 * PI, 24) {
            // Wheel of radius 1 rolling forward by sigma (clockwise), crank ratio at angle alpha
            // from the bottom: pedal x = sigma - ratio sin(alpha + sigma).
            let x = |sigma: f64| sigma - ratio * (alpha + sigma).sin();
            let h = 1e-6;
            // Work of a backward horizontal force of unit size for d(sigma) = 1.
            let work = -(x(h) - x(-h)) / (2.0 * h);
            largest = mx(largest, work);
            cases += 1;
        }
    }
    let holds = largest < 0.0;
    Claim::new(
        "unicycle-pedal-paradox",
        "26",
        "Pulling the lowest pedal backwards makes the cycle roll backwards, not forwards: the work of -F is -F OP ds, negative for a forward roll.",
        "The exact kinematics of a wheel rolling without slipping with a crank of length m: the pedal's horizontal position differenced in the rolling angle (h = 1e-6), times a backward unit force, for m/R from 0.05 to 0.95 and 24 crank angles (the memoir's lowest pedal and all others).",
        &[("cases", cases as f64), ("largest_work_per_F_R", largest)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The work is -F (R - m cos(alpha)) ds: negative for every crank position, because the pedal is always above the ground, whose point O is the instantaneous centre. For the lowest pedal it is -F OP ds as printed.",
    )
}

/// The bicycle of n° 26 bis: work rate of a unit string tension for a forward pedal rotation,
/// the string from the lowest pedal under the rear axle S (a point pulley on the frame) and
/// pulled at the zenith distance `zeta` (positive backwards).
struct StringBike {
    /// Rear axle height, crank axle ahead of it and its height, crank, advance per radian.
    axle: f64,
    ahead: f64,
    bracket: f64,
    crank: f64,
    advance: f64,
}

impl StringBike {
    fn pedal(&self, d: f64) -> (f64, f64) {
        (self.ahead + self.advance * d - self.crank * d.sin(), self.bracket - self.crank * d.cos())
    }

    /// The work rate at the zenith distance `zeta` with the pulley S carried by the frame
    /// (`pulley_moves`, as built) or held fixed on the ground (the falsification).
    fn work_with(&self, zeta: f64, pulley_moves: bool) -> f64 {
        let u = (-zeta.sin(), zeta.cos());
        let f = |d: f64| {
            let s = (if pulley_moves { self.advance * d } else { 0.0 }, self.axle);
            let p = self.pedal(d);
            u.0 * s.0 + u.1 * s.1 - ((p.0 - s.0).powi(2) + (p.1 - s.1).powi(2)).sqrt()
        };
        let h = 1e-6;
        (f(h) - f(-h)) / (2.0 * h)
    }

    /// Virtual work, per radian of forward pedal rotation, of the rider's own backward unit
    /// force on the lowest pedal and of its equal and opposite reaction applied at the point
    /// `reaction` of the frame (its position at d = 0; it moves with the frame when
    /// `moves_with_frame`, otherwise it is held fixed: the falsification). Each point's
    /// displacement comes from its own kinematics, differenced at ±1e-6 rad.
    fn interior_work(&self, reaction: (f64, f64), moves_with_frame: bool) -> f64 {
        let h = 1e-6;
        let force = (-1.0, 0.0);
        let frame_point = |d: f64| {
            let shift = if moves_with_frame { self.advance * d } else { 0.0 };
            (reaction.0 + shift, reaction.1)
        };
        let work = |d: f64| {
            let (p, q) = (self.pedal(d), frame_point(d));
            force.0 * p.0 + force.1 * p.1 - (force.0 * q.0 + force.1 * q.1)
        };
        (work(h) - work(-h)) / (2.0 * h)
    }
}

fn bikes() -> Vec<StringBike> {
    let mut out = Vec::new();
    for axle in [0.33, 0.35, 0.36] {
        for ahead in [0.40, 0.45] {
            for bracket in [0.25, 0.28] {
                for crank in [0.15, 0.17] {
                    for gear in [2.0, 2.5, 3.0] {
                        out.push(StringBike { axle, ahead, bracket, crank, advance: axle * gear });
                    }
                }
            }
        }
    }
    out
}

fn string_angle() -> Claim {
    string_angle_check(true)
}

/// The check of [`string_angle`] with the pulley carried by the frame (`pulley_moves`) or
/// held fixed on the ground (the falsification).
fn string_angle_check(pulley_moves: bool) -> Claim {
    let (mut worst, mut order_ok, mut lo, mut hi) = (0.0f64, true, f64::INFINITY, 0.0f64);
    let all = bikes();
    for b in &all {
        let work = |z: f64| b.work_with(z, pulley_moves);
        order_ok &= work(PI / 2.0) < 0.0 && work(0.0) > 0.0 && work(-PI / 4.0) > 0.0;
        let zeta = bisect(work, 0.0, PI / 2.0);
        let p = b.pedal(0.0);
        let (dx, dy) = (p.0, p.1 - b.axle);
        let sin_zp = dx.abs() / (dx * dx + dy * dy).sqrt();
        worst = mx(worst, (zeta.sin() - b.crank / b.advance * sin_zp).abs());
        lo = lo.min(zeta.to_degrees());
        hi = mx(hi, zeta.to_degrees());
    }
    let holds = order_ok && worst <= FD;
    Claim::new(
        "unicycle-string-neutral-angle",
        "26 bis",
        "With a string from the lowest pedal under the rear axle, pulling backwards makes the bicycle recede, pulling forwards or up makes it advance, and between the backward and the vertical pull one inclination leaves it at rest: sin S = (m/M) sin(P, I), a constant of the machine.",
        "Virtual work of the string for a forward pedal rotation (frame advancing M per radian, crank m turning, the string through a point pulley at the axle S), differenced at ±1e-6 rad, for 72 bicycle geometries (axle height 0.33–0.36 m, crank axle 0.40–0.45 m ahead and 0.25–0.28 m high, cranks 0.15–0.17 m, gears 2–3); the neutral zenith distance by bisection against the printed formula.",
        &[("geometries", all.len() as f64), ("max_abs_diff_sin", worst), ("neutral_deg_min", lo), ("neutral_deg_max", hi)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The work is F (m sin(zeta_P) - M sin(S)) per radian: backward pulls recede, vertical and forward pulls advance, and the neutral pull has sin S = (m/M) sin(zeta_P), with zeta_P the zenith distance of the strand PS, which is how (P, I) must be read (a horizontal displacement projects on a strand by the sine of its zenith distance, as on SB in the memoir's (2)); read as the angle of PS with the horizontal I the sine would be a cosine. It depends only on the machine's geometry.",
    )
}

/// The points of the frame where the rider's reaction is applied: the saddle (above the crank
/// axle), the handlebar (ahead and higher) and the crank axle itself, relative to the rear
/// contact point (m).
const REACTION_POINTS: [(f64, f64); 3] = [(0.35, 0.95), (0.95, 1.0), (0.42, 0.27)];

/// The check of n° 26 bis with the reaction carried by the frame (`moves_with_frame`) or held
/// fixed (the falsification: the reaction applied to a point that does not move with the
/// frame, as if the force came from outside).
fn interior_force_check(moves_with_frame: bool) -> Claim {
    let all = bikes();
    let (mut smallest, mut worst) = (f64::INFINITY, 0.0f64);
    for b in &all {
        for q in REACTION_POINTS {
            let w = b.interior_work(q, moves_with_frame);
            smallest = smallest.min(w);
            worst = mx(worst, (w / b.crank - 1.0).abs());
        }
    }
    let holds = smallest > 0.0 && worst <= FD;
    Claim::new(
        "unicycle-interior-force-advances",
        "26 bis",
        "When the force on the pedal is interior (from the rider), the cycle advances: the reaction cancels the work of the translation and only the relative work remains.",
        "The virtual work, for a forward pedal rotation, of a backward unit force on the lowest pedal (its displacement from the crank's kinematics on the advancing frame) and of the equal and opposite force on the frame, applied at the saddle, the handlebar or the crank axle (each point's displacement from the frame's translation), differenced at ±1e-6 rad on the same 72 geometries: positive, and equal to the crank m (the relative work) within 1e-6.",
        &[("geometries", all.len() as f64), ("reaction_points", REACTION_POINTS.len() as f64), ("min_work", smallest), ("max_rel_diff_work_vs_crank", worst)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The work is + F m per radian whatever the gear and wherever the reaction acts on the frame: positive, the cycle advances. Applied to a point that does not move with the frame (an exterior force), the same force gives F (m - M) < 0: the paradox of n° 26.",
    )
}

/// The check of n° 26 for every velocipede: a backward force on the lowest pedal from outside
/// the machine, on the 72 bicycles of n° 26 bis with the advance per radian M scaled by
/// `advance_scale` (1 for the check; the falsification gears the machines down below m).
fn velocipede_paradox_check(advance_scale: f64) -> Claim {
    let all: Vec<StringBike> = bikes()
        .into_iter()
        .map(|b| StringBike { advance: b.crank + advance_scale * (b.advance - b.crank), ..b })
        .collect();
    let mut largest = f64::NEG_INFINITY;
    for b in &all {
        // A point of the ground: the exterior force has no reaction on the frame.
        largest = mx(largest, b.interior_work((0.0, 0.0), false));
    }
    Claim::new(
        "unicycle-velocipede-paradox",
        "26",
        "The same holds for every velocipede (« tout appareil vélocipédique »): pulling the lowest pedal backwards makes it recede, the transmission hiding the reason.",
        "The 72 bicycle geometries of n° 26 bis (gears 2–3, the frame advancing M per radian of the cranks of length m): the virtual work of a backward unit force on the lowest pedal with no reaction on the frame, differenced at ±1e-6 rad; negative for every one because M > m.",
        &[("geometries", all.len() as f64), ("largest_work", largest)],
        policy::claim(largest < 0.0, Verdict::DerivationDiffers),
        "The work is -F (M - m) per radian: the pedal's point advances by M - m > 0 with the frame, as the wheel's pedal of n° 26 advances by R - m; the chain only changes M.",
    )
}

fn velocipede_paradox() -> Claim {
    velocipede_paradox_check(1.0).falsified_by(
        "the machines geared down so that the frame advances less than the crank (M - m scaled by -0.5)",
        velocipede_paradox_check(-0.5),
    )
}

fn interior_force() -> Claim {
    interior_force_check(true).falsified_by(
        "the reaction applied at a point that does not move with the frame (an exterior force)",
        interior_force_check(false),
    )
}

// n° 29–30 ----------------------------------------------------------------------------------

fn steady_n_identity() -> Claim {
    let mut worst = 0.0f64;
    for base in points(false).iter().take(16) {
        let p = with(base, &[("p", 0.0), ("dp", 0.0), ("dn", 0.0), ("ds", 0.0)]);
        let v = eval(&p);
        let scale = (p["A"] + p["B"] + p["C"] + p["B1"]) * p["g"] / p["R"];
        worst = mx(worst, (v["rider_n"] + v["wheel_n"]).abs() / scale);
    }
    Claim::new(
        "unicycle-steady-n-identity",
        "29",
        "In a steady state (s' = n' = p = p' = 0) the turning equation (n) reduces to an identity.",
        "The generated (n) first member (rider + wheel, any L) at p = p' = n' = s' = 0 at 16 seeded states, relative to (A + B + C + B1) g/R. Holds by construction because every term of the generated rider's and wheel's shares of (n) carries one of p, p', n', s' (no moment about the vertical acts on the model): each share vanishes by itself at rest of those rates, so no change of a coefficient or of a parameter in one share breaks the identity (the rider's mass scaled by 1 + 1e-2 in its share, tried, leaves it at 0); only a moment about the vertical that the model does not have (a pivoting friction) would",
        &[("points", 16.0), ("max_rel_n_first_member", worst)],
        policy::claim(worst <= 1e-12, Verdict::DerivationDiffers),
        "Every term of (n) carries p, p', n' or s' (with the wheel's too), so steady states are fixed by (p) alone, which is (E).",
    )
}

fn equilibrium_hoop_form() -> Claim {
    let mut worst = 0.0f64;
    let mut rng = crate::sample::Rng(super::SEED ^ 29);
    for base in points(false).iter().take(16) {
        let e = |th: f64, s: f64, n: f64| {
            out(&with(base, &[("theta", th), ("s", s), ("n", n)]), "equilibrium")
        };
        let th0: f64 = 0.5;
        let c = e(th0, 0.0, 0.0) / th0.sin();
        let a = (e(th0, 0.0, 1.0) - e(th0, 0.0, 0.0)) / (th0.sin() * th0.cos());
        let b = (e(th0, 1.0, 1.0) - e(th0, 0.0, 1.0)) / th0.cos();
        for _ in 0..8 {
            let (th, s, n) =
                (rng.uniform(-1.2, 1.2), rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0));
            let form = a * n * n * th.sin() * th.cos() + b * s * n * th.cos() + c * th.sin();
            worst = mx(worst, rel_diff(e(th, s, n), form));
        }
    }
    Claim::new(
        "unicycle-equilibrium-hoop-form",
        "29",
        "The equilibrium equation (E) has the same form as the hoop's: (B - C) n^2 sin cos + mu R z s n cos + mu g z sin = 0.",
        "The generated (E) of the full model (rider and wheel apart) at 16 seeded unicycles: its three coefficients read at theta = 0.5 and tested at 8 seeded (theta, s, n) each against a n^2 sin cos + b s n cos + c sin. Holds by construction because every term the derivation gives (E) for a rider whose centre lies in the wheel's plane, with (E) free of the product of inertia L, is of one of the three forms: a change of a mass, height, moment or coefficient changes a, b, c but not the form; only a term of another form (a centre off the plane), which the generated program's parameters cannot express, would break it",
        &[("points", 128.0), ("max_rel_diff", worst)],
        policy::claim(worst <= 1e-9, Verdict::DerivationDiffers),
        "The form holds for the full model too, with a = B - C + B1 - C1, b = mu R z + B1, c = (mu z + mu1 R) g: the hoop's three terms.",
    )
}

fn skid_reduces_to_hoop() -> Claim {
    let mut worst = 0.0f64;
    for base in points(false).iter().take(16) {
        let p = with(base, &[("z", base["R"])]);
        let Ok(hoop) = Hoop::new(p["R"], 1.0, p["g"]) else { continue };
        worst = mx(worst, rel_diff(out(&p, "skid"), hoop.skid(p["theta"], p["s"], p["n"])));
    }
    Claim::new(
        "unicycle-skid-reduces-to-hoop",
        "30",
        "With z = R the steady skid tendency (D) is the hoop's expression of n° 10.",
        "The generated steady D of the unicycle at z = R against the hoop's generated D (n° 10) at 16 seeded states.",
        &[("points", 16.0), ("max_rel_diff", worst)],
        policy::numeric(worst, 1e-12, Verdict::DerivationDiffers),
        "D depends only on the motion of the total centre of gravity, at the height R for both.",
    )
}

fn abrupt_turn() -> (Claim, Claim) {
    // At theta = 0 the neglected terms (z p^2 sin, z p' sin) vanish: the memoir's relative
    // increase is first-order exact there.
    let (r, g, zc) = (0.5, 9.81, 0.98);
    let (mut rel_pp, mut ratio_p2, mut first_min, mut second) =
        (0.0f64, f64::NAN, f64::INFINITY, 0.0);
    for d_target in [0.3, 0.4, 0.5] {
        let s = 2.0;
        let n = -d_target * g / (r * s);
        let d = |p: f64, dp: f64| {
            out(
                &BTreeMap::from([
                    ("R", r),
                    ("g", g),
                    ("z", zc),
                    ("theta", 0.0),
                    ("p", p),
                    ("dp", dp),
                    ("n", n),
                    ("s", s),
                ]),
                "skid_full",
            )
        };
        let d0 = d(0.0, 0.0);
        let eps = 1e-4;
        let k_dp = (d(0.0, eps) / d0 - 1.0) / eps;
        let k_p2 = (d(eps, 0.0) / d0 - 1.0) / (eps * eps);
        let memoir_dp = zc / (-(r * n * s));
        rel_pp = mx(rel_pp, rel_diff(k_dp, memoir_dp));
        ratio_p2 = k_p2 / (-zc / g);
        first_min = first_min.min(k_dp);
        second = k_p2;
    }
    let a = Claim::new(
        "unicycle-abrupt-turn-increase",
        "31",
        "The skid tendency is increased by -z p' cos of the numerator and +z p^2 cos of the denominator of D; the relative increase is z p' cos / (-(Rns + z n^2 sin)) - z p^2 cos / g.",
        "First-order relative change of the generated complete D of n° 30 in p' and in p^2 (differences at 1e-4) at theta = 0, where the terms the memoir neglects vanish, z cos = 0.98 m, R = 0.5 m, s = 2/s and n giving D = 0.3, 0.4, 0.5.",
        &[("max_rel_diff_p_prime_term", rel_pp), ("derived_over_printed_p2_term", ratio_p2)],
        policy::claim(rel_pp <= FD && (ratio_p2 - 1.0).abs() <= FD, Verdict::MemoirError),
        "The p' term agrees; the p^2 term is + z p^2 cos / g, the opposite of the printed one (ratio -1): the printed minus follows the misprinted denominator g + z p^2 cos of n° 30 (derived g - z p^2 cos), while the memoir's words (D « augmentée » by that term) agree with the derivation.",
    );
    let holds = first_min >= 1.99 * second;
    let b = Claim::new(
        "unicycle-abrupt-turn-pprime-larger",
        "31",
        "With z cos = 0.98 m the p^2 term reaches 0.1 for p = 1, and the p' term is notably larger for p' = 1, its denominator being a fraction of g below the friction coefficient (0.3 to 0.5).",
        "The two first-order coefficients of the previous claim for D = 0.3, 0.4, 0.5 (the denominator -(Rns + z n^2 sin) = D g at theta = 0).",
        &[("p_prime_term_min", first_min), ("p2_term", second)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The p' term is 0.98/(D g) = 0.20–0.33 per unit p', two to three times the p^2 term 0.0999 per unit p^2 (exactly twice at D = 0.5).",
    );
    (a, b)
}

// n° 32 ------------------------------------------------------------------------------------

fn turns_toward_lean() -> Claim {
    let (mut cases, mut opposite, mut centre_ok) = (0usize, true, true);
    let mut rng = crate::sample::Rng(super::SEED ^ 32);
    for base in points(false).iter() {
        for _ in 0..8 {
            let th = rng.uniform(0.02, 1.4) * if rng.next_unit() < 0.5 { -1.0 } else { 1.0 };
            let s = rng.uniform(0.2, 8.0) * (base["g"] / base["R"]).sqrt();
            let e = |n: f64| out(&with(base, &[("theta", th), ("s", s), ("n", n)]), "equilibrium");
            let Some(ns) = roots(e) else { continue };
            for n in ns {
                cases += 1;
                opposite &= n * th < 0.0;
                // Centre of the contact's path R s / n along J; wheel centre -R sin(theta) along J.
                centre_ok &= (base["R"] * s / n) * (-base["R"] * th.sin()) > 0.0;
            }
        }
    }
    let holds = cases > 100 && opposite && centre_ok;
    Claim::new(
        "unicycle-turns-toward-lean",
        "32",
        "Given s and theta, (E) gives two values of n of sign opposite to theta: « le cycle converge du côté où il penche ».",
        "The two real roots in n of the generated (E) of the full model (rider and wheel apart, B > C) at 48 seeded unicycles × 8 seeded (theta, s), 0.02 <= |theta| <= 1.4, s > 0; for each root the sign of n theta and the side of the centre of the contact's path (R s/n along J, with I' = J n, n° 23) against the side of the wheel's centre (k = -J sin(theta) + K cos(theta), n° 1).",
        &[("roots", cases as f64), ("all_opposite", if opposite { 1.0 } else { 0.0 }), ("all_centres_on_lean_side", if centre_ok { 1.0 } else { 0.0 })],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Both roots have the sign of -theta whenever they are real (their product is (mu z + mu1 R) g / ((B - C + B1 - C1) cos) > 0 and their sum has the sign of -theta for B - C + B1 - C1 > 0, a rider taller than wide), and the path's centre lies on the side of the lean.",
    )
}

fn skid_is_tan_on_e() -> Claim {
    let mut worst = 0.0f64;
    let mut count = 0;
    for th in grid(5.0, 60.0, 12) {
        for n in [-0.1, -0.3, -0.5, -1.0, -1.5, -2.0, -3.0] {
            let s = s_on_e(th, n);
            worst = mx(worst, rel_diff(out(&n32(th, s, n), "skid_n32"), th.to_radians().tan()));
            count += 1;
        }
    }
    Claim::new(
        "unicycle-skid-is-tan-on-e",
        "32",
        "With B - C = mu z^2, on (E) the skid tendency reduces to D = + tan(theta), so a friction coefficient tan 23.6° = 0.437 stops the diagram at the asymptote of (N).",
        "The generated normalised (D) of n° 32 at steady states s on the generated (E), 12 leans 5°–60° × 7 values of n.",
        &[("points", count as f64), ("max_rel_diff", worst)],
        policy::formula(worst, Verdict::DerivationDiffers),
        "D = tan(theta) exactly on (E) in the example (h/R = 2.5, B - C = mu h^2): the resultant of weight and inertia is inclined at theta, along the wheel's steepest line Ok, so skidding starts at the lean whose tangent is the friction coefficient; not so for a general B - C.",
    )
}

fn separation_curve() -> Claim {
    let mut worst = 0.0f64;
    for th in grid(0.5, 23.0, 46) {
        let t = th.to_radians();
        let printed = (t.tan() / (1.0 - H_OVER_R * t.sin())).sqrt();
        worst = mx(worst, rel_diff(read::curve_n_s(th).unwrap_or(f64::NAN), printed));
    }
    Claim::new(
        "unicycle-separation-curve",
        "32",
        "The separation of walking and pivoting is obtained by putting n = -s in (E): (N) s^2 = tan(theta) / (1 - 2.5 sin(theta)).",
        "The positive root in s of the generated (E) at n = -s, 46 leans 0.5°–23°, against the printed (N).",
        &[("points", 46.0), ("max_rel_diff", worst)],
        policy::formula(worst, Verdict::DerivationDiffers),
        "",
    )
}

fn n_touches_e() -> Claim {
    let theta_i = bisect(
        |th| {
            let (n0, s0) = minimum_on_e(th);
            s0 + n0
        },
        1.0,
        20.0,
    );
    let (mut min_gap_away, mut gap_at_i) = (f64::INFINITY, f64::NAN);
    for th in grid(0.5, 23.0, 91) {
        let gap = curve_n_s(th).unwrap_or(f64::NAN) - minimum_on_e(th).1;
        if (th - theta_i).abs() > 1.0 {
            min_gap_away = min_gap_away.min(gap);
        }
    }
    if let Some(sn) = curve_n_s(theta_i) {
        gap_at_i = (sn - minimum_on_e(theta_i).1).abs();
    }
    let holds = min_gap_away > 0.0 && gap_at_i <= 1e-6;
    Claim::new(
        "unicycle-n-touches-e",
        "32",
        "(N) touches the curve (ℰ) of the smallest s at the point I where s0 = -n0 (theta = 11.5°, s0 = 0.639).",
        "s on the generated (N) minus the smallest s on the generated (E) (golden section) at 91 leans 0.5°–23°, and at the derived point I (bisection of s0 + n0). Holds by construction because (N) is (E) taken at n = -s and (ℰ) is the smallest s over n on the same (E): every point of (N) is a point of (E), so (N) cannot pass below (ℰ) and meets it exactly where the minimising n0 equals -s0, whatever (E) is (a perturbed (E) moves both curves together); where I lies, theta = 11.5° and s0 = 0.639, is judged by the value entries of n° 32 (point I)",
        &[("theta_I_deg", theta_i), ("gap_at_I", gap_at_i), ("min_gap_1deg_away", min_gap_away)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "(N) lies above (ℰ) everywhere else (as it must: (ℰ) is the smallest s over n) and meets it at I only, a contact.",
    )
}

/// Walking |n| < s (n° 17).
fn walks(n: f64, s: f64) -> bool {
    n.abs() < s
}

fn regions() -> Claim {
    let theta_i = bisect(
        |th| {
            let (n0, s0) = minimum_on_e(th);
            s0 + n0
        },
        1.0,
        20.0,
    );
    let (mut tested, mut wrong) = (0usize, 0usize);
    let mut none_below = true;
    for th in grid(0.5, 23.0, 46) {
        let (_, s0) = minimum_on_e(th);
        let sn = curve_n_s(th).unwrap_or(f64::INFINITY);
        for s in grid(0.02, 3.0, 150) {
            let near = |c: f64| (s - c).abs() < 1e-3 * c.max(1e-3);
            if near(s0) || near(sn) || (th - theta_i).abs() < 0.1 {
                continue;
            }
            let r = roots_n32(th, s);
            if s < s0 {
                none_below &= r.is_none();
                continue;
            }
            let Some([n1, n2]) = r else {
                wrong += 1;
                continue;
            };
            tested += 1;
            let expect = if s > sn {
                (false, true) // between Oz and (N): n1 pivots, n2 walks
            } else if th < theta_i {
                (false, false) // the lune O-I: both pivot
            } else {
                (true, true) // beyond I: both walk
            };
            if (walks(n1, s), walks(n2, s)) != expect {
                wrong += 1;
            }
        }
    }
    let holds = wrong == 0 && none_below && tested > 1000;
    Claim::new(
        "unicycle-walking-pivoting-regions",
        "32",
        "Between the axis Oz and (N) the root n2 walks and n1 pivots; between (N) and (ℰ) both pivot in the lune from O to I and both walk beyond I; between (ℰ) and Ox there is no steady state.",
        "The roots n1 <= n2 of the generated normalised (E) on a polar grid, 46 leans 0.5°–23° × 150 rates 0.02–3 (points within 1e-3 of a curve or 0.1° of I skipped), classified as walking when |n| < s (n° 17: path radius above the wheel's).",
        &[("points_with_roots", tested as f64), ("misclassified", wrong as f64), ("none_below_E", if none_below { 1.0 } else { 0.0 })],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Every point falls in the region the memoir names.",
    )
}

/// The walking root n2's stability limit on (S) of n° 40 at θ < 16.3°: s_a of n° 41.
fn stability_circle() -> Claim {
    let (root1, _) = read::first_member_roots();
    let mut max_dev = 0.0f64;
    for th in grid(0.5, root1 - 0.05, 40) {
        if let Some([(na, sa), (nb, sb)]) = read::stability_limit(th) {
            // The branch through (n = 0, s = 1): the root of smaller |n|.
            let s_lim = if na.abs() < nb.abs() { sa } else { sb };
            max_dev = mx(max_dev, (s_lim - 1.0).abs());
        }
    }
    // Stable walking states below the circle, beyond the first root (all states stable there).
    let mut below_stable_to = root1;
    for th in grid(root1, 23.5, 200) {
        if read::minimum_on_e(th).1 < 1.0 {
            below_stable_to = th;
        }
    }
    let holds = max_dev <= 0.05;
    Claim::new(
        "unicycle-stability-circle",
        "32",
        "The stability limit curve may be practically taken as the circle s = 1.",
        "The branch of the limit of (S) of n° 40 through (theta = 0, s = 1) (the walking root n2's limit, from the generated trinomial of n° 41) at 40 leans below the first root of n° 41, its largest distance to s = 1; and the leans beyond that root where steady states with s < 1 exist (all stable there).",
        &[("max_abs_s_limit_minus_1", max_dev), ("first_root_deg", root1), ("stable_below_circle_up_to_deg", below_stable_to)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Within 3.2 %: the limit leaves s = 1 at theta = 0 (rising slightly, by 0.75 theta^2), then falls to 0.97 at 16.3°; beyond, every steady state is stable, so between 16.3° and the lean where (ℰ) crosses s = 1 the circle declares unstable some stable states (on the safe side).",
    )
}

/// The rider's shape in the normalised model of n° 32–41 (unit $\mu R^2$): n° 39's
/// $E = B - C - \mu h^2$ and the rider's moment $C$ about his vertical axis Ok. The wheel
/// is n° 40's, $\mu_1 R^2 = C$ and $B_1 = 2\mu_1 R^2$; it enters (S) only, as in n° 40.
#[derive(Clone, Copy)]
struct Shape {
    /// $E = B - C - \mu h^2$ (n° 39).
    e: f64,
    /// The rider's moment $C$ about Ok (with $E = 0$ it drops out of (E), (D) and (S)).
    c: f64,
}

/// n° 32's and n° 40's rider: $B - C = \mu h^2$ ($E = 0$; its $C$, here $\mu R^2$, drops out).
const SHAPE_32: Shape = Shape { e: 0.0, c: 1.0 };

/// A rider with $B - C = \mu h^2 / 2$ ($E = -\mu h^2/2$) and $C = 0.6\,\mu h^2$: his moment
/// about the vertical exceeds the one about the lateral axis through his centre by
/// $\mu h^2/2$ (as a rider carrying a long balancing pole across the wheel's plane), so the
/// rider's centrifugal couple $(B - C)n^2\sin\theta\cos\theta$ of (E) is halved.
const SHAPE_POLE: Shape = Shape { e: -0.5 * H_OVER_R * H_OVER_R, c: 0.6 * H_OVER_R * H_OVER_R };

/// A point of the generated full `unicycle` program for the normalised model of n° 32–41
/// (R = g = mu = 1, z = h/R, L = 0, rates in units of sqrt(g/R)) with the rider's `shape`
/// and a wheel of moment `wheel` mu1 R^2 about its axle (0 for none, 2 for n° 40's) and
/// mu1 R^2 = C; the rider's A is taken equal to B (A only divides K, whose sign is read).
fn n40_point(theta_deg: f64, s: f64, n: f64, shape: Shape, wheel: f64) -> Point {
    let (z, c) = (H_OVER_R, shape.c);
    let b = c + z * z + shape.e;
    let mu1 = if wheel == 0.0 { 0.0 } else { c };
    BTreeMap::from([
        ("R", 1.0),
        ("g", 1.0),
        ("mu", 1.0),
        ("z", z),
        ("A", b),
        ("B", b),
        ("C", c),
        ("L", 0.0),
        ("mu1", mu1),
        ("A1", 1.5 * mu1),
        ("B1", wheel * mu1),
        ("C1", 0.5 * mu1),
        ("theta", theta_deg.to_radians()),
        ("p", 0.0),
        ("n", n),
        ("s", s),
        ("dp", 0.0),
        ("dn", 0.0),
        ("ds", 0.0),
    ])
}

fn practical_region() -> Claim {
    practical_region_check(SHAPE_32)
}

/// The check of [`practical_region`] for a rider of the given `shape`: (E) of n° 29 with no
/// wheel (n° 32), D of n° 30 and the stability K of the simplified model of n° 33 with
/// n° 40's wheel, all from the generated full program (with $E = 0$ they are n° 32's (E)
/// and (D) and n° 40's (S) times positive factors).
fn practical_region_check(shape: Shape) -> Claim {
    let limit = carvallo::unicycle_discussion::speed_limit();
    let friction = (1.0 / H_OVER_R).asin().tan();
    let (mut tested, mut n2_bad, mut n1_good, mut n2_bad_s) = (0usize, 0usize, 0usize, 0.0f64);
    let mut example = (f64::NAN, f64::NAN, f64::NAN);
    for th in grid(0.5, 23.5, 47) {
        for s in grid(1.0, limit, 60) {
            let e = |n: f64| out(&n40_point(th, s, n, shape, 0.0), "equilibrium");
            let Some([n1, n2]) = roots(e) else { continue };
            tested += 1;
            let usable = |n: f64| {
                walks(n, s)
                    && out(&n40_point(th, s, n, shape, 0.0), "skid") < friction
                    && out(&n40_point(th, s, n, shape, HOOP_SPIN), "stability_simplified") > 0.0
            };
            if !usable(n2) {
                n2_bad += 1;
                n2_bad_s = n2_bad_s.max(s);
            }
            if usable(n1) {
                n1_good += 1;
                if example.0.is_nan() {
                    example = (th, s, n1);
                }
            }
        }
    }
    // n2 fails only in the band under the true limit of stability, which the memoir takes as
    // s = 1 (claim unicycle-stability-circle): not counted against the region.
    let holds = n2_bad_s < 1.04 && n1_good == 0 && tested > 500;
    Claim::new(
        "unicycle-practical-region",
        "32",
        "Leaving the pivoting solutions aside, only the solution n2 is suitable, and only in the region between the polar rays 0° and 23.6° and the circles of radii 1 and 2.6.",
        "At the steady states of the normalised (E) (n° 32: B - C = mu h^2, h/R = 2.5, g = R = mu = 1, no wheel; the generated full (E) of n° 29, n° 32's form times mu g h cos(theta)) on a grid of 47 leans 0.5°–23.5° × 60 rates from 1 to the derived speed limit 2.51: whether each root walks (|n| < s), does not skid (generated D of n° 30 below tan 23.6° = 0.437) and is stable (generated K of n° 33's simplified model with n° 40's wheel, mu1 R^2 = C, B1 = 2 mu1 R^2, > 0: n° 40's (S) times A/(mu R h); the rider's C drops out).",
        &[("points_with_roots", tested as f64), ("n2_unusable", n2_bad as f64), ("n2_unusable_max_s", n2_bad_s), ("n1_usable", n1_good as f64), ("first_n1_theta_deg", example.0), ("first_n1_s", example.1), ("first_n1_n", example.2)],
        policy::claim(holds, Verdict::MemoirError),
        "n2 walks, holds and is stable everywhere in the region except in the thin band 1 < s < 1.032 under the true limit of stability (the circle s = 1 is an approximation, claim unicycle-stability-circle); but n1 is not always a pivoting solution there: between (N) and (ℰ) beyond I the memoir itself says both roots walk, and there n1 is also stable and does not skid (all states are stable beyond 16.3°), so « n2 seule » overlooks that band; the region is also bounded below by (ℰ) (no steady state under it, e.g. s < 1.32 at 23.6°). Kept `memoir-error` against the policy's words (issue 24): a 'practical' summary is not an approximation the memoir declares with a size, which `rounding` would need, and the fault is the memoir's own reasoning, shown where: its own regions of n° 32 (claim unicycle-walking-pivoting-regions, agrees) make n1 walk in that band, and there the derivation finds n1 stable and not skidding (first example above). The band is the rider's centrifugal couple (B - C) n^2 sin(theta) cos(theta) of (E): it lifts (N) over the circle s = 1 at 16.4°, before the asymptote; with that couple halved (the falsification's rider, B - C = mu h^2/2) (N) stays under s = 1 up to 23.5° and I moves to 23.58°, n1 pivots in the whole region, n2 stays usable, and « n2 seule » would hold.",
    )
}

// n° 33–35 ----------------------------------------------------------------------------------

fn l_terms_vanish() -> Claim {
    let (mut steady, mut structure) = (0.0f64, 0.0f64);
    for base in points(false).iter().take(16) {
        let res = |q: &Point| {
            let v = eval(q);
            [v["rider_p"] + v["wheel_p"], v["rider_n"] + v["wheel_n"], v["rider_s"] + v["wheel_s"]]
        };
        let by_l = |q: &Point| {
            let (a, b) = (res(&with(q, &[("L", 1.0)])), res(&with(q, &[("L", 0.0)])));
            [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
        };
        let st = with(base, &[("p", 0.0), ("dp", 0.0), ("dn", 0.0), ("ds", 0.0)]);
        for x in by_l(&st) {
            steady = mx(steady, x.abs());
        }
        let d = by_l(base);
        let (th, p, dp, dn) = (base["theta"], base["p"], base["dp"], base["dn"]);
        let expect = [-dn * th.cos(), -dp * th.cos() + p * p * th.sin(), 0.0];
        for (x, y) in d.iter().zip(expect) {
            structure = mx(structure, (x - y).abs() / (1.0 + y.abs()));
        }
    }
    let holds = steady <= 1e-12 && structure <= 1e-10;
    Claim::new(
        "unicycle-l-terms-vanish-at-steady",
        "33",
        "The variables multiplied by L, n' cos(theta), p' and p^2 sin(theta), vanish in a steady state.",
        "The part of the generated (p), (n), (s) first members (rider + wheel) proportional to L (difference of L = 1 and L = 0) at 16 seeded states, against -n' cos, -p' cos + p^2 sin, 0, and at the same states made steady.",
        &[("max_L_part_steady", steady), ("max_diff_L_part_general", structure)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "L multiplies exactly those variables and nothing else (none in (s)): L does not enter (E) nor the steady states; it enters the stability (n° 78).",
    )
}

fn solved_form() -> Claim {
    let (mut with_l0, mut with_l1) = (0.0f64, 0.0f64);
    for base in points(false).iter().take(16) {
        for (l, acc) in [(0.0, &mut with_l0), (1.0, &mut with_l1)] {
            let q = |p: f64| eval(&with(base, &[("L", l), ("p", p)]));
            let (v0, v1, v2) = (q(0.0), q(0.7), q(1.4));
            let scale = base["g"] / base["R"];
            let dev = [
                (v1["pns_dp"] - v0["pns_dp"]).abs(),
                v0["pns_dn"].abs(),
                v0["pns_ds"].abs(),
                (v2["pns_dn"] - 2.0 * v1["pns_dn"]).abs(),
                (v2["pns_ds"] - 2.0 * v1["pns_ds"]).abs(),
            ];
            *acc = mx(*acc, dev.iter().fold(0.0f64, |a, &b| a.max(b)) / scale);
        }
    }
    let holds = with_l0 <= 1e-12 && with_l1 > 1e-3;
    Claim::new(
        "unicycle-solved-form",
        "34",
        "Solved for p', n', s', the equations have the form p' = f(n, s, theta), n' = p g(n, s, theta), s' = p h(n, s, theta), which the transformations of n° 8–9 need.",
        "The generated full model's p', n', s' at p = 0, 0.7, 1.4 (other state and parameters seeded, 16 points): p' independent of p, n' and s' zero at p = 0 and linear in p; with L = 0 and with L = 1. Holds by construction because the form is a statement about which monomials the derived equations contain, not about their coefficients: with L = 0 no term of (p) carries p or p' (p enters the moments only through the compound centrifugal terms of (n) and (s), each a product of p with a rate), so a coefficient scaled or an ingredient changed keeps it (every argument of pns_dp, pns_dn and pns_ds scaled by -1, 0, 1.01 and 2, and each of their first 12 constants by -1, 1.01 and 2, one at a time, leaves the verdict, tried on branch hC); only a term of another form, which the derivation cannot give, would break it",
        &[("max_dev_L0_in_g_over_R", with_l0), ("max_dev_L1_in_g_over_R", with_l1)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The form holds exactly with L = 0 (wheel included); with L != 0 it is lost (terms L p' cos and L p^2 sin), which is why n° 33 sets L = 0 and n° 78 needs another method.",
    )
}

fn stability_recipe() -> Claim {
    let mut worst = 0.0f64;
    for base in points(false).iter().take(16) {
        let b = with(base, &[("L", 0.0), ("p", 0.0)]);
        let pp = |q: &Point| out(q, "pns_dp");
        let d_theta = diff(&b, "theta", 1e-5, pp);
        let d_n = diff(&b, "n", 1e-3, pp);
        let d_s = diff(&b, "s", 1e-3, pp);
        let one = eval(&with(&b, &[("p", 1.0)]));
        let p2 = d_theta + one["pns_dn"] * d_n + one["pns_ds"] * d_s;
        worst = mx(worst, rel_diff(-p2, out(&b, "stability")));
    }
    Claim::new(
        "unicycle-stability-recipe",
        "34",
        "The stability condition is (S) 0 < -p''/p with p''/p = dp'/dtheta + (n'/p) dp'/dn + (s'/p) dp'/ds, as for the hoop at n° 9.",
        "The memoir's recipe evaluated on the generated full model (L = 0): the partial derivatives of p' by central differences, n'/p and s'/p at p = 1, at 16 seeded states, against the generated stability first member (the n° 76 determinant divided by lambda^2).",
        &[("points", 16.0), ("max_rel_diff", worst)],
        policy::numeric(worst, FD, Verdict::DerivationDiffers),
        "The recipe and the determinant give the same first member.",
    )
}

fn stability_biquadratic() -> Claim {
    let (mut form, mut biq) = (0.0f64, 0.0f64);
    let mut rng = crate::sample::Rng(super::SEED ^ 35);
    for base in points(false).iter().take(16) {
        let b = with(base, &[("L", 0.0)]);
        let k = |s: f64, n: f64| out(&with(&b, &[("s", s), ("n", n)]), "stability");
        let d = k(0.0, 0.0);
        let a = k(0.0, 1.0) - d;
        let c = k(1.0, 0.0) - d;
        let bb = k(1.0, 1.0) - a - c - d;
        for _ in 0..4 {
            let (s, n) = (rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0));
            form = mx(form, rel_diff(k(s, n), a * n * n + bb * s * n + c * s * s + d));
        }
        // Along (E): s = e n + f/n; then n^2 K is a quadratic in m = n^2.
        let e0 = |n: f64| out(&with(&b, &[("s", 0.0), ("n", n)]), "equilibrium");
        let e1 = |n: f64| out(&with(&b, &[("s", 1.0), ("n", n)]), "equilibrium");
        let on_e = |m: f64| {
            let n = -m.sqrt();
            let s = -e0(n) / (e1(n) - e0(n));
            m * k(s, n)
        };
        let (y1, y2, y3) = (on_e(1.0), on_e(2.0), on_e(3.0));
        let q2 = (y3 - 2.0 * y2 + y1) / 2.0;
        let q1 = y2 - y1 - 3.0 * q2;
        let q0 = y1 - q1 - q2;
        for m in [0.25, 0.6, 5.0] {
            biq = mx(biq, rel_diff(on_e(m), q2 * m * m + q1 * m + q0));
        }
    }
    let holds = form <= 1e-9 && biq <= 1e-8;
    Claim::new(
        "unicycle-stability-biquadratic",
        "35",
        "(S) has the form a n^2 + b n + c s^2 + d > 0 with a, b, c, d functions of theta; with s = e n + f/n from (E) it becomes a biquadratic inequality in n (terms in n^2, 1/n^2 and a constant).",
        "The generated stability first member of the full model (L = 0) at 16 seeded unicycles: its coefficients read at (s, n) = (0, 0), (0, 1), (1, 0), (1, 1) and tested at 4 seeded (s, n) each; along the generated (E), n^2 times it at n^2 = 1, 2, 3 fitted by a quadratic in n^2 and tested at n^2 = 0.25, 0.6, 5. Holds by construction because (S) at p = 0 is the constant term of the n° 76 determinant, a sum of products of two first-order terms of the equations, each linear in n and s or free of them: a coefficient scaled, an ingredient changed or an argument's sign flipped keeps a n^2 + b s n + c s^2 + d (scaling n or s maps the form onto itself), and along (E), which is linear in s, n^2 (S) stays a quadratic in n^2; only a term of another degree, which the derivation cannot give, would break it",
        &[("max_rel_diff_form", form), ("max_rel_diff_biquadratic", biq)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The form is a n^2 + b s n + c s^2 + d: the printed « b n » lost its s (the memoir's next sentence, terms in n^2, 1/n^2 and a constant only, needs b s n; with b n there would be a term in n). With it the inequality is biquadratic, for the full model too.",
    )
}

// n° 36–37 ----------------------------------------------------------------------------------

fn straight_running_steady() -> Claim {
    let mut worst = 0.0f64;
    let mut zero = 0.0f64;
    for base in points(false).iter().take(16) {
        let e = |th: f64, s: f64| {
            out(&with(base, &[("theta", th), ("s", s), ("n", 0.0)]), "equilibrium")
        };
        let th = base["theta"];
        let w = (base["mu"] * base["z"] + base["mu1"] * base["R"]) * base["g"] * th.sin();
        for s in [0.0, 1.0, 10.0] {
            worst = mx(worst, rel_diff(e(th, s).abs(), w.abs()));
            zero = mx(zero, e(0.0, s).abs());
        }
    }
    Claim::new(
        "unicycle-straight-running-steady",
        "36",
        "Straight running (n = 0): (E) gives theta = 0 and s arbitrary.",
        "The generated (E) of the full model at n = 0, 16 seeded unicycles and leans, s = 0, 1, 10: its size against the weight's moment (mu z + mu1 R) g sin(theta), and its value at theta = 0.",
        &[("max_rel_diff_weight", worst), ("max_at_theta_0", zero)],
        policy::claim(worst <= 1e-12 && zero <= 1e-12, Verdict::DerivationDiffers),
        "At n = 0 (E) is the weight's moment alone, zero only upright, whatever s.",
    )
}

/// The full model's straight-running threshold s^2 (unit g/R) with no rider, and with a rider
/// of vanishing mass, on the hoop wheel; the hoop's own (n° 14).
pub(super) fn light_rider_limit() -> (f64, f64, f64) {
    let base = hoop_wheel(&points(false)[0], 5.0);
    let none = stability_threshold(&no_rider(&base), "stability").powi(2);
    let tiny = with(
        &base,
        &[("mu", 1e-6), ("A", 1e-6), ("B", 1e-6), ("C", 1e-7), ("L", 0.0), ("z", 1.25)],
    );
    let small = stability_threshold(&tiny, "stability").powi(2);
    let hoop = Hoop::new(base["R"], 5.0, base["g"]).ok();
    let h = hoop.map_or(f64::NAN, |h| {
        let u = h.rate_unit();
        bisect(|s| crate::perturb::hoop_stability(&h, 0.0, s * u, 0.0), 0.0, 100.0).powi(2)
    });
    (none, small, h)
}

fn light_rider_hoop() -> Claim {
    let (none, small, hoop) = light_rider_limit();
    // The memoir's formula s^2 > C / (mu1 R^2) with C = C1 = mu1 R^2 / 2.
    let base = points(false)[0].clone();
    let memoir = (0.5 * 5.0 * base["R"] * base["R"]) / (5.0 * base["R"] * base["R"]);
    let holds = rel_diff(memoir, hoop) <= 1e-9;
    Claim::new(
        "unicycle-light-rider-hoop-limit",
        "36",
        "For an infinitely light rider C reduces to C1 = mu1 R^2 / 2 and (S) s^2 > C/(mu1 R^2) gives back the hoop's result s^2 > 1/2.",
        "The straight-running threshold (root in s of the generated stability first member of the full model, L = 0, theta = 0, n = 0) with the hoop wheel and no rider, and with a rider of 1e-6 kg; against the hoop's own generated (S) of n° 9 at theta = 0 and the memoir's formula with C = C1.",
        &[("full_no_rider_s2", none), ("full_light_rider_s2", small), ("hoop_s2", hoop), ("memoir_formula_s2", memoir)],
        policy::claim(holds, Verdict::MemoirError),
        "The formula gives 1/2, but the hoop's threshold is s^2 > 1/4 (n° 14, and n° 18's s >= 0.5), and the full model with the rider removed gives 1/4 too. The formula's limit is wrong because the merged letters (n° 24) put mu R z, the rider's term, for the s n coefficient of (p), which for the hoop is B1 = 2 mu1 R^2 (twice mu1 R R): the merge, harmless while the rider dominates, fails exactly in this limit. The memoir's « on retrouve le résultat obtenu pour le cerceau » compares with a hoop result it misremembers (s > 1/2 of n° 18 read as s^2 > 1/2).",
    )
}

fn light_wheel() -> Claim {
    light_wheel_check(HOOP_SPIN)
}

/// The check of [`light_wheel`] with the wheel's moment about its axle `spin` mu1 R^2.
fn light_wheel_check(spin: f64) -> Claim {
    let masses = [5.0, 0.5, 0.05, 0.005];
    let s2: Vec<f64> = masses
        .iter()
        .map(|&m| threshold_units(&example_spin(0.5, m, 1.25, 0.77, 0.0, spin)).powi(2))
        .collect();
    let scaled: Vec<f64> = s2.iter().zip(masses).map(|(s, m)| s * m).collect();
    let none =
        example_spin(0.5, 0.0, 1.25, 0.77, 0.0, spin).and_then(|u| u.straight_running_threshold());
    let holds = none.is_none()
        && s2.windows(2).all(|w| w[1] > 5.0 * w[0])
        && rel_diff(scaled[3], scaled[2]) < 2e-2;
    Claim::new(
        "unicycle-light-wheel-unstable",
        "36",
        "For a wheel infinitely light before the rider the lower limit of s^2 grows indefinitely: no finite speed makes the equilibrium stable.",
        "The straight-running threshold of the generated full model (n° 36 example: rider 60 kg, h = 1.25 m, C0 = 0.77, hoop wheel of R = 0.5 m) for wheel masses 5, 0.5, 0.05, 0.005 kg, and for a massless wheel (bisection up to 1000 sqrt(g/R)).",
        &[("s2_5kg", s2[0]), ("s2_0.005kg", s2[3]), ("s2_times_mu1_0.005kg", scaled[3]), ("massless_wheel_threshold_found", if none.is_some() { 1.0 } else { 0.0 })],
        policy::claim(holds, Verdict::DerivationDiffers),
        "s^2 grows like 1/mu1 (s^2 mu1 tends to a constant, g C0 / (mu1 R^3) in the full model) and no rate stabilises a massless wheel.",
    )
}

fn stability_decreases() -> Claim {
    stability_decreases_check(HOOP_SPIN)
}

/// The check of [`stability_decreases`] with the wheel's moment about its axle `spin` mu1 R^2.
fn stability_decreases_check(spin: f64) -> Claim {
    let mut speeds = Vec::new();
    for m in [50.0, 20.0, 10.0, 5.0, 2.0, 1.0, 0.5] {
        speeds.push(threshold_speed(&example_spin(0.5, m, 1.25, 0.77, 0.0, spin)));
    }
    let monotone = speeds.windows(2).all(|w| w[1] > w[0]);
    Claim::new(
        "unicycle-stability-decreases-with-wheel",
        "37",
        "« La stabilité diminue indéfiniment avec l'importance relative du moment d'inertie de la roue. »",
        "The straight-running threshold speed R s (m/s) of the generated full model (n° 36 example) for hoop wheels of 50, 20, 10, 5, 2, 1, 0.5 kg.",
        &[("speed_50kg", speeds[0]), ("speed_5kg", speeds[3]), ("speed_0.5kg", speeds[6])],
        policy::claim(monotone, Verdict::DerivationDiffers),
        "The threshold speed rises steadily as the wheel's inertia shrinks relative to the rider's (and without bound, previous claim of n° 36).",
    )
}

fn stability_from_spin() -> Claim {
    let mut rider_term = 0.0f64;
    for base in points(false).iter().take(16) {
        let p = with(
            base,
            &[("theta", 0.0), ("n", 0.0), ("p", 0.0), ("dp", 0.0), ("dn", 0.0), ("ds", 0.0)],
        );
        let scale = p["C"] * p["g"] / p["R"];
        rider_term = mx(rider_term, diff(&p, "p", 1e-3, |q| out(q, "rider_n")).abs() / scale);
    }
    // A wheel whose B1 is only mu1 R^2: no gyroscopic excess. Its threshold from the generated
    // (S) of the full model (what Unicycle::straight_running_threshold evaluates), so that a
    // perturbation of that output reaches it.
    let flat: Point = BTreeMap::from([
        ("R", 0.5),
        ("g", 9.81),
        ("mu", 60.0),
        ("z", 1.25),
        ("A", 100.0),
        ("B", 100.0),
        ("C", 0.77),
        ("L", 0.0),
        ("mu1", 5.0),
        ("A1", 0.625 + 1.25),
        ("B1", 1.25),
        ("C1", 0.625),
        ("p", 0.0),
        ("dp", 0.0),
        ("dn", 0.0),
        ("ds", 0.0),
    ]);
    let found = stability_threshold(&flat, "stability").is_finite();
    let holds = rider_term <= 1e-9 && !found;
    Claim::new(
        "unicycle-stability-from-wheel-spin",
        "37",
        "Only the compound centrifugal forces can give stability; in straight running the rider's are very weak, having no sensible rotation: the stability comes from the wheel's rotation.",
        "The derivative in p of the rider's generated (n) first member at theta = 0, n = 0 (16 seeded states, relative to C g/R); and the full model's straight-running threshold (the root in s of the generated stability first member at theta = 0, n = 0, L = 0, searched up to 1000 sqrt(g/R)) for the n° 36 example with a wheel whose B1 - mu1 R^2 is zero (B1 = mu1 R^2).",
        &[("max_rider_p_term", rider_term), ("threshold_found_without_spin_excess", if found { 1.0 } else { 0.0 })],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The rider contributes nothing to the p s coupling of (n) in straight running; without the wheel's gyroscopic term (B1 - mu1 R^2) p s cos no speed stabilises.",
    )
}

fn fall_turns_toward_lean() -> Claim {
    fall_turns_check(HOOP_SPIN)
}

/// [`fall_turns_toward_lean`] with the wheel's moment about its axle `spin` mu1 R^2
/// ([`HOOP_SPIN`] for the hoop wheel, whose other moments it keeps).
fn fall_turns_check(spin: f64) -> Claim {
    let (mut turn_ok, mut right_ok, mut cases) = (true, true, 0);
    for base in points(false).iter().take(16) {
        let rider = Rider {
            mass: base["mu"],
            height: base["z"],
            a: base["A"],
            b: base["B"],
            c: base["C"],
            l: 0.0,
        };
        let (r, mu1) = (base["R"], base["mu1"]);
        let m = mu1 * r * r;
        let wheel = Wheel { mass: mu1, a1: 1.5 * m, b1: spin * m, c1: 0.5 * m };
        let Ok(u) = Unicycle::new(r, base["g"], rider, wheel) else { continue };
        let s = 2.0 * u.rate_unit();
        for p in [0.05, -0.05] {
            // Upright, falling toward the side of p.
            let [_, _, dn, _] = u.rhs([0.0, p, 0.0, s]);
            turn_ok &= dn * p < 0.0;
            // Once turning that way, the s n term of (p) rights it.
            let n = -p;
            let [_, with_n, _, _] = u.rhs([0.0, 0.0, n, s]);
            let [_, without, _, _] = u.rhs([0.0, 0.0, 0.0, s]);
            right_ok &= (with_n - without) * p < 0.0;
            cases += 1;
        }
    }
    let holds = cases == 32 && turn_ok && right_ok;
    Claim::new(
        "unicycle-fall-turns-toward-lean",
        "37",
        "A fall p of the rolling wheel (fig. 8) gives a turning n from the side it leans: « le cerceau converse du côté où il penche »; and the couple of that turning tends to right it.",
        "The generated full model's right-hand side (L = 0, hoop wheels, 16 seeded unicycles, s = 2 sqrt(g/R)) upright with a fall rate p = ±0.05/s: the sign of n' against p; then at p = 0 with n = -p: the change of p' that the turning brings.",
        &[("cases", cases as f64), ("turns_toward_fall", if turn_ok { 1.0 } else { 0.0 }), ("turning_rights", if right_ok { 1.0 } else { 0.0 })],
        policy::claim(holds, Verdict::DerivationDiffers),
        "n' has the sign of -p (toward the lean, as n° 32 for steady states) and the turning then gives p' the sign opposite to the fall.",
    )
}

/// n° 37: the « couple accélérateur » 2psR² of a rim's elements at the ends of the horizontal
/// diameter, from the acceleration W = Rsp of the rotated velocity vector.
fn accelerating_couple() -> Claim {
    let (r, s, p) = (0.5f64, 10.0f64, 0.3f64);
    // A rim point spinning at s about the axle J, the wheel leaning at p about OI, from the end A
    // of the horizontal diameter (r0 = -R I) at t = 0: its position, then the acceleration
    // normal to the wheel (along J) by a central second difference.
    let pos = |phase: f64, t: f64| {
        let a = phase + s * t;
        let (x, z) = (-r * a.cos(), r * a.sin());
        let lean = p * t;
        [x, -z * lean.sin(), z * lean.cos()]
    };
    let h = 1e-4;
    let acc = |phase: f64| -> [f64; 3] {
        let (a, b, c) = (pos(phase, h), pos(phase, 0.0), pos(phase, -h));
        std::array::from_fn(|i| (a[i] - 2.0 * b[i] + c[i]) / (h * h))
    };
    let normal_a = acc(0.0)[1].abs();
    let normal_b = acc(PI)[1].abs();
    // The couple of the pair of unit masses at A and B about the vertical OK.
    let pair = normal_a * r + normal_b * r;
    // The ring of unit mass: the moment about OK of its elements' accelerations, against the
    // rate of change of its spin momentum, (μR²) s p.
    let n = 720;
    let mut ring = 0.0;
    for k in 0..n {
        let phase = 2.0 * PI * k as f64 / n as f64;
        let (x, a) = (pos(phase, 0.0), acc(phase));
        ring += (x[0] * a[1] - x[1] * a[0]) / n as f64;
    }
    let memoir_w = r * s * p;
    let memoir_couple = 2.0 * p * s * r * r;
    Claim::new(
        "unicycle-accelerating-couple",
        "37",
        "The rotation p of the wheel turns the velocity V = sR of the rear end A of the horizontal diameter, giving A the acceleration W = VV'/dt = Rsp normal to the wheel, and the front end B the opposite one: an « accelerating couple » about the vertical OK of moment psR × 2R = 2psR² (per unit mass at A and B), whose inertia couple turns the hoop toward its lean.",
        "a rim point of a wheel of radius R = 0.5 m spinning at s = 10 rad/s about its axle and leaning at p = 0.3 rad/s about OI: its position in closed form, its acceleration by a central second difference (step 1e-4 s, error about 1e-8 relative); the normal (J) accelerations at A and B, the couple of the pair about OK, and the moment of a ring of unit mass (720 elements) against the rate of change of its spin momentum R² s p (the second route). Holds if the couple is 2psR² within 1e-6. Holds by construction because it is the kinematics of one rim point in closed form (a spin s about the axle composed with a lean rate p about OI) and takes no ingredient of the derived equations: there is no generated expression of it to perturb, and its verdict is decided by the factor 2 between W = Rsp and the Coriolis acceleration 2 p × V, which no mass, moment or coefficient enters; its two routes (the pair A, B and the ring against R² s p) check each other, and the couple as it enters the hoop's equations (the 4/3 s n of (E)) is broken by hoop-turns-toward-lean's perturbation",
        &[
            ("normal acceleration at A (m/s²)", normal_a),
            ("the memoir's W = Rsp (m/s²)", memoir_w),
            ("couple of the pair A, B per unit mass (m²/s²)", pair),
            ("the memoir's 2psR² (m²/s²)", memoir_couple),
            ("ring of unit mass: moment about OK (m²/s²)", ring),
            ("ring: R² s p (m²/s²)", r * r * s * p),
        ],
        policy::claim((pair / memoir_couple - 1.0).abs() < 1e-6, Verdict::MemoirError),
        "the normal acceleration at A is 2Rsp, twice the memoir's W, and the couple 4psR², twice 2psR²: turning the velocity vector accounts for half of the compound centrifugal (Coriolis) acceleration 2 p × V; the other half is the change of the transport velocity p × (A - O) as the spin carries the point (the ring's moment R² s p = B s p confirms 4psR² per pair: a ring's elements weigh cos² of their angle, mean 1/2). The sense, the proportionality to s p and the conclusion drawn (the hoop turns toward its lean, unicycle-fall-turns-toward-lean) are right",
    )
}

/// n° 37: the fall acceleration depends on gravity alone, the turning one is proportional to
/// s, the righting one to s².
fn three_accelerations() -> Claim {
    use carvallo::hoop_discussion as hd;
    let (r, g) = (0.5f64, 9.81f64);
    let rhs = |s: f64, theta: f64, p: f64, n: f64| {
        let v = hd::eval(&[
            ("R", r),
            ("g", g),
            ("s", s),
            ("M", 0.0),
            ("M1", 0.0),
            ("theta", theta),
            ("p", p),
            ("n", n),
        ]);
        (v["stick_dp"], v["stick_dn"])
    };
    let s = 2.0 * (g / r).sqrt();
    let theta = 0.01;
    // The fall acceleration at rest (p = n = 0): gravity only.
    let fall = |s: f64| rhs(s, theta, 0.0, 0.0).0;
    // The turning acceleration n' caused by a fall rate p.
    let turn = |s: f64| rhs(s, 0.0, 0.1, 0.0).1;
    // The righting acceleration caused by the turn n = -2sθ that the fall produces (n° 19 (3)).
    let right = |s: f64| rhs(s, theta, 0.0, -2.0 * s * theta).0 - fall(s);
    let ratios = [fall(2.0 * s) / fall(s), turn(2.0 * s) / turn(s), right(2.0 * s) / right(s)];
    Claim::new(
        "unicycle-three-accelerations",
        "37",
        "The first acceleration, of the fall p', is proportional to gravity alone; the second, W, to s; the third, the righting one, to s²: when s is large enough the righting couple wins over the fall, which is due to gravity alone.",
        "the generated linearised equations of n° 19's (2) without stick moments (stick_dp, stick_dn; R = 0.5 m, g = 9.81, s = 2 sqrt(g/R)) at s and 2s: the fall acceleration at θ = 0.01 rad at rest, the turning acceleration n' for a fall rate p = 0.1 rad/s upright, and the righting part of p' for the turn n = -2sθ that the fall produces (n° 19 (3)). Holds if doubling s multiplies them by 1, 2 and 4 within 1e-12. Holds by construction because the ratios are the degrees of the three terms in the rates (none, p s, s n with n = -2 s θ): every term of the generated equations is a product of rates and a coefficient of θ alone, so no constant of the program can move the ratios, only the degrees, which a re-derivation would change",
        &[
            ("fall acceleration ratio (2s / s)", ratios[0]),
            ("turning acceleration ratio (2s / s)", ratios[1]),
            ("righting acceleration ratio (2s / s)", ratios[2]),
        ],
        policy::claim(
            (ratios[0] - 1.0).abs() < 1e-12
                && (ratios[1] - 2.0).abs() < 1e-12
                && (ratios[2] - 4.0).abs() < 1e-12,
            Verdict::DerivationDiffers,
        ),
        "1, 2, 4: the fall acceleration 2gθ/(3R) has no s, the turning one -2ps is proportional to s, the righting one (4/3) s n with n = -2sθ is -(8/3) s² θ, which beats gravity when 4s² > g/R (n° 19's h², n° 14's upright threshold)",
    )
}

fn straight_oscillates() -> Claim {
    straight_oscillates_check(HOOP_SPIN)
}

/// The check of [`straight_oscillates`] with the wheel's moment about its axle `spin` mu1 R^2.
fn straight_oscillates_check(spin: f64) -> Claim {
    let u = example_spin(0.5, 5.0, 1.25, 0.77, 0.0, spin);
    let (mut fast_max, mut fast_changes, mut slow_max, mut drift) =
        (f64::NAN, 0usize, f64::NAN, f64::NAN);
    if let Some(u) = u {
        if let Some(th) = u.straight_running_threshold() {
            let run = |s: f64, seconds: f64| {
                let mut x = [0.02, 0.0, 0.0, s];
                let (mut largest, mut changes, mut last) = (0.0f64, 0usize, 1.0f64);
                let e0 = u.energy(x);
                let steps = (seconds / 1e-3) as usize;
                for _ in 0..steps {
                    x = u.simulate(x, 1e-3, 1);
                    largest = mx(largest, x[0].abs());
                    if x[1] != 0.0 && x[1].signum() != last {
                        changes += 1;
                        last = x[1].signum();
                    }
                    if x[0].abs() > 1.0 {
                        break;
                    }
                }
                (largest, changes, (u.energy(x) - e0).abs() / e0.abs())
            };
            let (m, c, d) = run(1.5 * th, 10.0);
            fast_max = m;
            fast_changes = c;
            drift = d;
            slow_max = run(0.5 * th, 10.0).0;
        }
    }
    let holds = fast_max < 0.1 && fast_changes >= 4 && slow_max > 1.0 && drift < 1e-8;
    Claim::new(
        "unicycle-straight-running-oscillates",
        "37",
        "When s is large enough the righting couple (proportional to s^2) overcomes the fall due to gravity alone; the rotations then alternate and are periodic.",
        "RK4 (dt = 1 ms, 10 s) of the generated full model (n° 36 example, L = 0), upright straight running disturbed by theta = 0.02 rad, at 1.5 and 0.5 times the straight-running threshold.",
        &[("fast_max_theta", fast_max), ("fast_sign_changes_of_p", fast_changes as f64), ("fast_rel_energy_drift", drift), ("slow_max_theta", slow_max)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Above the threshold the fall rate p changes sign again and again and the lean stays between two bounds (here 0.02 and 0.053 rad: it swings about a neighbouring steady turn, not about the upright, as the hoop's of n° 9); below it the unicycle falls (the run stops at 1 rad).",
    )
}

// n° 39 ------------------------------------------------------------------------------------

fn light_only_turning() -> Claim {
    let (mut smallest_stable_n, mut straight_max) = (f64::INFINITY, f64::NEG_INFINITY);
    for th in grid(0.0, 60.0, 61) {
        for n in grid(-4.0, -0.01, 400) {
            let s = if th == 0.0 { 0.0 } else { s_on_e(th, n) };
            if out(&n32(th, s, n), "stability_n39") > 0.0 {
                smallest_stable_n = smallest_stable_n.min(n.abs());
            }
        }
    }
    for s in grid(0.0, 100.0, 101) {
        straight_max = mx(straight_max, out(&n32(0.0, s, 0.0), "stability_n39"));
    }
    let bound = (1.0 / H_OVER_R).sqrt();
    let holds = smallest_stable_n >= bound * (1.0 - 1e-2) && straight_max < 0.0;
    Claim::new(
        "unicycle-light-stable-only-turning",
        "39",
        "« C'est seulement en tournant que le cavalier d'un cycle léger peut acquérir la stabilité. »",
        "The generated (S1) of n° 39 (infinitely light wheel, E = 0, h/R = 2.5) at the steady states of the generated (E): 61 leans 0°–60° × 400 turning rates; and upright straight running (theta = 0, n = 0) for s = 0–100.",
        &[("smallest_stable_abs_n", smallest_stable_n), ("sqrt_R_over_h", bound), ("max_S1_straight", straight_max)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Straight running is never stable (S1 = -1 whatever s) and every stable state turns with |n| >= sqrt(R/h) / cos^(3/2) >= 0.632 sqrt(g/R): a light unicycle is stable only while turning.",
    )
}

fn light_root_n1() -> Claim {
    let (mut n2_stable, mut checked) = (0usize, 0usize);
    let mut gaps = Vec::new();
    for th in [10.0, 20.0, 30.0, 40.0, 50.0] {
        let (n0, s0) = minimum_on_e(th);
        let f = |n: f64| out(&n32(th, s_on_e(th, n), n), "stability_n39");
        let n_lim = bisect(f, -10.0, n0);
        let s_lim = s_on_e(th, n_lim);
        gaps.push((s_lim - s0) / s0);
        for s in grid(s0 * 1.0001, 4.0 * s0, 60) {
            let Some([n1, n2]) = roots_n32(th, s) else { continue };
            checked += 1;
            if out(&n32(th, s, n2), "stability_n39") > 0.0 {
                n2_stable += 1;
            }
            let n1_stable = out(&n32(th, s, n1), "stability_n39") > 0.0;
            if n1_stable != (s > s_lim) {
                n2_stable += 1000;
            }
        }
    }
    let holds = n2_stable == 0 && gaps.iter().all(|g| *g < 0.15);
    Claim::new(
        "unicycle-light-stable-root-n1",
        "39",
        "The stability limit follows (ℰ) very closely, so practically stability means taking the root n1 of (E), the smaller algebraically, the larger in absolute value.",
        "At leans 10°–50°, 60 rates from s0 to 4 s0 each: the generated (S1) of n° 39 at both roots of the generated (E); the limit rate s_lim where (S1) vanishes along (E) against s0 of (ℰ).",
        &[("states", checked as f64), ("exceptions", n2_stable as f64), ("rel_gap_10deg", gaps[0]), ("rel_gap_30deg", gaps[2]), ("rel_gap_50deg", gaps[4])],
        policy::claim(holds, Verdict::DerivationDiffers),
        "n2 is never stable; n1 is stable exactly above s_lim, which is within 1e-4 of (ℰ) at 10° and 10 % above it at 50°: « pratiquement », as the memoir says, n1 is the stable root, except in that thin band above (ℰ).",
    )
}

fn light_turning_radius() -> Claim {
    let mut largest = 0.0f64;
    for th in grid(0.5, 85.0, 170) {
        for n in grid(-6.0, -0.05, 300) {
            let s = s_on_e(th, n);
            if s > 0.0 && out(&n32(th, s, n), "stability_n39") > 0.0 {
                largest = mx(largest, s / n.abs());
            }
        }
    }
    let r = 0.5;
    let radius = largest * r;
    let holds = 2.0 * radius < 4.0;
    Claim::new(
        "unicycle-light-turning-radius",
        "39",
        "The Nouveau Cirque unicyclist, on a light wheel, evolved on a small platform (about 4 m square): the cause is that a light unicycle is stable only while turning.",
        "The radius of the contact's path R s/|n| (n° 17) over the stable steady states of the generated (S1) of n° 39 along the generated (E), 170 leans 0.5°–85° × 300 turning rates, with the memoir's R = 0.5 m.",
        &[("max_path_radius_over_R", largest), ("max_path_radius_m", radius)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "Every stable state turns on a circle of radius at most 2.72 R (bound (h/R) sin(theta)(1 + cos^2 theta)), 1.36 m for R = 0.5 m: the circles fit the 4 m platform, consistent with the memoir's explanation.",
    )
}

/// The circumference (m) of the cylinder rider of n° 36 whose moments the checks of n° 39 read:
/// the memoir's 1 m.
const RIDER_CIRCUMFERENCE: f64 = 1.0;

/// The words stating the fat cylinder rider under which the checks of n° 39 must fail.
const FAT_RIDER: &str = "the cylinder rider's circumference 3 m instead of 1 m (radius 0.48 m instead of 0.16 m; 60 kg, centre at 1.25 m and lengths 1.0-1.8 m kept): its moment C about its axis grows ninefold";

fn e_larger_than_c() -> Claim {
    e_larger_than_c_for(RIDER_CIRCUMFERENCE)
}

/// [`e_larger_than_c`] for a cylinder rider of circumference `circumference` (m).
fn e_larger_than_c_for(circumference: f64) -> Claim {
    let (mu, r) = (60.0, circumference / (2.0 * PI));
    let h = 1.25;
    let mut ratios = Vec::new();
    for len in grid(1.0, 1.8, 9) {
        let (_, b, c) = cylinder(mu, r, len, h);
        ratios.push((b - c - mu * h * h) / c);
    }
    let zero_len = bisect(
        |len| {
            let (_, b, c) = cylinder(mu, r, len, h);
            b - c - mu * h * h
        },
        0.05,
        1.0,
    );
    let holds = ratios.iter().all(|x| *x > 1.0) && zero_len < 2.0 * r;
    Claim::new(
        "unicycle-e-larger-than-c",
        "39",
        "E = B - C - mu h^2 is usually larger than C, and E = 0 corresponds to a rider « démesurément gros et court ».",
        "The memoir's cylinder rider of n° 36 (60 kg, circumference 1 m, centre at h = 1.25 m): B and C by the midpoint rule over its volume for lengths 1.0–1.8 m, and the length for which E = 0 by bisection.",
        &[("min_E_over_C", ratios.iter().fold(f64::INFINITY, |a, &b| a.min(b))), ("max_E_over_C", ratios.iter().fold(0.0f64, |a, &b| a.max(b))), ("length_for_E0_m", zero_len), ("diameter_m", 2.0 * r)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "E/C is 6–21 for riders of 1.0–1.8 m; E = 0 needs a cylinder only 0.28 m long for a diameter of 0.32 m, short and fat indeed (E = mu(l^2/12 - r^2/4), C = mu r^2/2).",
    )
}

/// n° 39: E = 0 is acceptable in (E) (beside μh²) but not in (S) (beside C).
fn e_zero_not_in_s() -> Claim {
    e_zero_not_in_s_for(RIDER_CIRCUMFERENCE)
}

/// [`e_zero_not_in_s`] for a cylinder rider of circumference `circumference` (m).
fn e_zero_not_in_s_for(circumference: f64) -> Claim {
    let (mu, r, h) = (60.0, circumference / (2.0 * PI), 1.25);
    let (mut max_e_share, mut min_e_share, mut min_factor) = (0.0f64, f64::INFINITY, f64::INFINITY);
    for len in grid(1.0, 1.8, 9) {
        let (_, b, c) = cylinder(mu, r, len, h);
        let e = b - c - mu * h * h;
        // (E) of n° 32 uses B - C = μh² + E: the relative change when E is dropped.
        max_e_share = max_e_share.max(e / (mu * h * h + e));
        min_e_share = min_e_share.min(e / (mu * h * h + e));
        // (S) of n° 39: the coefficient of μRhsn sin θ is (C + E(1 + cos²θ)) / (C + E sin²θ),
        // 1 with E = 0.
        for deg in [10.0f64, 20.0, 30.0] {
            let (sn, cs) = (deg.to_radians().sin(), deg.to_radians().cos());
            min_factor = min_factor.min((c + e * (1.0 + cs * cs)) / (c + e * sn * sn));
        }
    }
    Claim::new(
        "unicycle-e-zero-not-in-s",
        "39",
        "The hypothesis E = 0 (B - C = μh²), « très acceptable au n° 32 » where only an approximate value of the coefficient B - C of (E) is needed, « ne l'est plus au même titre dans l'inégalité (S) »: there E stands beside C, much smaller, in the fraction (C + E(1 + cos²θ)) / (C + E sin²θ).",
        "the cylinder riders of unicycle-e-larger-than-c (60 kg, circumference 1 m, centre at h = 1.25 m, lengths 1.0-1.8 m, B and C by the midpoint rule): the share of E in B - C = μh² + E (the error of E = 0 in (E)), and the fraction of (S) at θ = 10°, 20°, 30° (1 with E = 0). Holds if the relative error of E = 0 in (S)'s fraction, (fraction - 1), is at least ten times its largest relative error in (E)'s coefficient (a comparison: « pas au même titre »)",
        &[
            ("smallest share of E in B - C", min_e_share),
            ("largest share of E in B - C", max_e_share),
            ("smallest fraction of (S) with the real E", min_factor),
            ("error in (S) over error in (E)", (min_factor - 1.0) / max_e_share),
        ],
        policy::claim((min_factor - 1.0) >= 10.0 * max_e_share, Verdict::DerivationDiffers),
        "E = 0 changes the coefficient B - C of (E) by 5 to 14 % for riders of 1.0 to 1.8 m, a rough value as n° 32 needs; in (S) it replaces a fraction of 4.6 or more by 1, an error 25 times larger: (S) with E = 0 is not the realistic rider's condition, as the memoir warns",
    )
}

// n° 40–41 ----------------------------------------------------------------------------------

fn threshold_independent() -> Claim {
    let base = example(0.5, 5.0, 1.25, 0.77, 0.0);
    let reference = threshold_units(&base);
    let mut worst = 0.0f64;
    for (a, b) in [(100.0, 100.0), (95.0, 95.5), (140.0, 139.5), (60.0, 60.5)] {
        let rider = Rider { mass: 60.0, height: 1.25, a, b, c: 0.77, l: 0.0 };
        let u = Unicycle::new(0.5, 9.81, rider, Wheel::hoop(5.0, 0.5)).ok();
        worst = mx(worst, rel_diff(threshold_units(&u), reference));
    }
    // L through the product of the roots of n° 78 (s held constant).
    let p0: Point = BTreeMap::from([
        ("R", 0.5),
        ("g", 9.81),
        ("mu", 60.0),
        ("z", 1.25),
        ("A", 100.0),
        ("B", 100.0),
        ("C", 0.77),
        ("mu1", 5.0),
        ("A1", 1.875),
        ("B1", 2.5),
        ("C1", 0.625),
        ("theta", 0.0),
        ("n", 0.0),
        ("p", 0.0),
        ("dp", 0.0),
        ("dn", 0.0),
        ("ds", 0.0),
    ]);
    let unit = (9.81f64 / 0.5).sqrt();
    for l in [-2.0, 0.0, 2.0] {
        let q = with(&p0, &[("L", l)]);
        let root = bisect(|s| out(&with(&q, &[("s", s * unit)]), "char78_c0"), 0.0, 100.0);
        worst = mx(worst, rel_diff(root, reference));
    }
    let memoir = (1.40f64 / 1.25).sqrt();
    let holds = reference.is_finite() && worst <= 1e-9;
    Claim::new(
        "unicycle-straight-threshold-independent",
        "40",
        "The straight-running stability of n° 36 was found without the simplifications of n° 39–40 (E = 0, h/R = 2.5, mu1 R^2/C = 1); the result is independent of them.",
        "The full model's straight-running threshold (n° 36 example) for four pairs (A, B) (so E = B - C - mu h^2 from -34 to +46 kg m^2), and the root of the generated n° 78 product (s held constant) for L = -2, 0, 2.",
        &[("threshold_units", reference), ("max_rel_change", worst), ("memoir_formula_units", memoir)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "A, B (hence E) and L do not enter the threshold; what does change it is the merge of the wheel's letters (n° 24): 1.040 in the full model against the formula's 1.058 with C = 1.40 (the report's n° 36 entries).",
    )
}

fn bracket_positive() -> Claim {
    let mut smallest = f64::INFINITY;
    for th in grid(0.0, 89.5, 180) {
        let (_, b, _) = read::trinomial(th);
        smallest = smallest.min(-b * th.to_radians().cos());
    }
    Claim::new(
        "unicycle-bracket-positive",
        "41",
        "With h/R = 2.5 the bracket 1/cos(theta) - (h/R) sin^2(theta) cos(theta) is always positive.",
        "Minus the n^2 coefficient of the generated trinomial S(n^2) of n° 41, times cos(theta), at 180 leans 0°–89.5°.",
        &[("min_cos_times_bracket", smallest)],
        policy::claim(smallest > 0.0, Verdict::DerivationDiffers),
        "cos times the bracket is 1 - 2.5 cos^2 sin^2 >= 1 - 2.5/4 = 0.375: positive for every lean (for h/R < 4).",
    )
}

fn stable_between_roots() -> Claim {
    let (r1, r2) = carvallo::unicycle_discussion::first_member_roots();
    let (mut smallest, mut count) = (f64::INFINITY, 0);
    for th in grid(r1 + 0.05, r2 - 0.05, 60) {
        for n in grid(-6.0, -0.01, 300) {
            let v = out(&n32(th, s_on_e(th, n), n), "stability_n40");
            smallest = smallest.min(v / (1.0 + n * n));
            count += 1;
        }
    }
    Claim::new(
        "unicycle-stable-between-roots",
        "41",
        "Between 16.0° and 62.7° the trinomial S(n^2) has imaginary roots, it is always positive and the stability condition (S) is satisfied: every steady state there is stable.",
        "The generated (S) of n° 40 at the steady states of the generated (E) for 60 leans strictly between the derived zeros (16.32°, 62.82°) × 300 turning rates from -6 to -0.01.",
        &[("states", count as f64), ("min_S_over_1_plus_n2", smallest), ("first_zero_deg", r1), ("second_zero_deg", r2)],
        policy::claim(smallest > 0.0, Verdict::DerivationDiffers),
        "Every lean between the two zeros is stable at every rate (the zeros are 16.32° and 62.82°, printed 16.0° and 62.7°).",
    )
}

fn small_lean() -> Claim {
    let (r1, _) = carvallo::unicycle_discussion::first_member_roots();
    let (mut wrong, mut count) = (0usize, 0usize);
    for th in grid(0.5, r1 - 0.05, 40) {
        let (a, b, c) = trinomial(th);
        let disc = (b * b - 4.0 * a * c).sqrt();
        let (m1, m2) = ((-b - disc) / (2.0 * a), (-b + disc) / (2.0 * a));
        if !(m1 > 0.0 && m2 > m1) {
            wrong += 1;
            continue;
        }
        for n in grid(-4.0, -0.01, 200) {
            let m = n * n;
            if (m - m1).abs() < 1e-6 * m1 || (m - m2).abs() < 1e-6 * m2 {
                continue;
            }
            let stable = out(&n32(th, s_on_e(th, n), n), "stability_n40") > 0.0;
            if stable != (m < m1 || m > m2) {
                wrong += 1;
            }
            count += 1;
        }
    }
    Claim::new(
        "unicycle-small-lean-outside-interval",
        "41",
        "For theta < 16.0° the trinomial has two positive roots a^2, b^2, and stability requires n^2 outside (a^2, b^2), i.e. n outside (-b, -a).",
        "The roots of the generated trinomial at 40 leans 0.5°–16.27°, and the generated (S) of n° 40 at the steady states of the generated (E) for 200 turning rates each.",
        &[("states", count as f64), ("exceptions", wrong as f64)],
        policy::claim(wrong == 0 && count > 1000, Verdict::DerivationDiffers),
        "",
    )
}

fn curve_ends() -> Claim {
    let mut ratios = Vec::new();
    let mut inner = Vec::new();
    for th in [0.5, 1.0, 2.0] {
        if let Some([(na, sa), (nb, sb)]) = read::stability_limit(th) {
            let (outer, inn) = if na.abs() < nb.abs() { (sa, sb) } else { (sb, sa) };
            ratios.push((outer - 1.0) / th.to_radians().powi(2));
            inner.push(inn);
        }
    }
    let holds = ratios.len() == 3
        && rel_diff(ratios[0], ratios[1]) < 0.02
        && inner[0] < inner[1]
        && inner[0] < 0.05;
    Claim::new(
        "unicycle-s-curve-ends",
        "41",
        "At the origin the curve (S) is tangent to the ray theta = 0; at (theta = 0, s = 1) s - 1 is of the second order, so the curve leaves normally to that ray.",
        "The two points of the limit of stability (generated trinomial and (E)) at theta = 0.5°, 1°, 2°: (s - 1)/theta^2 on the branch through s = 1, and s on the branch through the origin.",
        &[("s_minus_1_over_theta2_0.5deg", ratios.first().copied().unwrap_or(f64::NAN)), ("s_minus_1_over_theta2_1deg", ratios.get(1).copied().unwrap_or(f64::NAN)), ("inner_s_0.5deg", inner.first().copied().unwrap_or(f64::NAN))],
        policy::claim(holds, Verdict::DerivationDiffers),
        "(s - 1)/theta^2 is constant to 2 %: second order, the branch leaves normally to the ray; the other branch tends to s = 0 as theta does, tangent to the ray at the origin.",
    )
}

fn s_misses_e() -> Claim {
    let f = |th: f64| {
        let (n0, s0) = minimum_on_e(th);
        out(&n32(th, s0, n0), "stability_n40")
    };
    let mut changes = Vec::new();
    let pts: Vec<f64> = grid(0.5, 85.0, 339).collect();
    for w in pts.windows(2) {
        if f(w[0]).signum() != f(w[1]).signum() {
            changes.push(bisect(f, w[0], w[1]));
        }
    }
    let holds = changes.len() == 1 && changes[0] > 62.0;
    Claim::new(
        "unicycle-s-curve-misses-e",
        "41",
        "(S) meets (ℰ) only at theta = 63.5°, on the branch left aside: the branch of interest (theta < 16°) does not touch (ℰ).",
        "The sign of the generated (S) of n° 40 at the points of (ℰ) (smallest s on the generated (E)) at 339 leans 0.5°–85°; each sign change bisected.",
        &[("contacts", changes.len() as f64), ("contact_deg", changes.first().copied().unwrap_or(f64::NAN))],
        policy::claim(holds, Verdict::DerivationDiffers),
        "One contact, at 63.43° (printed 63.5°), beyond the second zero of n° 41: none on the branch below 16°.",
    )
}

// n° 42 ------------------------------------------------------------------------------------

fn stable_principle() -> Claim {
    stable_principle_check(1.0)
}

/// The check of [`stable_principle`] with the rider's arm below the axle `arm_sign` (R - h):
/// 1 as the memoir, -1 for the centre of gravity reflected about the axle.
fn stable_principle_check(arm_sign: f64) -> Claim {
    // Wheel hoops of the same linear density as the 5 kg, 0.5 m wheel; rider 60 kg, moment
    // 10 kg m^2 about its centre of gravity, seated centre of gravity 1.10 m above the ground.
    let make = |r: f64, height: f64| {
        let m = 5.0 * r / 0.5;
        let arm = arm_sign * Pitch::arm_for_height(r, height);
        Pitch::new(r, 9.81, m, m * r * r, 60.0, 10.0, arm).ok()
    };
    let mut radii = Vec::new();
    let mut stable = Vec::new();
    for r in [0.5, 0.8, 1.05, 1.15, 1.2, 1.5] {
        let p = make(r, 1.10);
        let w2 = p.map_or(f64::NAN, |p| p.linear_rate_squared());
        radii.push(r);
        stable.push(w2);
    }
    let sim = |r: f64| {
        make(r, 1.10).map_or(f64::NAN, |p| p.simulate([0.0, 0.05, 0.0, 0.0], 1e-3, 10_000).0)
    };
    let (big, small) = (sim(1.2), sim(0.5));
    let sign_ok = radii.iter().zip(&stable).all(|(r, w2)| (*r > 1.10) == (*w2 > 0.0));
    let holds = sign_ok && big < 0.05 + 1e-9 && small > 1.0;
    Claim::new(
        "unicycle-stable-principle",
        "42",
        "The unicycle's worst defect is the instability about the wheel's axle; it is corrected by placing the rider's centre of gravity below the axle, which needs a wheel of radius above the height of a cyclist's centre of gravity (about 1.10 m).",
        "The pitch model of carvallo::unicycle::variants (the memoir replaces this motion by a constraint, n° 20): a hoop wheel (5 kg per 0.5 m of radius) rolling with a 60 kg rider hinged freely on the axle (moment 10 kg m^2 about its centre of gravity, 1.10 m above the ground): the linear rate at radii 0.5–1.5 m, and 10 s of RK4 (dt = 1 ms) from a 0.05 rad pitch at R = 1.2 m and R = 0.5 m.",
        &[("omega2_R0.5", stable[0]), ("omega2_R1.2", stable[4]), ("max_pitch_R1.2", big), ("max_pitch_R0.5", small)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The rider hangs like a pendulum from the axle exactly when R exceeds the height of his centre of gravity: he swings within the initial 0.05 rad at R = 1.2 m and falls over at R = 0.5 m.",
    )
}

fn big_wheel_lean() -> Claim {
    big_wheel_lean_check(HOOP_SPIN)
}

/// The check of [`big_wheel_lean`] with the wheels' moment about their axle `spin` mu1 R^2.
fn big_wheel_lean_check(spin: f64) -> Claim {
    let small = example_spin(0.5, 5.0, 1.25, 0.77, 0.0, spin);
    let big = example_spin(1.2, 12.0, 1.10, 0.77, 0.0, spin);
    let (su, bu) = (threshold_units(&small), threshold_units(&big));
    let (sv, bv) = (threshold_speed(&small), threshold_speed(&big));
    let holds = bv < 0.95 * sv;
    Claim::new(
        "unicycle-big-wheel-lean-stability",
        "42",
        "With the large wheel the cycle gains stability in the direction of the lean theta.",
        "The straight-running threshold of the generated full model (L = 0) for the n° 36 unicycle (R = 0.5 m, 5 kg hoop, rider at h = 1.25 m) and for the large wheel of n° 42 (R = 1.2 m, 12 kg hoop of the same linear density, the rider's centre of gravity 1.10 m high, below the axle), in the memoir's unit sqrt(g/R) and in m/s.",
        &[("small_threshold_units", su), ("big_threshold_units", bu), ("small_threshold_m_per_s", sv), ("big_threshold_m_per_s", bv)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "In the memoir's unit sqrt(g/R) the threshold drops (1.04 to 0.68), but that unit grows with R: the threshold speed is about the same, 2.30 against 2.33 m/s. The large wheel does not make straight running stable at a lower speed; its gain is the slower fall (the time scale sqrt(R/g), n° 18's practical stability), which the memoir's sentence may mean.",
    )
}

// n° 78 ------------------------------------------------------------------------------------

fn product_is_36() -> Claim {
    let mut worst = 0.0f64;
    for base in points(false).iter().take(16) {
        let Some(u) = unicycle_at(base, 0.0) else { continue };
        let Some(th) = u.straight_running_threshold() else { continue };
        let p = with(
            &hoop_wheel(base, base["mu1"]),
            &[("theta", 0.0), ("n", 0.0), ("p", 0.0), ("dp", 0.0), ("dn", 0.0), ("ds", 0.0)],
        );
        let root = bisect(|s| out(&with(&p, &[("s", s)]), "char78_c0"), 0.0, 10.0 * th);
        worst = mx(worst, rel_diff(root, th));
    }
    Claim::new(
        "unicycle-78-product-is-36",
        "78",
        "The first condition (product of the roots positive) is identical to the condition (S) of n° 36.",
        "The root in s of the generated n° 78 product (s held constant, any L) against the full model's straight-running threshold (s free, n° 34–36, L = 0), 16 seeded unicycles with hoop wheels.",
        &[("max_rel_diff", worst)],
        policy::numeric(worst, 1e-9, Verdict::DerivationDiffers),
        "Holding s by the pedals does not move the threshold: both are -(C + C1)(mu h + mu1 R) g + (mu R h + B1)(B1 - mu1 R^2) s^2 = 0 in the full model (the memoir's form with merged letters is the report's n° 78 entry).",
    )
}

fn leading_positive() -> Claim {
    let mut rng = crate::sample::Rng(super::SEED ^ 78);
    let (mut smallest, mut cases, mut largest_l) = (f64::INFINITY, 0, 0.0f64);
    for _ in 0..32 {
        // A rider of 12 point masses, symmetric about the wheel's plane, tilted arbitrarily.
        let (mut mu, mut mz, mut sxx, mut syy, mut szz, mut sxz) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        for _ in 0..6 {
            let m = rng.uniform(1.0, 10.0);
            let (x, y, z) = (rng.uniform(-0.8, 0.8), rng.uniform(0.0, 0.3), rng.uniform(0.2, 1.8));
            for yy in [y, -y] {
                mu += m;
                mz += m * z;
                sxx += m * x * x;
                syy += m * yy * yy;
                szz += m * z * z;
                sxz += m * z * x;
            }
        }
        let p: Point = BTreeMap::from([
            ("R", 0.5),
            ("g", 9.81),
            ("mu", mu),
            ("z", mz / mu),
            ("A", syy + szz),
            ("B", szz + sxx),
            ("C", sxx + syy),
            ("L", sxz),
            ("mu1", 5.0),
            ("A1", 1.875),
            ("B1", 2.5),
            ("C1", 0.625),
            ("theta", rng.uniform(-1.2, 1.2)),
            ("n", rng.uniform(-3.0, 3.0)),
            ("s", rng.uniform(0.0, 10.0)),
            ("p", 0.0),
            ("dp", 0.0),
            ("dn", 0.0),
            ("ds", 0.0),
        ]);
        let c2 = out(&p, "char78_c2");
        smallest = smallest.min(c2 / ((p["A"] + 1.875) * (p["C"] + 0.625)));
        largest_l = mx(largest_l, sxz.abs() / (syy + szz));
        cases += 1;
    }
    Claim::new(
        "unicycle-78-leading-positive",
        "78",
        "The coefficient of lambda^2, A(C cos^2 + B sin^2) - L^2 cos^2, is positive because L is small before A and C.",
        "The generated n° 78 lambda^2 coefficient (full model) for 32 seeded riders of 12 point masses symmetric about the wheel's plane (A, B, C, L, z from the sums of n° 21), at seeded steady states, relative to (A + A1)(C + C1).",
        &[("riders", cases as f64), ("min_rel_coefficient", smallest), ("max_L_over_A", largest_l)],
        policy::claim(smallest > 0.0, Verdict::DerivationDiffers),
        "Positive for every rider, with L up to a sizeable fraction of A: L^2 <= (sum m zeta^2)(sum m xi^2) <= A C (Cauchy–Schwarz), so the smallness of L is not needed.",
    )
}

/// The n° 36 example's generated n° 78 coefficients (c2, c1, c0) at the rolling rate `s`.
fn char78(l: f64, s: f64) -> (f64, f64, f64) {
    let p: Point = BTreeMap::from([
        ("R", 0.5),
        ("g", 9.81),
        ("mu", 60.0),
        ("z", 1.25),
        ("A", 100.0),
        ("B", 100.0),
        ("C", 0.77),
        ("L", l),
        ("mu1", 5.0),
        ("A1", 1.875),
        ("B1", 2.5),
        ("C1", 0.625),
        ("theta", 0.0),
        ("n", 0.0),
        ("s", s),
        ("p", 0.0),
        ("dp", 0.0),
        ("dn", 0.0),
        ("ds", 0.0),
    ]);
    let v = eval(&p);
    (v["char78_c2"], v["char78_c1"], v["char78_c0"])
}

/// Growth of the amplitude over one period of the roots alpha ± i omega of c2 x^2 + c1 x + c0.
fn growth_per_period(l: f64, s: f64) -> f64 {
    let (c2, c1, c0) = char78(l, s);
    let alpha = -c1 / (2.0 * c2);
    let omega = (c0 / c2 - alpha * alpha).sqrt();
    (2.0 * PI * alpha / omega).exp()
}

fn l_sign() -> Claim {
    l_sign_check(1.0)
}

/// The check of [`l_sign`] with the rider's product of inertia entered as `l_sign` L in the
/// simulated equations and in the generated n° 78 coefficients (1 as derived, -1 flipped).
fn l_sign_check(l_sign: f64) -> Claim {
    let mut envelopes = BTreeMap::new();
    let threshold = example(0.5, 5.0, 1.25, 0.77, 0.0)
        .and_then(|u| u.straight_running_threshold())
        .unwrap_or(f64::NAN);
    let s = 2.0 * threshold;
    for l in [-0.2, 0.0, 0.2] {
        let Some(u) = example(0.5, 5.0, 1.25, 0.77, l_sign * l) else { continue };
        let leans = u.simulate_constant_speed([0.01, 0.0, 0.0], s, 2e-3, 5000);
        let half = leans.len() / 2;
        let first = leans[..half].iter().fold(0.0f64, |a, &b| a.max(b.abs()));
        let second = leans[half..].iter().fold(0.0f64, |a, &b| a.max(b.abs()));
        envelopes.insert(
            if l < 0.0 {
                "neg"
            } else if l > 0.0 {
                "pos"
            } else {
                "zero"
            },
            second / first,
        );
    }
    let mut oscillating = true;
    for l in [-0.5, 0.05, 0.5] {
        let (c2, c1, c0) = char78(l_sign * l, s);
        oscillating &= c1 * c1 - 4.0 * c2 * c0 < 0.0;
    }
    let (small, large) = (growth_per_period(l_sign * 0.05, s), growth_per_period(l_sign * 0.5, s));
    let get = |k: &str| envelopes.get(k).copied().unwrap_or(f64::NAN);
    let holds = get("pos") > 1.01
        && get("neg") < 0.99
        && (get("zero") - 1.0).abs() < 0.02
        && oscillating
        && small < 1.1;
    Claim::new(
        "unicycle-78-l-sign",
        "78",
        "The second condition L <= 0 is new: stability depends on the rider's position; if L > 0 the cycle is unstable, but weakly since L stays small, and for large s the perturbation oscillates with an amplitude growing slowly.",
        "RK4 (dt = 2 ms, 10 s) of the (p) and (n) equations with s held constant by the pedals (carvallo::unicycle::variants, from the generated sums), n° 36 example at twice its threshold, from theta = 0.01 rad, for L = -0.2, 0, 0.2 kg m^2: the largest lean of the second 5 s over that of the first; the discriminant of the generated (1)' for L = -0.5, 0.05, 0.5; the growth of the amplitude per period from its roots for L = 0.05 and 0.5 kg m^2.",
        &[("envelope_ratio_L_neg", get("neg")), ("envelope_ratio_L_0", get("zero")), ("envelope_ratio_L_pos", get("pos")), ("oscillating", if oscillating { 1.0 } else { 0.0 }), ("growth_per_period_L0.05", small), ("growth_per_period_L0.5", large)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The sign of L decides (s > 0): L > 0 makes the oscillation grow, L < 0 damps it, L = 0 keeps it. « Weak » holds while L is a few hundredths of kg m^2 (growth per swing in the evidence); at L = 0.5 kg m^2 the amplitude already more than doubles per swing.",
    )
}

fn big_wheel_remark() -> Claim {
    // Growth rate Re(lambda) = -c1/(2 c2) at twice the threshold, L = 0.5, per second.
    let growth = |r: f64, m1: f64, h: f64| {
        let u = example(r, m1, h, 0.77, 0.5);
        let th = u.and_then(|u| u.straight_running_threshold()).unwrap_or(f64::NAN);
        let m = m1 * r * r;
        let p: Point = BTreeMap::from([
            ("R", r),
            ("g", 9.81),
            ("mu", 60.0),
            ("z", h),
            ("A", 100.0),
            ("B", 100.0),
            ("C", 0.77),
            ("L", 0.5),
            ("mu1", m1),
            ("A1", 1.5 * m),
            ("B1", 2.0 * m),
            ("C1", 0.5 * m),
            ("theta", 0.0),
            ("n", 0.0),
            ("s", 2.0 * th),
            ("p", 0.0),
            ("dp", 0.0),
            ("dn", 0.0),
            ("ds", 0.0),
        ]);
        let v = eval(&p);
        (-v["char78_c1"] / (2.0 * v["char78_c2"]), m1 * r - 60.0 * h)
    };
    let (g_small, f_small) = growth(0.5, 5.0, 1.25);
    let (g_big, f_big) = growth(1.2, 12.0, 1.10);
    let holds = g_big < g_small;
    Claim::new(
        "unicycle-78-big-wheel-remark",
        "78",
        "The instability, when it exists, decreases with the factor mu1 R - mu h, a circumstance favourable to the large unicycle of n° 42.",
        "The growth rate -c1/(2 c2) (1/s) of the generated n° 78 characteristic equation (full model, L = 0.5 kg m^2, twice the straight-running threshold) for the n° 36 unicycle and the n° 42 large wheel (R = 1.2 m, 12 kg hoop, rider at 1.10 m), beside the memoir's factor mu1 R - mu h.",
        &[("growth_small", g_small), ("growth_big", g_big), ("factor_small", f_small), ("factor_big", f_big)],
        policy::claim(holds, Verdict::DerivationDiffers),
        "The large wheel's instability grows eight times slower, so the remark holds in the full model, but not through the printed factor, which comes from the merged letters (the report's n° 78 entries): the full model's sum is -L s (mu R h + mu1 R^2), larger for the large wheel; the growth rate L s (mu R h + mu1 R^2) / (2 c2) falls because the large wheel's moments (A1, and C1 = 8.6 kg m^2 against the rider's 0.77) enlarge c2 and its threshold rate s is lower.",
    )
}

/// The unicycle's claims, n° by n°.
/// The first constant of the generated stability first member of n° 34 (`stability`) scaled
/// by 1 + 1e-3.
const STABILITY_SCALED: crate::perturb::Perturbation = crate::perturb::Perturbation {
    model: "unicycle",
    output: "stability",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};
/// The rider's height z in the generated (S) of n° 40 (`stability_n40`) scaled by 1 + 1e-2
/// (the terms (h/R) n^2 and (h/R) cos^2 s n sin moved, in that output only). Not a constant
/// of it: the lowering's Horner scheme factors (S) so that its only constant is the 1 of
/// 1 + (h/R) cos^2, which moves neither this check nor that of (S) meeting (E) at 1e-3.
const S40_SCALED: crate::perturb::Perturbation = crate::perturb::Perturbation {
    model: "unicycle",
    output: "stability_n40",
    target: crate::perturb::Target::Argument("z"),
    factor: 1.0 + 1e-2,
};

/// Every use of the named argument in one output of the generated `unicycle` program scaled
/// by `factor` (a model ingredient changed in that output only).
const fn scaled(output: &'static str, argument: &'static str, factor: f64) -> Perturbation {
    Perturbation { model: "unicycle", output, target: Target::Argument(argument), factor }
}

/// The rider's height z in the generated (S) of n° 40 scaled by 0.9 (h/R from 2.5 to 2.25 in
/// that output only): (S) then meets (E) at 8.7°, on the branch of interest.
const S40_Z_LOWER: Perturbation = scaled("stability_n40", "z", 0.9);
/// The rider's height z in the generated (E) of n° 29 scaled by 1 + 1e-2.
const E_Z: Perturbation = scaled("equilibrium", "z", 1.0 + 1e-2);
/// The rolling rate s in the generated (E) of n° 29 negated (its rolling terms turned against
/// the lean).
const E_S_FLIPPED: Perturbation = scaled("equilibrium", "s", -1.0);
/// The rider's height z in the generated skid D of n° 30 scaled by 1 + 1e-2.
const SKID_Z: Perturbation = scaled("skid", "z", 1.0 + 1e-2);
/// The fall acceleration p' in the generated full skid D of n° 31 scaled by 1 - 1e-2.
const SKID_FULL_DP: Perturbation = scaled("skid_full", "dp", 1.0 - 1e-2);
/// The rider's height z in the generated normalised (E) of n° 32 scaled by 1 + 1e-2.
const E32_Z: Perturbation = scaled("equilibrium_n32", "z", 1.0 + 1e-2);
/// The rider's height z in the generated trinomial S(n^2) of n° 41 scaled by 1.8 (h/R from 2.5
/// to 4.5 in that output only).
const TRINOMIAL_Z: Perturbation = scaled("trinomial_n41", "z", 1.8);
/// The rolling rate s in the generated normalised (E) of n° 32 negated: the steady states,
/// and the limit of stability drawn on them, on the side s < 0 (the branch of (S) through
/// s = -1 instead of s = 1).
const E32_S_FLIPPED: Perturbation = scaled("equilibrium_n32", "s", -1.0);
/// The rider's height z in the generated normalised D of n° 32 scaled by 1 + 1e-2.
const SKID32_Z: Perturbation = scaled("skid_n32", "z", 1.0 + 1e-2);
/// The rider's product of inertia L in the generated rider's share of the p equation (n° 33)
/// scaled by 1 + 1e-2.
const RIDER_P_L: Perturbation = scaled("rider_p", "L", 1.0 + 1e-2);
/// The rider's height z in the generated constant term of n° 78's characteristic equation
/// scaled by 1 + 1e-2.
const CHAR78_C0_Z: Perturbation = scaled("char78_c0", "z", 1.0 + 1e-2);

/// The first constant of the generated (S) of n° 40 (`stability_n40`) scaled by 1 + 1e-2.
const S40_SCALED_1E2: Perturbation = Perturbation {
    model: "unicycle",
    output: "stability_n40",
    target: Target::Constant(0),
    factor: 1.0 + 1e-2,
};

/// The rider's height z in the generated light-rider (S) of n° 39 scaled by 1.5.
const S39_Z: Perturbation = scaled("stability_n39", "z", 1.5);
/// The turning rate n in the generated light-rider (S) of n° 39 negated.
const S39_N_FLIPPED: Perturbation = scaled("stability_n39", "n", -1.0);
/// The rider's moment A in the generated leading coefficient of n° 78 negated.
const CHAR78_C2_A_FLIPPED: Perturbation = scaled("char78_c2", "A", -1.0);
/// The rider's product of inertia L in the generated middle coefficient of n° 78 negated.
const CHAR78_C1_L_FLIPPED: Perturbation = scaled("char78_c1", "L", -1.0);

/// The weight g in the generated complete skid D of n° 30 (`skid_full`) negated: its
/// denominator g - (p' z sin + p^2 z cos) becomes -g - (…), the sign the memoir's misprint
/// gives the p^2 term relative to g.
const SKID_FULL_G_FLIPPED: Perturbation = scaled("skid_full", "g", -1.0);
/// The wheel's moment about its axle B1 in the generated stability first member of the full
/// model (`stability`) doubled.
const STABILITY_B1_DOUBLED: Perturbation = scaled("stability", "B1", 2.0);
/// The weight g in the hoop's generated (S) of n° 9 (`stability` of generated/hoop.ir)
/// doubled: its weight term -2/3 g cos/R becomes -4/3 g cos/R.
const HOOP_S_G_DOUBLED: Perturbation =
    Perturbation { model: "hoop", output: "stability", target: Target::Argument("g"), factor: 2.0 };

/// The wheel's moment about its axle twice the hoop's: B1 = 4 mu1 R^2 (a perturbation of the
/// wheel's spin, its other moments kept).
const DOUBLE_SPIN: f64 = 4.0;

/// The memoir's claims of the unicycle, with the falsification of those that a perturbation
/// of the generated `unicycle` program breaks ([`crate::perturb::falsify`]).
pub fn claims() -> Vec<Claim> {
    let table: [crate::perturb::Row; 21] = [
        (
            &SKID_FULL_G_FLIPPED,
            || {
                let (a, b) = abrupt_turn();
                vec![a, b]
            },
            &["unicycle-abrupt-turn-increase"],
        ),
        (
            &STABILITY_B1_DOUBLED,
            || vec![stability_from_spin()],
            &["unicycle-stability-from-wheel-spin"],
        ),
        (&HOOP_S_G_DOUBLED, || vec![light_rider_hoop()], &["unicycle-light-rider-hoop-limit"]),
        (
            &TRINOMIAL_Z,
            || vec![bracket_positive(), stability_circle()],
            &["unicycle-bracket-positive", "unicycle-stability-circle"],
        ),
        (&E32_S_FLIPPED, || vec![curve_ends()], &["unicycle-s-curve-ends"]),
        (&S40_SCALED_1E2, || vec![stable_between_roots()], &["unicycle-stable-between-roots"]),
        (&S39_Z, || vec![light_only_turning()], &["unicycle-light-stable-only-turning"]),
        (&S39_N_FLIPPED, || vec![light_turning_radius()], &["unicycle-light-turning-radius"]),
        (&CHAR78_C2_A_FLIPPED, || vec![leading_positive()], &["unicycle-78-leading-positive"]),
        (&CHAR78_C1_L_FLIPPED, || vec![big_wheel_remark()], &["unicycle-78-big-wheel-remark"]),
        (&E_Z, || vec![straight_running_steady()], &["unicycle-straight-running-steady"]),
        (&E_S_FLIPPED, || vec![turns_toward_lean()], &["unicycle-turns-toward-lean"]),
        (&SKID_Z, || vec![skid_reduces_to_hoop()], &["unicycle-skid-reduces-to-hoop"]),
        (
            &SKID_FULL_DP,
            || {
                let (a, b) = abrupt_turn();
                vec![a, b]
            },
            &["unicycle-abrupt-turn-pprime-larger"],
        ),
        (
            &E32_Z,
            || vec![regions(), light_root_n1(), separation_curve()],
            &[
                "unicycle-walking-pivoting-regions",
                "unicycle-light-stable-root-n1",
                "unicycle-separation-curve",
            ],
        ),
        (&SKID32_Z, || vec![skid_is_tan_on_e()], &["unicycle-skid-is-tan-on-e"]),
        (&RIDER_P_L, || vec![l_terms_vanish()], &["unicycle-l-terms-vanish-at-steady"]),
        (
            &CHAR78_C0_Z,
            || vec![threshold_independent(), product_is_36()],
            &["unicycle-straight-threshold-independent", "unicycle-78-product-is-36"],
        ),
        (&STABILITY_SCALED, || vec![stability_recipe()], &["unicycle-stability-recipe"]),
        (&S40_SCALED, || vec![small_lean()], &["unicycle-small-lean-outside-interval"]),
        (&S40_Z_LOWER, || vec![s_misses_e()], &["unicycle-s-curve-misses-e"]),
    ];
    const FLAT: &str = "the wheel's moment about its axle B1 = mu1 R^2 instead of the hoop's 2 mu1 R^2 (its spin carrying no moment of momentum beyond its rolling translation's), the n° 36 unicycle otherwise";
    crate::perturb::falsify(claims_as_derived(), &table)
        .into_iter()
        .map(|c| match c.id.as_str() {
            "unicycle-light-wheel-unstable" => c.falsified_by(FLAT, light_wheel_check(FLAT_SPIN)),
            "unicycle-fall-turns-toward-lean" => c.falsified_by(
                "the wheel's moment about its axle B1 = mu1 R^2 instead of the hoop's 2 mu1 R^2 (its spin carrying no moment of momentum beyond its rolling translation's), the 16 seeded unicycles otherwise",
                fall_turns_check(FLAT_SPIN),
            ),
            "unicycle-stability-decreases-with-wheel" => {
                c.falsified_by(FLAT, stability_decreases_check(FLAT_SPIN))
            }
            "unicycle-78-l-sign" => c.falsified_by(
                "the rider's product of inertia L entered with its sign flipped (L -> -L) in the simulated (p), (n) equations with s held constant and in the generated n° 78 coefficients, the n° 36 example otherwise",
                l_sign_check(-1.0),
            ),
            "unicycle-stable-principle" => c.falsified_by(
                "the rider's centre of gravity reflected about the axle in the pitch model (arm h - R above it instead of R - h below it), the wheels and rider otherwise as the check's",
                stable_principle_check(-1.0),
            ),
            "unicycle-big-wheel-lean-stability" => c.falsified_by(
                "both wheels' moment about their axle twice the hoop's, B1 = 4 mu1 R^2 instead of 2 mu1 R^2 (their other moments kept), the two unicycles otherwise as the check's",
                big_wheel_lean_check(DOUBLE_SPIN),
            ),
            "unicycle-straight-running-oscillates" => {
                c.falsified_by(FLAT, straight_oscillates_check(FLAT_SPIN))
            }
            "unicycle-e-larger-than-c" => c.falsified_by(FAT_RIDER, e_larger_than_c_for(3.0)),
            "unicycle-wheel-small-against-rider" => c.falsified_by(
                "the hoop wheel of 50 kg instead of 5 (R = 0.5 m kept, A1 = 3/2 mu1 R^2 tenfold)",
                wheel_small_for(50.0),
            ),
            "unicycle-slope-sign" => c.falsified_by(
                "the weight reversed, g = -9.81 m/s^2 instead of 9.81 in the generalised force of gravity",
                slope_moment_for(-9.81, false).1,
            ),
            "unicycle-slope-moment" => c.falsified_by(
                "the cycle advanced horizontally by R ds and raised onto the slope (a rise R ds tan(i), n° 25's reading) instead of rolling R ds along it",
                slope_moment_for(9.81, true).0,
            ),
            "unicycle-e-zero-not-in-s" => c.falsified_by(FAT_RIDER, e_zero_not_in_s_for(3.0)),
            "unicycle-practical-region" => c.falsified_by(
                "the rider's shape of n° 39 with E = B - C - mu h^2 = -mu h^2/2 instead of 0 (B - C = mu h^2/2: his moment C about the vertical 0.6 mu h^2, above the one about the lateral axis through his centre, as with a long balancing pole held across the wheel's plane) in (E) of n° 29 and in the stability of the simplified model of n° 33 (n° 40's wheel, mu1 R^2 = C, B1 = 2 mu1 R^2, kept), the rest of the normalised model of n° 32–40 otherwise",
                practical_region_check(SHAPE_POLE),
            ),
            "unicycle-pedal-paradox" => c.falsified_by(
                "the cranks twice as long (0.1 R to 1.9 R: the lowest pedal below the ground line for cranks beyond R)",
                pedal_paradox_check(2.0),
            ),
            "unicycle-string-neutral-angle" => c.falsified_by(
                "the pulley S under the rear axle held fixed on the ground instead of carried by the frame",
                string_angle_check(false),
            ),
            _ => c,
        })
        .collect()
}

/// The claims as derived.
fn claims_as_derived() -> Vec<Claim> {
    let (slope, slope_sign) = slope_moment();
    let (increase, larger) = abrupt_turn();
    vec![
        unmounted_is_hoop(),
        weight_work(),
        wheel_small(),
        steady_needs_no_motor(),
        slope,
        slope_sign,
        pedal_paradox(),
        string_angle(),
        velocipede_paradox(),
        interior_force(),
        steady_n_identity(),
        equilibrium_hoop_form(),
        skid_reduces_to_hoop(),
        increase,
        larger,
        turns_toward_lean(),
        skid_is_tan_on_e(),
        separation_curve(),
        n_touches_e(),
        regions(),
        stability_circle(),
        practical_region(),
        l_terms_vanish(),
        solved_form(),
        stability_recipe(),
        stability_biquadratic(),
        straight_running_steady(),
        light_rider_hoop(),
        light_wheel(),
        stability_decreases(),
        stability_from_spin(),
        fall_turns_toward_lean(),
        accelerating_couple(),
        three_accelerations(),
        straight_oscillates(),
        light_only_turning(),
        light_root_n1(),
        light_turning_radius(),
        e_larger_than_c(),
        e_zero_not_in_s(),
        threshold_independent(),
        bracket_positive(),
        stable_between_roots(),
        small_lean(),
        curve_ends(),
        s_misses_e(),
        stable_principle(),
        big_wheel_lean(),
        product_is_36(),
        leading_positive(),
        l_sign(),
        big_wheel_remark(),
    ]
}

use Status::{Checked, Left, Value};

const fn a(section: &'static str, says: &'static str, status: Status) -> Assertion {
    Assertion { section, says, status }
}

/// Every assertion of n° 20–42, and the unicycle's part of n° 74 and n° 78.
pub const INVENTORY: &[Assertion] = &[
    a("20", "the unmounted unicycle is a hoop, its theory the same", Checked("unicycle-unmounted-is-hoop")),
    a("20", "the pedal cranks change the moments of inertia of n° 4", Left("the cranks and pedals are not modelled (they would change A1, B1, C1 only)")),
    a("20", "the rider's fore-aft balance about the axle is out of reach; replaced by a constraint holding his centre of gravity on the wheel's steepest line", Left("a modelling hypothesis; the motion it removes is studied in n° 42 (claim unicycle-stable-principle)")),
    a("20", "the rider is treated as a rigid body", Left("a modelling hypothesis (the legs' motion is left out)")),
    a("21", "the zero sums express the symmetry about the mid-plane; sum m xi = 0 the rider's balance about the axle", Left("definitions of the rider's constants")),
    a("22", "three degrees of freedom; dPhi carries the rider with the wheel, j ds only translates him with the wheel's centre", Left("the kinematic hypothesis of the model (its equations are the entries of n° 23–24)")),
    a("22", "the work of gravity is (mu z + mu1 R) g sin(theta) dp", Checked("unicycle-weight-work")),
    a("23", "in the third bracket (s) only the I component of M'' counts", Value("rider [j sum m (S-O) M'']")),
    a("24", "the terms of (2) and (3) in the same columns are like terms that add", Value("equation (p), letters merged")),
    a("24", "the wheel's mass and A1 are small before the rider's; A varies between riders by more than A1", Checked("unicycle-wheel-small-against-rider")),
    a("25", "the (s) equation is dominated by the motor moment; its interest is the effort to supply", Left("an appreciation, not a checkable statement")),
    a("25", "in a steady state (s) gives M = 0, as the vis viva theorem says", Checked("unicycle-steady-needs-no-motor")),
    a("25", "on a slope the motor moment is M = mu g R tan(i)", Checked("unicycle-slope-moment")),
    a("25", "M has the sign of i: push uphill, hold back downhill", Checked("unicycle-slope-sign")),
    a("25", "out of steady state the first term mu R^2 s' far outweighs the other two of (s)", Left("a magnitude statement about a pedal-driven motion; the model has no motor moment, and in free motion the first term equals minus the others")),
    a("25", "-mu R^2 s' is the work of the cycle's inertia; the other two terms are of theoretical interest only", Left("an interpretation of the terms")),
    a("26", "pulling the lowest pedal backwards makes the cycle go backwards", Checked("unicycle-pedal-paradox")),
    a("26", "the same holds for every velocipede, the transmission hiding the reason", Checked("unicycle-velocipede-paradox")),
    a("26 bis", "string under the rear axle: backward pull recedes, forward or upward pull advances, a neutral inclination sin S = (m/M) sin(P, I), a constant of the machine", Checked("unicycle-string-neutral-angle")),
    a("26 bis", "an interior force on the pedal (from the rider) makes the cycle advance", Checked("unicycle-interior-force-advances")),
    a("27", "a windmill ship can sail against the wind only if the wind's work is positive in forward motion; its power decreases with its speed", Left("a ship and a windmill: outside the models of this workspace")),
    a("27", "a water wheel with a pinion on a rack climbs the river and can tow a barge", Left("outside the models of this workspace")),
    a("28", "a ratchet for the rising foot, the gear ratio (Chauveau), the useless part of a vertical pedal force near the top, adjustable cranks", Left("engineering and physiological advice outside the unicycle model")),
    a("29", "in a steady state (n) reduces to an identity", Checked("unicycle-steady-n-identity")),
    a("29", "(s) reduces to M = 0: the motor balances the passive resistances", Value("unicycle check steady_identities")),
    a("29", "(E) has the same form as the hoop's", Checked("unicycle-equilibrium-hoop-form")),
    a("29", "(E) can also be found geometrically by the method of n° 11", Left("a second route announced, not carried out for the unicycle; (E) itself is the entry of n° 29")),
    a("30", "the inertia's resultant of translation is that of the total centre of gravity, moving with the frame of n° 22", Value("D complete")),
    a("30", "with z = R the steady D is the hoop's of n° 10", Checked("unicycle-skid-reduces-to-hoop")),
    a("31", "D is increased by -z p' cos (numerator) and +z p^2 cos (denominator); the relative increase formula", Checked("unicycle-abrupt-turn-increase")),
    a("31", "the p^2 term reaches 0.1 for p = 1 at z cos = 0.98 m", Value("relative increase of D")),
    a("31", "the p' term is notably larger, its denominator a fraction of g below the friction coefficient", Checked("unicycle-abrupt-turn-pprime-larger")),
    a("31", "these terms matter at the entry of abrupt turns on tracks", Left("a practical consequence without a quantity to check beyond the two terms")),
    a("32", "(E) and (D) have the hoop's form and the same discussion", Value("unicycle check equilibrium_n32_memoir")),
    a("32", "both roots n have the sign opposite to theta: the cycle turns toward the side it leans", Checked("unicycle-turns-toward-lean")),
    a("32", "B - C = mu z^2 is approximately true in general", Left("depends on the rider's shape, which the memoir does not give; with its own cylinder rider of n° 36 B - C exceeds mu h^2 by E (claim unicycle-e-larger-than-c)")),
    a("32", "on (E) D reduces to + tan(theta)", Checked("unicycle-skid-is-tan-on-e")),
    a("32", "the minimum of s at a given theta: n0 = -sqrt(1/(2.5 cos)), s0 = (2/n0) tan", Value("s0 of (E), formula")),
    a("32", "the separation (N): n = -s in (E), s^2 = tan / (1 - 2.5 sin)", Checked("unicycle-separation-curve")),
    a("32", "(N) has the asymptote theta = arcsin(1/2.5) = 23.6°", Value("asymptote of (N)")),
    a("32", "(N) touches (ℰ) at I where s0 = -n0", Checked("unicycle-n-touches-e")),
    a("32", "the regions: n2 walks and n1 pivots between Oz and (N); both pivot in the lune O-I, both walk beyond I; nothing under (ℰ)", Checked("unicycle-walking-pivoting-regions")),
    a("32", "with a friction coefficient tan 23.6° = 0.437 skidding stops the diagram at the asymptote of (N)", Value("friction coefficient tan 23.6°")),
    a("32", "speed limit 20 km/h, s = 2.58 in the unit sqrt(g/R)", Value("limit radius s / sqrt(g/R)")),
    a("32", "that length is about the one kept on the asymptote in the figure", Left("about the drawing of figure 7")),
    a("32", "the stability limit is practically the circle s = 1", Checked("unicycle-stability-circle")),
    a("32", "the rider may use unstable equilibria below s = 1, especially on a large cycle: falls more dangerous but less frequent", Left("riding skill and practical stability (n° 18); not a property of the model's steady states")),
    a("32", "only n2 is suitable, between the rays 0° and 23.6° and the circles 1 and 2.6", Checked("unicycle-practical-region")),
    a("33", "the variables multiplied by L vanish in steady states", Checked("unicycle-l-terms-vanish-at-steady")),
    a("33", "L is small before A, the rider's principal axes being near the horizontal and vertical", Left("needs a body model of the rider's inertia; n° 78 shows the smallness is not needed for the lambda^2 coefficient (claim unicycle-78-leading-positive)")),
    a("33", "the change of L with body motions may be as large as L", Left("the rider's deformations are outside the model")),
    a("34", "solved, the equations have the form p' = f, n' = p g, s' = p h of n° 8–9", Checked("unicycle-solved-form")),
    a("34", "the stability condition is 0 < -p''/p with the recipe of n° 9", Checked("unicycle-stability-recipe")),
    a("34", "the method applies too when s is held constant by the pedals (n° 78)", Left("announced for n° 78, where it is done by the determinant of n° 76 (claims of n° 78)")),
    a("35", "(S) is a n^2 + b n + c s^2 + d > 0 and with (E) a biquadratic inequality in n", Checked("unicycle-stability-biquadratic")),
    a("35", "plan: straight running, the hoop against the infinitely light unicycle, an intermediate case", Left("the plan of the discussion")),
    a("36", "straight running: (E) gives theta = 0 and any s", Checked("unicycle-straight-running-steady")),
    a("36", "the stability condition 0 < -mu0 g z + mu1 R z (B1 - mu1 R^2)/C s^2", Value("first member (S): s^2 over constant term")),
    a("36", "replacing B1 - mu1 R^2 by mu1 R^2 for a spoked wheel is harmless since the constants may be changed at will", Left("a choice of constants: exact for the hoop of n° 4, a parameter otherwise")),
    a("36", "(S) s^2 > C/(mu1 R^2)", Value("straight running threshold s, full model")),
    a("36", "an infinitely light rider gives back the hoop's s^2 > 1/2", Checked("unicycle-light-rider-hoop-limit")),
    a("36", "an infinitely light wheel: no finite speed is stable", Checked("unicycle-light-wheel-unstable")),
    a("36", "the example: s > 1.06", Value("straight running threshold s (units sqrt(g/R)), C = 1.40")),
    a("37", "stability decreases indefinitely with the relative importance of the wheel's moment", Checked("unicycle-stability-decreases-with-wheel")),
    a("37", "only compound centrifugal forces stabilise; the rider's are weak in straight running: stability comes from the wheel", Checked("unicycle-stability-from-wheel-spin")),
    a("37", "a fall makes the wheel turn toward its lean (fig. 8), and that turning rights it", Checked("unicycle-fall-turns-toward-lean")),
    a("37", "the rotated velocity of the rim's rear end gives it the acceleration W = Rsp, and with the front end an accelerating couple 2psR² about the vertical", Checked("unicycle-accelerating-couple")),
    a("37", "the fall acceleration is due to gravity alone, the second acceleration is proportional to s, the righting one to s²", Checked("unicycle-three-accelerations")),
    a("37", "when s is large enough the righting wins; the rotations alternate and are periodic", Checked("unicycle-straight-running-oscillates")),
    a("37", "the explanation applies to every fast-spinning solid of revolution; the gyroscopic compass principle", Left("gyroscopes in general: outside the unicycle model")),
    a("37", "compound centrifugal forces are paradoxical by their direction, normal to the effort one expects to supply", Left("a judgement on intuition; the direction it names, normal to the wheel for a rotation about OI, is computed in unicycle-accelerating-couple")),
    a("38", "the compound centrifugal force and Laplace's force; the current a velocity, the field a vortex; the usual induction method hides a sign error", Left("electrodynamics: outside the models of this workspace")),
    a("39", "with E = 0 the condition is (S1) s n sin + (h/R) n^2 - cos > 0", Value("stability_n39")),
    a("39", "the limit is n^2 > 1/((h/R) cos^3 theta)", Value("table n° 39, theta = 10°, |n| limit")),
    a("39", "the limit curve follows (ℰ) closely: practically, stability means the root n1", Checked("unicycle-light-stable-root-n1")),
    a("39", "a light cycle's rider can be stable only while turning", Checked("unicycle-light-stable-only-turning")),
    a("39", "the Nouveau Cirque unicyclist on a light wheel evolved on a small platform, for that reason", Checked("unicycle-light-turning-radius")),
    a("39", "E is usually larger than C; E = 0 is an absurdly fat and short rider", Checked("unicycle-e-larger-than-c")),
    a("39", "E = 0 is acceptable in the coefficient B - C of (E) but not in the same way in the inequality (S), where E stands beside C", Checked("unicycle-e-zero-not-in-s")),
    a("40", "the straight-running result of n° 36 is independent of the simplifying hypotheses", Checked("unicycle-straight-threshold-independent")),
    a("40", "these hypotheses hardly change the practical results", Left("the n° 40 model is generated only for E = 0; the effect of E != 0 on the curve of n° 41 is not computed")),
    a("40", "the condition (S) with B = C + mu h^2, h/R = 2.5, mu1 R^2 = C, B1 = 2 mu1 R^2", Value("stability_n40")),
    a("41", "(E) in (S) gives the trinomial S(n^2)", Value("trinomial_n41")),
    a("41", "the bracket 1/cos - (h/R) sin^2 cos is always positive for h/R = 2.5", Checked("unicycle-bracket-positive")),
    a("41", "the first member vanishes at 16.0° and 62.7°", Value("first zero of the first member")),
    a("41", "between the two zeros every steady state is stable", Checked("unicycle-stable-between-roots")),
    a("41", "beyond 62.7° a branch of no interest, such leans are never reached", Left("a practical remark on large leans")),
    a("41", "below 16° stability needs n outside (-b, -a)", Checked("unicycle-small-lean-outside-interval")),
    a("41", "at theta = 0 the limits s = 0, n^2 > R/h and n = 0, s > 1", Value("theta = 0 limit")),
    a("41", "the branches join on theta = 16.0° at n = -0.425, s = 0.97", Value("junction point n")),
    a("41", "the curve is tangent to the ray 0 at the origin and leaves normally at s = 1", Checked("unicycle-s-curve-ends")),
    a("41", "(S) touches (ℰ) only at 63.5°, the branch of interest does not", Checked("unicycle-s-curve-misses-e")),
    a("41", "practical conclusion: a speed above mu1 R / C (= 1)", Value("conclusion: speed limit")),
    a("42", "the worst defect is the instability about the axle; a centre of gravity below the axle corrects it, with a wheel of radius above 1.10 m", Checked("unicycle-stable-principle")),
    a("42", "the larger wheel also gains stability in the lean theta", Checked("unicycle-big-wheel-lean-stability")),
    a("42", "a single rider would sit in a recess of the wheel; two riders on frames either side of the wheel are more practical", Left("a construction proposal, not a property of a model")),
    a("42", "other unicycles are for professional equilibrists only", Left("an appreciation")),
    a("74", "the rider alone is the infinitely light unicycle; the wheel's work is that of n° 73", Left("the plan of the computation")),
    a("74", "the (nu) and (sigma) equations agree with n° 23 for L = 0: a verification of both methods", Value("unicycle check lagrange_agrees_with_moments")),
    a("78", "with L = 0 the same calculation as the hoop; the new method applies to every case", Value("unicycle check characteristic_78_memoir")),
    a("78", "N has theta' as a factor, so lambda factors out of the characteristic equation", Value("characteristic determinant, second row")),
    a("78", "the lambda^2 coefficient is positive because L is small", Checked("unicycle-78-leading-positive")),
    a("78", "straight running: dN/dp = (B1 - mu1 R^2) s = mu1 R^2 s", Value("dN/dp at theta = 0, n = 0")),
    a("78", "the product condition -C mu g h + mu mu1 R^3 h s^2 > 0", Value("(2) product of the roots")),
    a("78", "the product condition is identical to (S) of n° 36", Checked("unicycle-78-product-is-36")),
    a("78", "the sum condition L R s (mu1 R - mu h) >= 0, i.e. L <= 0", Value("(3) sum of the roots")),
    a("78", "L > 0 is unstable, weakly; for large s the perturbation oscillates and grows slowly", Checked("unicycle-78-l-sign")),
    a("78", "the instability decreases with mu1 R - mu h, favouring the large unicycle of n° 42", Checked("unicycle-78-big-wheel-remark")),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The normalised model of [`practical_region_check`] read from the generated full
    /// program at [`n40_point`], against the memoir's printed closed forms typed here: with
    /// $E = 0$, (E) is n° 32's $\frac hR n^2\sin\theta + sn + \tan\theta$ times
    /// $\mu g h\cos\theta$, D is n° 32's $-ns - \frac hR n^2\sin\theta$ and the simplified
    /// model's K is n° 40's (S) times $\mu R h / A$, whatever the rider's C; with the pole's
    /// shape only the couple $(B - C)n^2\sin\theta\cos\theta$ of (E) changes, to
    /// $\frac12\mu h^2 n^2\sin\theta\cos\theta$. Relative tolerance 1e-12 of the largest term
    /// (the program evaluates in f64; its rounding is a few ulps of the terms).
    #[test]
    fn the_full_program_gives_the_normalised_model() {
        let h = H_OVER_R;
        for (th, s, n) in [(5.0, 1.3, -0.4), (17.0, 1.1, -0.9), (23.0, 2.4, -1.7)] {
            let (sin, cos) = (f64::to_radians(th).sin(), f64::to_radians(th).cos());
            let close = |got: f64, want: f64, terms: &[f64], what: &str| {
                let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
                assert!((got - want).abs() <= 1e-12 * scale, "{what} at {th}°: {got} vs {want}");
            };
            let e32 = [h * n * n * sin, s * n, sin / cos];
            let s40 = [h * n * n, (1.0 + h * cos * cos) * s * n * sin, s * s * cos * cos, -cos];
            for c in [0.3, 1.0, 4.0] {
                let shape = Shape { e: 0.0, c };
                let at = |wheel: f64| n40_point(th, s, n, shape, wheel);
                let e = out(&at(0.0), "equilibrium") / (h * cos);
                close(e, e32.iter().sum(), &e32, "(E)");
                let d = out(&at(0.0), "skid");
                close(d, -n * s - h * n * n * sin, &e32, "D");
                let a = c + h * h;
                let k = out(&at(HOOP_SPIN), "stability_simplified") * a / h;
                close(k, s40.iter().sum(), &s40, "(S)");
            }
            let pole = |wheel: f64| n40_point(th, s, n, SHAPE_POLE, wheel);
            let e = out(&pole(0.0), "equilibrium") / (h * cos);
            let halved = [0.5 * h * n * n * sin, s * n, sin / cos];
            close(e, halved.iter().sum(), &halved, "(E), pole");
        }
    }
}
