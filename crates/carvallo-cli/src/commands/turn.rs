//! `carvallo turn --model carvallo --gamma DEG --speed V [--json]`: a steady turn of
//! Carvallo's bicycle with the handlebar held (memoir n° 99–105, module
//! [`carvallo::bicycle_turn`], the constants of n° 117) and its characteristic equation (C) of
//! n° 101 with the rolling speed held: the lean θ₀, the pitch, the turning rate n, the hands'
//! torque, the three coefficients $df/dp'$, $df/dp$, $df/d\theta$ and the two roots; the
//! free-wheeling cubic's roots beside them.
//!
//! γ is in degrees (Carvallo's sign: the bicycle leans to −γ), V is the speed $Rs$ in m/s.
//! Unknown, repeated or missing arguments, non-finite numbers, an out-of-range γ, a negative
//! speed and a turn that does not exist are errors naming the value, exit code 2.

use carvallo::bicycle_straight::Constants;
use carvallo::bicycle_turn::{Hold, LockedSteer, MAX_GAMMA};
use serde_json::json;

use crate::args::finite;

/// `carvallo turn`: a steady turn of Carvallo's bicycle with the handlebar held.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: Carvallo's (the constants of n° 117), the only one `turn` knows
    #[arg(long, value_parser = ["carvallo"])]
    pub model: String,
    /// The handlebar angle γ [degrees] (Carvallo's sign: the bicycle leans to −γ)
    #[arg(long = "gamma", value_name = "DEG", value_parser = gamma, allow_hyphen_values = true)]
    pub gamma_deg: f64,
    /// The rolling speed Rs [m/s]
    #[arg(long, value_name = "V", value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true)]
    pub speed: f64,
    /// Print JSON instead of text
    #[arg(long)]
    pub json: bool,
}

/// The handlebar angle in degrees: finite and strictly within ±[`MAX_GAMMA`].
fn gamma(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    let max = MAX_GAMMA.to_degrees();
    if x.abs() >= max {
        return Err(format!("must lie strictly between -{max:.1} and {max:.1} degrees"));
    }
    Ok(x)
}

/// Runs `carvallo turn`: the text to print, or an error naming the bad value.
pub fn run(c: &Args) -> Result<String, String> {
    let err = |e: carvallo::bicycle_turn::TurnError| e.to_string();
    let bike = LockedSteer::new(Constants::MEMOIR).map_err(|e| e.to_string())?;
    let t = bike.steady_turn(c.gamma_deg.to_radians(), c.speed).map_err(err)?;
    let f = bike.fall_equation(&t, Hold::Rolling).map_err(err)?;
    let w = bike.free_wheel(&t).map_err(err)?;
    let roots: Vec<f64> = f.roots.iter().map(|r| r.re).collect();
    let free: Vec<[f64; 2]> = w.roots.iter().map(|r| [r.re, r.im]).collect();
    if c.json {
        let out = json!({
            "model": "carvallo",
            "gamma_deg": c.gamma_deg,
            "speed": c.speed,
            "lean": t.lean,
            "pitch": t.pitch,
            "turning_rate": t.yaw_rate,
            "hands_torque": t.hands_torque,
            "dfdpp": f.dfdpp,
            "dfdp": f.dfdp,
            "dfdtheta": f.dfdtheta,
            "dfdtheta_gravity": f.dfdtheta_gravity,
            "roots": roots,
            "free_wheel_roots": free,
        });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    // Upright, the lean and the rates are signed zeros: print them as 0.
    let (lean, yaw) = (t.lean + 0.0, t.yaw_rate + 0.0);
    let mut s = format!(
        "model carvallo, handlebar held at gamma = {} deg, speed {} m/s\n",
        c.gamma_deg, c.speed
    );
    s.push_str(&format!("lean theta0: {lean:.6} rad\n"));
    s.push_str(&format!("pitch: {:.6e} rad\n", t.pitch));
    s.push_str(&format!("turning rate n: {yaw:.6} 1/s\n"));
    s.push_str(&format!("hands' torque: {:.6} N m\n", t.hands_torque));
    s.push_str(&format!(
        "(C) with s held: {:.6} lambda^2 {:+.6} lambda {:+.6} = 0\n",
        f.dfdpp, f.dfdp, f.dfdtheta
    ));
    s.push_str(&format!("roots: {:.6} {:.6} 1/s\n", roots[0], roots[1]));
    let zero = if w.roots[1].norm() < 1e-9 {
        "0 (below 1e-9)".to_string()
    } else {
        format!("{:.6}", w.roots[1].re)
    };
    s.push_str(&format!(
        "free-wheeling roots: {:.6} {zero} {:.6} 1/s\n",
        w.roots[0].re, w.roots[2].re
    ));
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        let turn = |words: &[&str]| parse::<Args>(&[&["turn"], words].concat());
        assert_eq!(
            turn(&["--model", "carvallo", "--gamma", "5", "--speed", "5.5"]),
            Ok(Args { model: "carvallo".into(), gamma_deg: 5.0, speed: 5.5, json: false })
        );
        let e = turn(&["--model", "benchmark", "--gamma", "5", "--speed", "5"]).unwrap_err();
        assert!(e.contains("invalid value 'benchmark' for '--model <MODEL>'"), "{e}");
        assert!(e.contains("[possible values: carvallo]"), "{e}");
        let e = turn(&["--model", "carvallo", "--gamma", "x", "--speed", "5"]).unwrap_err();
        assert!(e.contains("invalid value 'x' for '--gamma <DEG>': not a number"), "{e}");
        let e = turn(&["--model", "carvallo", "--gamma", "-89", "--speed", "5"]).unwrap_err();
        assert!(e.contains("invalid value '-89' for '--gamma <DEG>': must lie strictly"), "{e}");
        let e = turn(&["--model", "carvallo", "--speed", "5"]).unwrap_err();
        assert!(e.contains("--gamma <DEG>"), "{e}");
        let e = turn(&["--json", "--json"]).unwrap_err();
        assert!(e.contains("'--json' cannot be used multiple times"), "{e}");
    }
}
