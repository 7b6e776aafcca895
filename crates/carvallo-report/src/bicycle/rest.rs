//! The handlebar's rest position at a given lean (memoir n° 67), computed now from
//! [`carvallo::bicycle_rest`]: for the leans of [`LEANS`] the frame's lowest position γ55 (n° 55,
//! the one Carvallo retains when the front wheel's weight is neglected) and the rigorous
//! equilibrium γ67 with it, which he calls "voisine de celle du n° 55, sinon confondue"; the
//! stability of γ67, the instability of the normal position and the limit of small leans.
//!
//! The leans are counted as in the n° 56 entries of the geometry report: the frame leans to the
//! side of positive γ (θ < 0 in the solver's convention), so the angles printed are positive.
//!
//! Verdict policy. The memoir gives no number for γ67; "voisine" is judged on the handlebar
//! angle against the memoir's own scale for a negligible error in γ, the 0°,6 of n° 53 (61°,6
//! against 62°,2, "assez faible pour la question pratique"): a shift up to [`NEGLIGIBLE_DEG`]
//! `agrees`, a larger one is `derivation-differs`, with the frame's rise beside it.

use std::collections::BTreeMap;

use carvallo::bicycle_rest::{RestBicycle, RestConstants, RestError, RestPosition, SECOND_STEP};

use crate::claims::{Assertion, Status};
use crate::entry::{Derived, Entry, Memoir, Verdict};
use crate::policy::{self, rel_diff};

/// The leans tabulated (degrees).
pub const LEANS: [f64; 5] = [5.0, 10.0, 20.0, 30.0, 40.0];

/// The forward distance e (m) of the new bicycle of n° 122, the sensitivity case.
pub const E_122: f64 = 0.35;

/// The largest shift of the handlebar (degrees) that the memoir treats as negligible (n° 53).
pub const NEGLIGIBLE_DEG: f64 = 0.6;

fn deg(x: f64) -> f64 {
    x.to_degrees()
}

/// `below {bound:e}` when `x` is below `bound` (rounding noise, not printed), else `x`.
fn small(x: f64, bound: f64) -> String {
    if x.abs() < bound {
        format!("below {bound:e}")
    } else {
        format!("{x:.1e}")
    }
}

fn failure(quantity: String, why: &str) -> Entry {
    Entry {
        falsification: None,
        section: "67".into(),
        quantity,
        memoir: Memoir::Formula("voisine de celle du n° 55, sinon confondue".into()),
        derived: Derived::Numbers(BTreeMap::new()),
        rel_diff: None,
        verdict: policy::finding(Verdict::DerivationDiffers),
        note: format!("the computation failed: {why}"),
    }
}

/// The numbers of one position: γ55, γ67 and their difference (degrees), the stiffness
/// (J/rad²), the frame's rise and the front centre's drop (mm).
fn numbers(p: &RestPosition) -> BTreeMap<String, f64> {
    BTreeMap::from([
        ("gamma55_deg".to_string(), deg(p.lowest.gamma)),
        ("gamma67_deg".to_string(), deg(p.equilibrium.gamma)),
        ("difference_deg".to_string(), deg(p.difference())),
        ("stiffness_j_per_rad2".to_string(), p.equilibrium.curvature.value),
        ("frame_rise_mm".to_string(), 1e3 * p.frame_rise()),
        (
            "wheel_drop_mm".to_string(),
            1e3 * (p.at_lowest.wheel_height - p.at_equilibrium.wheel_height),
        ),
    ])
}

