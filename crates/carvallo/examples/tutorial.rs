//! The library tutorial of the README, runnable: declare a scene over the generated hoop
//! program, call its evaluator, use the validated `Hoop` model, and compute the benchmark
//! bicycle's stable speed window. `cargo run --example tutorial -p carvallo`.

use carvallo::hoop::Hoop;
use carvallo::whipple::{Whipple, WhippleParams};

carvallo::scene! {
    /// Steady turning of a hoop of radius 0.5 m under g = 9.81 m/s²: only (E) and (S) are
    /// generated, with R and g folded into the code as constants.
    pub mod turning {
        model: hoop,
        fixed: { R: 0.5, g: 9.81 },
        outputs: [equilibrium, stability],
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // 1. The scene: a plain function of the inputs its outputs need (theta, s, n).
    println!("scene `turning`: inputs {:?}, {} operations", turning::INPUTS, turning::OP_COUNT);
    let out = turning::eval(&turning::Args { theta: 0.2, n: -1.0, s: 6.0 });
    println!(
        "(E) residual = {:.6} 1/s², (S) first member = {:.6} 1/s²",
        out.equilibrium, out.stability
    );

    // 2. The model with validated parameters: the two steady turning rates of (E).
    let hoop = Hoop::new(0.5, 1.0, 9.81)?;
    if let Some([n1, n2]) = hoop.steady_turning_rates(0.2, 6.0) {
        for n in [n1, n2] {
            let stable = hoop.stability(0.2, 6.0, n) > 0.0;
            println!(
                "steady turning at n = {n:.6} 1/s: {}",
                if stable { "stable" } else { "unstable" }
            );
        }
    }
    // Bad input is a typed error naming the value.
    if let Err(err) = Hoop::new(-0.5, 1.0, 9.81) {
        println!("rejected: {err}");
    }

    // 3. The Carvallo–Whipple benchmark bicycle (Meijaard et al. 2007): stable speed window.
    let window = Whipple::new(WhippleParams::benchmark()).stability_window();
    println!("benchmark bicycle: stable for {:?} m/s", window.stable);
    Ok(())
}
