//! `carvallo kinematics --theta DEG --gamma DEG [--json]`: the kinematics of the memoir's
//! bicycle (the old model of n° 52) at a lean θ and a handlebar angle γ (memoir n° 59–69,
//! module [`carvallo::bicycle_kinematics`]).
//!
//! It prints the exact contact of n° 43–58 (the frame angle η, the contact parameter ω, the
//! front contact x, y on the ground and the accessory angles α, β), the three relations (δη),
//! (δν), (δσ1) of n° 61 as the coefficients of δσ, δθ, δγ (the numerical solution of the
//! analytic δM = 0), the derivatives (I) of n° 66 with finite differences of the exact η(θ, γ)
//! beside dη/dθ and dη/dγ, the steady rates n/s and σ1′/s of (2), and whether the system of
//! n° 68 (pedals, brake and handlebar held) has rank 2.
//!
//! θ and γ are in degrees with the signs of [`carvallo::bicycle_kinematics`] (passed to it
//! unchanged, in radians). Unknown, repeated or missing arguments, non-numbers, non-finite
//! numbers, |θ| ≥ 90°, a position without a contact solution and a singular displacement
//! system are errors naming the value, exit code 2.

use carvallo::bicycle_kinematics::Kinematics;
use serde_json::json;

use crate::args::lean_deg;

/// Largest |det| / column norms of the n° 68 system still counted as zero (as the report's
/// n° 68 entry).
const RANK_DET_ZERO: f64 = 1e-12;
/// Smallest largest 2×2 minor / column norms counted as non-zero (as the report's entry).
const RANK_MINOR_NONZERO: f64 = 1e-3;

/// `carvallo kinematics`: contact, relations (I) and steady rates (2) (memoir n° 59–69).
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The frame's lean θ (degrees), strictly between -90 and 90
    #[arg(long = "theta", value_name = "DEG", value_parser = lean_deg, allow_hyphen_values = true)]
    pub theta_deg: f64,
    /// The handlebar angle γ (degrees)
    #[arg(long = "gamma", value_name = "DEG", value_parser = crate::args::ANGLE.parser(), allow_hyphen_values = true)]
    pub gamma_deg: f64,
    /// Print JSON instead of text
    #[arg(long)]
    pub json: bool,
}