fn lean_entry(bike: &RestBicycle, td: f64) -> Result<(Entry, f64), String> {
    let theta = -td.to_radians();
    let p = bike.rest_position(theta).map_err(|e| e.to_string())?;
    let slope = bike.slope(theta, p.lowest.gamma).map_err(|e| e.to_string())?;
    let stiff = bike.stiffness(theta, p.lowest.gamma).map_err(|e| e.to_string())?;
    let one_step = deg(-slope.value / stiff.value);
    let lowering =
        bike.state(theta, 0.0).map_err(|e| e.to_string())?.frame_height - p.at_lowest.frame_height;
    let shift = deg(p.difference());
    // The centre of gravity is illustrative: the same with n° 122's e = 0.35 m.
    let forward = RestConstants { forward: E_122, ..*bike.constants() };
    let far = RestBicycle::new(*bike.geometry(), forward)
        .map_err(|e| e.to_string())?
        .rest_position(theta)
        .map_err(|e| e.to_string())?;
    let mut n = numbers(&p);
    n.insert("difference_with_e_0.35_deg".to_string(), deg(far.difference()));
    let entry = Entry {
        falsification: None,
        section: "67".into(),
        quantity: format!("handlebar at rest, theta = {td}°: gamma67 against gamma55 (degrees)"),
        memoir: Memoir::Formula(
            "the frame lowest in its plane (n° 55) without the front wheel's weight; with it 'voisine de celle du n° 55, sinon confondue'".into(),
        ),
        derived: Derived::Numbers(n),
        rel_diff: Some(rel_diff(p.equilibrium.gamma, p.lowest.gamma)),
        verdict: policy::approx(shift.abs(), NEGLIGIBLE_DEG, Verdict::DerivationDiffers),
        note: format!(
            "gamma55: the minimum of the exact sigma(gamma) (M at E, sigma {:.4}° as upright, n° 56); gamma67: the stable zero of dU/dgamma, U = g(mu z_G + mu1 z_C), with n° 117's mu = 70 kg at e = 0.20 m, h = 1 m and mu1 = 5 kg on n° 52's geometry (an illustrative combination), by Newton/bisection on central differences (stiffness error {} J/rad^2); the handlebar turns {shift:.2}° beyond gamma55, against the 0.6° the memoir calls negligible in n° 53, while the frame rises by only {:.3} mm of the {:.2} mm it fell from gamma = 0: 'voisine' holds for the frame's height, not for the handlebar's angle. The frame's height is stationary at gamma55 and the front wheel's is not (dU/dgamma there is the wheel's mu1 g dz_C/dgamma = {:.4} J/rad), so the shift is of the first order in mu1/mu and the frame's flat minimum lets it be large: one Newton step from gamma55 already gives {one_step:.2}°. The centre of gravity is illustrative; with n° 122's e = {E_122} m (a stiffer frame term) the shift is still {:.2}°",
            deg(p.at_lowest.sigma),
            small(p.equilibrium.curvature.error, 1e-3),
            1e3 * p.frame_rise(),
            1e3 * lowering,
            slope.value,
            deg(far.difference()),
        ),
    };
    Ok((entry, slope.value))
}

/// The rest-position entries, computed now, with the falsifications of those that agree: the
/// direction of the shift with the front wheel's mass set to 0 in the derived model (its part
/// of dU/dgamma, which makes the shift, then vanishes), and the stiffnesses with the weight
/// reversed (U changes sign, its minima become maxima).
pub fn entries() -> Vec<Entry> {
    let bike = RestBicycle::memoir();
    let base = entries_of(&bike);
    let Ok(light) = bike.with_wheel_mass(0.0) else { return base };
    let k = *bike.constants();
    let hanging = RestBicycle::new_unchecked(*bike.geometry(), RestConstants { g: -k.g, ..k });
    let reversed = entries_of(&hanging);
    let weight = "the weight reversed in the derived model (g negated: RestBicycle::new_unchecked), the memoir's conclusion kept";
    let rows = [
        (
            "direction of the shift: dU/dgamma at gamma55, the front wheel's part (J/rad)".to_string(),
            entries_of(&light),
            "the front wheel's mass set to 0 in the derived model (RestBicycle::with_wheel_mass), the memoir's reasoning kept".to_string(),
        ),
        (
            "stiffness d2U/dgamma2 at the handlebar's rest position (J/rad^2)".to_string(),
            reversed.clone(),
            weight.to_string(),
        ),
        (
            "stiffness d2U/dgamma2 in the normal position, theta = gamma = 0 (J/rad^2)".to_string(),
            reversed,
            weight.to_string(),
        ),
    ];
    crate::perturb::falsify_by_rerun(base, &rows)
}

