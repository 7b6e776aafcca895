//! A scene over the generated hoop program that folds in every physical constant, and the
//! memoir's discussion data built on it: `cargo run --example hoop_scene -p carvallo`.
//!
//! The scene keeps only the stability first member (S) of n° 9 with $R$, $\mu$ and $g$ fixed,
//! so the generated function takes $(\theta, s, n)$ only. The example then scans the rolling
//! rate $s$ for the smallest stable straight run (θ = 0, n = 0; memoir n° 14/18:
//! $s^2 > g / (4R)$), and prints the special points of figure 3 (n° 14) from
//! [`carvallo::hoop::discussion::special_points`].

carvallo::scene! {
    /// (S) for a hoop of radius 0.5 m and mass 1 kg under g = 9.81 m/s².
    pub mod upright {
        model: hoop,
        fixed: { R: 0.5, mu: 1.0, g: 9.81 },
        outputs: [stability],
    }
}

fn main() {
    println!("scene `upright`: inputs {:?}, {} operations", upright::INPUTS, upright::OP_COUNT);
    // Bisection on s for the sign change of (S) at theta = 0, n = 0.
    let stable = |s: f64| upright::eval(&upright::Args { theta: 0.0, n: 0.0, s }).stability > 0.0;
    let (mut lo, mut hi) = (0.0, 20.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if stable(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let exact = (9.81f64 / (4.0 * 0.5)).sqrt();
    println!("smallest stable rolling rate: s = {hi:.9} 1/s (memoir: sqrt(g/4R) = {exact:.9})");
    let sp = carvallo::hoop::discussion::special_points();
    println!("figure 3 (x = cos theta, y = s^2): A = {:?}, D = {:?}, F = {:?}", sp.a, sp.d, sp.f);
    println!(
        "vertical tangent of (S): theta = {:.4} deg, s = {:.4} (unit sqrt(g/R))",
        sp.vertical.theta_deg, sp.vertical.s
    );
}
