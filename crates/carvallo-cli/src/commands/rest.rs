//! `carvallo rest --theta DEG [--wheel-mass KG] [--json]`: the handlebar's rest position at a
//! lean of θ degrees (memoir n° 67, module [`carvallo::bicycle_rest`], the geometry of n° 52
//! and the masses of n° 117): the frame's lowest position γ55, the equilibrium γ67 with the
//! front wheel's weight, their difference, the stiffness $d^2U/d\gamma^2$ at γ67, the frame's
//! rise and the front centre's drop from γ55 to γ67.
//!
//! The frame leans by θ to the side of positive γ (the convention of the report's n° 56 and
//! n° 67 entries); the handlebar falls to the side of the lean. Unknown, repeated or missing
//! arguments, non-finite numbers, |θ| ≥ 90° and a negative wheel mass are errors naming the
//! value, exit code 2. A lean without a rest position (near 90° the front wheel finds no
//! lowest point on the ground) is a physical outcome, not an error: exit 0 with the status
//! `no rest position` and why (`"status"` and `"reason"` in JSON; `"status": "at rest"`
//! otherwise).

use carvallo::bicycle_rest::RestBicycle;
use serde_json::json;

use crate::args::{finite, lean_deg};

/// `carvallo rest`: the handlebar's rest position at a lean (memoir n° 67).
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The frame's lean θ (degrees), strictly between -90 and 90
    #[arg(long = "theta", value_name = "DEG", value_parser = lean_deg, allow_hyphen_values = true)]
    pub theta_deg: f64,
    /// The front wheel's mass (kg)
    #[arg(long, value_name = "KG", default_value_t = 5.0, value_parser = mass, allow_hyphen_values = true)]
    pub wheel_mass: f64,
    /// Print JSON instead of text
    #[arg(long)]
    pub json: bool,
}

/// A mass in kg: finite, not negative and at most $10^{12}$ kg (the frame's weight, tens of
/// kilograms, keeps four digits beside the wheel's).
fn mass(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    if x < 0.0 {
        return Err("must not be negative".into());
    }
    const WHEEL: crate::args::Range = crate::args::Range {
        lo: 0.0,
        hi: 1e12,
        why: "beyond it the frame's weight is lost in the rounding of the wheel's",
    };
    WHEEL.check(x)
}

/// Runs `carvallo rest`: the text to print, or an error naming the bad value.
pub fn run(c: &Args) -> Result<String, String> {
    let bike = RestBicycle::memoir().with_wheel_mass(c.wheel_mass).map_err(|e| e.to_string())?;
    let p = match bike.rest_position(-c.theta_deg.to_radians()) {
        Ok(p) => p,
        Err(e) => return Ok(no_rest_position(c, &e.to_string())),
    };
    let deg = |x: f64| x.to_degrees();
    let drop = p.at_lowest.wheel_height - p.at_equilibrium.wheel_height;
    if c.json {
        let out = json!({
            "theta_deg": c.theta_deg,
            "wheel_mass": c.wheel_mass,
            "status": "at rest",
            "gamma55_deg": deg(p.lowest.gamma),
            "gamma67_deg": deg(p.equilibrium.gamma),
            "difference_deg": deg(p.difference()),
            "stiffness": p.equilibrium.curvature.value,
            "stiffness_error": p.equilibrium.curvature.error,
            "frame_rise": p.frame_rise(),
            "wheel_drop": drop,
            "sigma55_deg": deg(p.at_lowest.sigma),
            "mu55_deg": deg(p.at_lowest.mu),
        });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    let mut s = format!(
        "handlebar at rest, lean theta = {} deg, front wheel {} kg (memoir n° 67)\n",
        c.theta_deg, c.wheel_mass
    );
    s.push_str(&format!(
        "frame lowest (n° 55): gamma55 = {:.4} deg (sigma {:.4} deg, mu {:.4} deg)\n",
        deg(p.lowest.gamma),
        deg(p.at_lowest.sigma),
        deg(p.at_lowest.mu)
    ));
    s.push_str(&format!("equilibrium: gamma67 = {:.4} deg\n", deg(p.equilibrium.gamma)));
    s.push_str(&format!("difference: {:.4} deg\n", deg(p.difference())));
    s.push_str(&format!(
        "stiffness d2U/dgamma2: {:.4} J/rad^2 (error {:.1e})\n",
        p.equilibrium.curvature.value, p.equilibrium.curvature.error
    ));
    s.push_str(&format!(
        "frame rise: {:.4} mm, front centre drop: {:.4} mm\n",
        1e3 * p.frame_rise(),
        1e3 * drop
    ));
    Ok(s)
}

/// The outcome of a lean without a rest position: the status and `reason`, in text or JSON.
fn no_rest_position(c: &Args, reason: &str) -> String {
    if c.json {
        let out = json!({
            "theta_deg": c.theta_deg,
            "wheel_mass": c.wheel_mass,
            "status": "no rest position",
            "reason": reason,
        });
        return serde_json::to_string_pretty(&out).unwrap_or_default();
    }
    format!(
        "handlebar at rest, lean theta = {} deg, front wheel {} kg (memoir n° 67)
no rest position: {reason}
",
        c.theta_deg, c.wheel_mass
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["rest", "--theta", "20", "--json"]),
            Ok(Args { theta_deg: 20.0, wheel_mass: 5.0, json: true })
        );
        assert_eq!(
            parse::<Args>(&["rest", "--wheel-mass", "0", "--theta", "-5"]),
            Ok(Args { theta_deg: -5.0, wheel_mass: 0.0, json: false })
        );
        for (a, msg) in [
            (vec!["rest"], "required arguments were not provided:\n  --theta <DEG>"),
            (
                vec!["rest", "--theta", "90"],
                "invalid value '90' for '--theta <DEG>': must lie strictly between -90 and 90 degrees",
            ),
            (vec!["rest", "--theta", "nan"], "invalid value 'nan' for '--theta <DEG>': must be finite"),
            (vec!["rest", "--theta", "x"], "invalid value 'x' for '--theta <DEG>': not a number"),
            (
                vec!["rest", "--theta", "5", "--wheel-mass", "-1"],
                "invalid value '-1' for '--wheel-mass <KG>': must not be negative",
            ),
            (vec!["rest", "--theta", "5", "--theta", "6"], "'--theta <DEG>' cannot be used multiple times"),
            (vec!["rest", "--theta"], "a value is required for '--theta <DEG>' but none was supplied"),
            (vec!["rest", "--lean", "5"], "unexpected argument '--lean' found"),
        ] {
            let e = parse::<Args>(&a).unwrap_err();
            assert!(e.contains(msg), "{a:?}: {e}");
        }
    }
}
