//! Carvallo's root-squaring method (Graeffe's, as he lays it out in n° 14) and the Horner
//! shift of his first tableau, on polynomials given by their coefficients, highest degree
//! first.

/// Horner's scheme for the shift $t = a + u$ (Carvallo's first tableau of n° 14): repeated
/// synthetic division of the polynomial (coefficients highest degree first) by $t - a$.
/// Returns the coefficients in u (highest first) and every row of the tableau.
pub fn horner_shift(coeffs: &[f64], a: f64) -> (Vec<f64>, Vec<Vec<f64>>) {
    let mut work = coeffs.to_vec();
    let mut rows = Vec::new();
    let n = work.len();
    for end in (1..n).rev() {
        for i in 1..=end {
            work[i] += a * work[i - 1];
        }
        rows.push(work[..=end].to_vec());
    }
    (work, rows)
}

/// One root-squaring (Graeffe) step as Carvallo lays it out: from the coefficients
/// $a_0, \dots, a_m$ (highest degree first) of a polynomial with roots $r_i$, those of the
/// polynomial with roots $-r_i^2$ up to sign, $b_k = a_k^2 - 2a_{k-1}a_{k+1} + 2a_{k-2}a_{k+2}
/// - \dots$ (his rows: the squares, then the double products).
pub fn graeffe_step(a: &[f64]) -> Vec<f64> {
    let m = a.len();
    (0..m)
        .map(|k| {
            let mut b = a[k] * a[k];
            let mut sign = -2.0;
            for j in 1..=k.min(m - 1 - k) {
                b += sign * a[k - j] * a[k + j];
                sign = -sign;
            }
            b
        })
        .collect()
}

/// The largest-modulus root magnitude after `steps` squarings of `coeffs` (highest first):
/// $|r_1| \approx (b_1 / b_0)^{1/2^k}$.
pub fn graeffe_largest(coeffs: &[f64], steps: u32) -> (Vec<Vec<f64>>, f64) {
    let mut rows = vec![coeffs.to_vec()];
    for _ in 0..steps {
        let next = graeffe_step(rows.last().map_or(coeffs, |r| r.as_slice()));
        rows.push(next);
    }
    let last = &rows[rows.len() - 1];
    let ratio = last[1] / last[0];
    (rows.clone(), ratio.powf(1.0 / 2f64.powi(steps as i32)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn squaring_squares_the_roots() {
        // (x - 2)(x + 3) = x^2 + x - 6 has the roots 2 and -3; one squaring gives the roots
        // -4 and -9, that is x^2 + 13x + 36.
        assert_eq!(graeffe_step(&[1.0, 1.0, -6.0]), vec![1.0, 13.0, 36.0]);
        let (_, largest) = graeffe_largest(&[1.0, 1.0, -6.0], 6);
        assert!((largest - 3.0).abs() < 1e-6, "{largest}");
    }
}