/// The entries of [`entries`] for the bicycle `bike`.
fn entries_of(bike: &RestBicycle) -> Vec<Entry> {
    let mut e = Vec::new();
    let mut stiffness = BTreeMap::new();
    let mut wheel_slopes = BTreeMap::new();
    let mut beyond = true;
    for td in LEANS {
        let quantity =
            format!("handlebar at rest, theta = {td}°: gamma67 against gamma55 (degrees)");
        match lean_entry(bike, td) {
            Ok((x, slope)) => {
                if let Derived::Numbers(n) = &x.derived {
                    stiffness.insert(format!("theta_{td}deg"), n["stiffness_j_per_rad2"]);
                    beyond &= n["difference_deg"] > 0.0 && n["wheel_drop_mm"] > 0.0;
                }
                wheel_slopes.insert(format!("theta_{td}deg"), slope);
                e.push(x);
            }
            Err(why) => e.push(failure(quantity, &why)),
        }
    }
    let lowers = wheel_slopes.len() == LEANS.len() && wheel_slopes.values().all(|d| *d < 0.0);
    e.push(Entry {
        falsification: None,
        section: "67".into(),
        quantity: "direction of the shift: dU/dgamma at gamma55, the front wheel's part (J/rad)".into(),
        memoir: Memoir::Formula(
            "from n° 55 a larger gamma lowers the front wheel and raises the frame: a compensation beyond it".into(),
        ),
        derived: Derived::Numbers(wheel_slopes),
        rel_diff: None,
        verdict: policy::claim(lowers && beyond, Verdict::DerivationDiffers),
        note: "the frame's part of dU/dgamma vanishes at gamma55, the front wheel's mu1 g dz_C/dgamma is negative (a larger gamma lowers the wheel), and gamma67 lies beyond gamma55 with the frame higher and the wheel lower, at every lean of the table, as the memoir reasons".into(),
    });
    let all_stable = stiffness.len() == LEANS.len() && stiffness.values().all(|k| *k > 0.0);
    e.push(Entry {
        falsification: None,
        section: "67".into(),
        quantity: "stiffness d2U/dgamma2 at the handlebar's rest position (J/rad^2)".into(),
        memoir: Memoir::Formula("the front wheel 'va prendre une position d'équilibre stable'".into()),
        derived: Derived::Numbers(stiffness),
        rel_diff: None,
        verdict: policy::claim(all_stable, Verdict::DerivationDiffers),
        note: format!("central second differences of U at gamma67 (step {SECOND_STEP:e} rad), one per lean of the table; positive: a minimum of U, stable with the lean held"),
    });
    // The normal position and the limit of small leans.
    let q = "limit theta -> 0 of the handlebar's rest position (degrees)".to_string();
    // The stiffness in the normal position needs no rest position: it is stated whenever it is
    // computed (with the weight reversed, a falsification, no rest position exists).
    let at_zero = bike.stiffness(0.0, 0.0);
    if let Ok(at_zero) = &at_zero {
        e.push(Entry {
            falsification: None,
            section: "67".into(),
            quantity: "stiffness d2U/dgamma2 in the normal position, theta = gamma = 0 (J/rad^2)".into(),
            memoir: Memoir::Formula("the front wheel 'est au départ dans une position d'équilibre instable'".into()),
            derived: Derived::Number(at_zero.value),
            rel_diff: None,
            verdict: policy::claim(at_zero.value < 0.0, Verdict::DerivationDiffers),
            note: format!(
                "dU/dgamma vanishes at gamma = 0 upright by symmetry and U is a maximum there (error {} J/rad^2); leaning, gamma = 0 is no longer an equilibrium and the handlebar falls to the side of the lean",
                small(at_zero.error, 1e-3)
            ),
        });
    }
    let limit = (|| {
        at_zero?;
        let upright = bike.rest_position(0.0)?;
        let slight = bike.rest_position(-1e-2f64.to_radians())?;
        Ok::<_, RestError>((upright, slight))
    })();
    match limit {
        Ok((upright, slight)) => {
            let mut n = BTreeMap::new();
            n.insert("gamma55_upright_deg".to_string(), deg(upright.lowest.gamma));
            n.insert("gamma67_upright_deg".to_string(), deg(upright.equilibrium.gamma));
            n.insert("gamma55_at_0.01deg".to_string(), deg(slight.lowest.gamma));
            n.insert("gamma67_at_0.01deg".to_string(), deg(slight.equilibrium.gamma));
            let shift = deg(upright.difference());
            e.push(Entry {
                falsification: None,
                section: "67".into(),
                quantity: q,
                memoir: Memoir::Formula(
                    "the frame's lowest position of n° 53/55 (gamma = 61°,6), not gamma = 0".into(),
                ),
                derived: Derived::Numbers(n),
                rel_diff: Some(rel_diff(upright.equilibrium.gamma, upright.lowest.gamma)),
                verdict: policy::approx(shift.abs(), NEGLIGIBLE_DEG, Verdict::DerivationDiffers),
                note: format!(
                    "as theta -> 0 the rest position tends to that of the upright frame, not to gamma = 0 (unstable): gamma55 to the exact lowest position of n° 53 ({:.2}°; 61°,6 printed is the n° 53 entry), gamma67 to {:.2}°, {shift:.2}° beyond it; upright, +gamma67 and -gamma67 are equally stable and the lean decides the side",
                    deg(upright.lowest.gamma),
                    deg(upright.equilibrium.gamma)
                ),
            });
        }
        Err(err) => e.push(failure(q, &err.to_string())),
    }
    e
}

