//! The stable speed window of a Carvallo–Whipple bicycle, from the benchmark parameters or from
//! a parameter file in the anchors' TOML format given as the first argument:
//! `cargo run --release --example benchmark_window -p carvallo [-- FILE.toml]`.
//!
//! It prints the weave and capsize speeds, the stable interval, and the eigenvalues at the
//! middle of that interval (all real parts negative there). A bad file is reported with the key
//! and value at fault, and the example exits with code 2.

use carvallo::whipple::{Whipple, WhippleParams};

fn main() -> std::process::ExitCode {
    let params = match std::env::args().nth(1) {
        None => WhippleParams::benchmark(),
        Some(path) => {
            let read = std::fs::read_to_string(&path)
                .map_err(|e| format!("cannot read `{path}`: {e}"))
                .and_then(|text| {
                    WhippleParams::from_toml_str(&text).map_err(|e| format!("`{path}`: {e}"))
                });
            match read {
                Ok(p) => p,
                Err(err) => {
                    eprintln!("error: {err}");
                    return std::process::ExitCode::from(2);
                }
            }
        }
    };
    let bike = Whipple::new(params);
    let window = bike.stability_window();
    println!("weave speed   {:?} m/s", window.weave_speed);
    println!("capsize speed {:?} m/s", window.capsize_speed);
    for &(lo, hi) in &window.stable {
        println!("stable from {lo:.6} to {hi:.6} m/s");
        if hi.is_finite() {
            let mid = 0.5 * (lo + hi);
            let re: Vec<String> =
                bike.eigenvalues(mid).iter().map(|e| format!("{:+.4}", e.re)).collect();
            println!("  real parts at {mid:.3} m/s: {}", re.join(", "));
        }
    }
    std::process::ExitCode::SUCCESS
}
