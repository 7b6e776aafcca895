//! 2 × 2 matrices as plain arrays (rows), with the determinant and the mixed determinant that
//! the linearised bicycle's characteristic polynomials are made of.

use std::ops::{Add, Mul, Sub};

/// A 2 × 2 matrix, row by row.
pub type Mat2 = [[f64; 2]; 2];

/// $\det A$ (of `f64` or of any number type with the ring operations, such as double-double
/// or dual numbers).
pub fn det<T: Copy + Mul<Output = T> + Sub<Output = T>>(a: &[[T; 2]; 2]) -> T {
    a[0][0] * a[1][1] - a[0][1] * a[1][0]
}

/// The mixed determinant $\det(A + B) - \det A - \det B$: the coefficient of $xy$ in
/// $\det(xA + yB)$.
pub fn mix<T>(a: &[[T; 2]; 2], b: &[[T; 2]; 2]) -> T
where
    T: Copy + Add<Output = T> + Mul<Output = T> + Sub<Output = T>,
{
    a[0][0] * b[1][1] + b[0][0] * a[1][1] - a[0][1] * b[1][0] - b[0][1] * a[1][0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mix_is_the_cross_term_of_det() {
        let (a, b) = ([[1.0, 2.0], [3.0, 5.0]], [[-2.0, 0.5], [4.0, 1.0]]);
        let sum = [[a[0][0] + b[0][0], a[0][1] + b[0][1]], [a[1][0] + b[1][0], a[1][1] + b[1][1]]];
        assert_eq!(det(&sum) - det(&a) - det(&b), mix(&a, &b));
    }
}
