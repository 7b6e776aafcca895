//! The classical fourth-order Runge–Kutta step, for any fixed state size.

/// One classical Runge–Kutta step of $x' = f(x)$ from `x` with step `dt`.
pub fn rk4_step<const N: usize>(
    f: impl Fn([f64; N]) -> [f64; N],
    x: [f64; N],
    dt: f64,
) -> [f64; N] {
    let axpy = |a: f64, k: [f64; N]| std::array::from_fn(|i| x[i] + a * k[i]);
    let k1 = f(x);
    let k2 = f(axpy(0.5 * dt, k1));
    let k3 = f(axpy(0.5 * dt, k2));
    let k4 = f(axpy(dt, k3));
    std::array::from_fn(|i| x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harmonic_oscillator_over_one_period() {
        let (n, tau) = (1000, std::f64::consts::TAU);
        let mut x = [1.0, 0.0];
        for _ in 0..n {
            x = rk4_step(|y| [y[1], -y[0]], x, tau / n as f64);
        }
        assert!((x[0] - 1.0).abs() < 1e-10 && x[1].abs() < 1e-10, "{x:?}");
    }
}