/// Front wheel masses (kg) of the claim that the rest position tends to the lowest frame.
pub const WHEEL_MASSES: [f64; 3] = [5.0, 0.5, 0.05];

/// The memoir's claims checked in this report ([`crate::claims`]).
pub fn claims() -> Vec<crate::claims::Claim> {
    use crate::claims::Claim;
    let bike = RestBicycle::memoir();
    let theta = -20f64.to_radians();
    let shifts: Vec<f64> = WHEEL_MASSES
        .iter()
        .map(|&m| {
            bike.with_wheel_mass(m)
                .ok()
                .and_then(|b| b.rest_position(theta).ok())
                .map_or(f64::NAN, |p| p.difference().to_degrees())
        })
        .collect();
    let scaling = shifts[1] / shifts[2];
    let holds = shifts.iter().all(|d| d.is_finite() && *d > 0.0)
        && shifts[2] < 0.1
        && (scaling - 10.0).abs() < 1.0;
    vec![Claim::new(
        "rest-light-front-wheel-rests-at-lowest-frame",
        "67",
        "'Si l'on néglige le poids de la roue directrice devant celui du cadre, la position d'équilibre est celle qui donne au cadre la position la plus basse dans son plan.'",
        "the handlebar's rest position gamma67 (dU/dgamma = 0, stable) against the frame's lowest position gamma55 at theta = 20° (carvallo::bicycle_rest, n° 117's loaded frame on n° 52's geometry) with the front wheel's mass 5, 0.5 and 0.05 kg: the shift must vanish with the wheel's mass. Holds by construction because the potential of n° 67 is g (μ h_frame + μ1 h_wheel) and nothing else: as μ1 → 0 its stationary point in γ is by definition that of h_frame, the frame's lowest position, whatever the geometry, masses or centre of gravity; the check shows the limit is regular (the shift proportional to μ1) on the derived contact geometry, and no perturbation that keeps a potential of that form can break it",
        &[
            ("shift_deg_mu1_5kg", shifts[0]),
            ("shift_deg_mu1_0_5kg", shifts[1]),
            ("shift_deg_mu1_0_05kg", shifts[2]),
            ("shift_ratio_per_decade", scaling),
        ],
        policy::claim(holds, Verdict::DerivationDiffers),
        "holds as a limit: the shift is proportional to the wheel's mass and vanishes with it; with a real wheel (5 kg) it is several degrees because the frame's minimum is flat (entries 'gamma67 against gamma55')",
    )]
}

/// The memoir's assertions in this report's sections, n° by n°, with how each is covered.
pub const INVENTORY: &[crate::claims::Assertion] = &[
    Assertion { section: "67", says: "leaning the frame with the handlebar free, the front wheel starts from an unstable equilibrium", status: Status::Value("stiffness d2U/dgamma2 in the normal position") },
    Assertion { section: "67", says: "it turns about the steering axis to a stable equilibrium", status: Status::Value("stiffness d2U/dgamma2 at the handlebar's rest position") },
    Assertion { section: "67", says: "neglecting the front wheel's weight, the equilibrium is the frame's lowest position in its plane", status: Status::Checked("rest-light-front-wheel-rests-at-lowest-frame") },
    Assertion { section: "67", says: "from there a larger gamma lowers the front wheel and raises the frame", status: Status::Value("direction of the shift") },
    Assertion { section: "67", says: "the equilibrium is close to that of n° 55, if not the same", status: Status::Value("gamma67 against gamma55") },
    Assertion { section: "67", says: "the rigorous solution has no interest for what follows", status: Status::Left("an opinion on the rest of the memoir") },
    Assertion { section: "70", says: "the equations of motion by the methods of the hoop and the unicycle become too long; Lagrange's equations do not apply without modification", status: Status::Left("announces n° 71-72, outside this range (checked there with the symbolic check that the unmodified equations fail)") },
    Assertion { section: "70", says: "the artifice that gave the stability of the first apparatus fails for the bicycle", status: Status::Left("methodological statement, not a result") },
];