/// Runs `carvallo kinematics`: the text to print, or an error naming the bad value.
pub fn run(c: &Args) -> Result<String, String> {
    let k = Kinematics::old_model();
    let (theta, gamma) = (c.theta_deg.to_radians(), c.gamma_deg.to_radians());
    let at = format!("theta `{}` deg, gamma `{}` deg", c.theta_deg, c.gamma_deg);
    let no_contact = |e: carvallo::bicycle_geometry::ContactError| format!("at {at}: {e}");
    let r = k.relations(theta, gamma).map_err(no_contact)?;
    let f = k.geometry().front_wheel(theta, gamma, r.contact.sigma, r.contact.mu);
    // Columns δσ, δθ, δγ of the relations (δη), (δν), (δσ1).
    let mut columns = [[0.0; 3]; 3];
    for (j, column) in columns.iter_mut().enumerate() {
        let mut unit = [0.0; 3];
        unit[j] = 1.0;
        *column = k
            .solve_displacements(theta, gamma, unit)
            .map_err(no_contact)?
            .ok_or(format!("singular displacement system (n° 61) at {at}"))?;
    }
    let rows: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| columns[j][i]));
    let [fd_theta, fd_gamma] = k.eta_partials_fd(theta, gamma).map_err(|e| {
        format!("at {at}: the finite differences of eta leave the contact solutions: {e}")
    })?;
    let (det, minor) = k.fixation_rank(theta, gamma).map_err(no_contact)?;
    let rank_two = det < RANK_DET_ZERO && minor > RANK_MINOR_NONZERO;
    if c.json {
        let out = json!({
            "theta_deg": c.theta_deg,
            "gamma_deg": c.gamma_deg,
            "eta": r.contact.sigma,
            "omega": r.contact.mu,
            "x": f.contact[0],
            "y": f.contact[1],
            "alpha": f.alpha,
            "beta": f.beta,
            "d_eta": rows[0],
            "d_nu": rows[1],
            "d_sigma1": rows[2],
            "d_eta_d_theta": r.d_eta_d_theta,
            "d_eta_d_theta_fd": fd_theta,
            "d_eta_d_gamma": r.d_eta_d_gamma,
            "d_eta_d_gamma_fd": fd_gamma,
            "d_nu_d_theta": r.d_nu_d_theta,
            "d_nu_d_gamma": r.d_nu_d_gamma,
            "steady_n": r.steady_n,
            "steady_sigma1_rate": r.steady_sigma1_rate,
            "fixation_det": det,
            "fixation_minor": minor,
            "fixation_rank_two": rank_two,
        });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    let deg = |x: f64| x.to_degrees();
    let mut s = format!(
        "bicycle of n° 52, lean theta = {} deg, handlebar gamma = {} deg (memoir n° 59-69)\n",
        c.theta_deg, c.gamma_deg
    );
    s.push_str(&format!(
        "contact: eta {} deg, omega {} deg, x {} m, y {} m\n",
        sci(deg(r.contact.sigma)),
        sci(deg(r.contact.mu)),
        sci(f.contact[0]),
        sci(f.contact[1])
    ));
    s.push_str(&format!(
        "angles: alpha {} deg, beta {} deg\n",
        sci(deg(f.alpha)),
        sci(deg(f.beta))
    ));
    s.push_str("relations (n° 61):   dtheta         dgamma         dsigma\n");
    for (name, row) in ["deta   ", "dnu    ", "dsigma1"].iter().zip(rows) {
        s.push_str(&format!("  {name} = {}  {}  {}\n", sci(row[1]), sci(row[2]), sci(row[0])));
    }
    s.push_str(&format!(
        "(I): deta/dtheta {} (finite differences {})\n",
        sci(r.d_eta_d_theta),
        sci(fd_theta)
    ));
    s.push_str(&format!(
        "(I): deta/dgamma {} (finite differences {})\n",
        sci(r.d_eta_d_gamma),
        sci(fd_gamma)
    ));
    s.push_str(&format!(
        "(I): dnu/dtheta {}, dnu/dgamma {}\n",
        sci(r.d_nu_d_theta),
        sci(r.d_nu_d_gamma)
    ));
    s.push_str(&format!("(2): n/s {}, sigma1'/s {}\n", sci(r.steady_n), sci(r.steady_sigma1_rate)));
    s.push_str(&format!(
        "n° 68 system: {} (|det| / norms {} 1e-12, largest 2x2 minor / norms {:.4})\n",
        if rank_two { "rank 2" } else { "not rank 2" },
        if det < RANK_DET_ZERO { "<" } else { ">=" },
        minor
    ));
    Ok(s)
}

/// `x` with seven significant digits and a sign, in scientific notation (`+8.216131e-2`).
fn sci(x: f64) -> String {
    format!("{x:+.6e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["kinematics", "--gamma", "40", "--theta", "20", "--json"]),
            Ok(Args { theta_deg: 20.0, gamma_deg: 40.0, json: true })
        );
        for (a, msg) in [
            (vec!["kinematics", "--gamma", "1"], "--theta <DEG>"),
            (vec!["kinematics", "--theta", "1"], "--gamma <DEG>"),
            (
                vec!["kinematics", "--theta", "-90", "--gamma", "0"],
                "invalid value '-90' for '--theta <DEG>': must lie strictly between -90 and 90 degrees",
            ),
            (vec!["kinematics", "--theta", "nan"], "invalid value 'nan' for '--theta <DEG>': must be finite"),
            (vec!["kinematics", "--theta", "1", "--gamma", "x"], "invalid value 'x' for '--gamma <DEG>'"),
            (vec!["kinematics", "--gamma", "1", "--gamma", "2"], "'--gamma <DEG>' cannot be used multiple times"),
            (vec!["kinematics", "--theta"], "a value is required for '--theta <DEG>'"),
            (vec!["kinematics", "--steer", "5"], "unexpected argument '--steer' found"),
        ] {
            let e = parse::<Args>(&a).unwrap_err();
            assert!(e.contains(msg), "{a:?}: {e}");
        }
    }
}
