//! The four eigenvalues of a real $4\times4$ matrix by nalgebra's Schur decomposition with its
//! iterations capped (uncapped, it can loop for ever).

use nalgebra::Matrix4;

/// One eigenvalue.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eigenvalue {
    /// Real part (1/s).
    pub re: f64,
    /// Imaginary part (1/s).
    pub im: f64,
}

/// The largest number of QR sweeps the Schur decomposition may take before giving up.
pub const MAX_SCHUR_ITERATIONS: usize = 500;

/// The four eigenvalues of `a`, or `None` if the Schur decomposition does not converge within
/// [`MAX_SCHUR_ITERATIONS`] (nalgebra's uncapped `complex_eigenvalues` can loop for ever on
/// matrices such as the companion of $x^4 + 1$).
pub fn eigenvalues4(a: &Matrix4<f64>) -> Option<[Eigenvalue; 4]> {
    let schur = a.try_schur(f64::EPSILON, MAX_SCHUR_ITERATIONS)?;
    let z = schur.complex_eigenvalues();
    let out = [0, 1, 2, 3].map(|i| Eigenvalue { re: z[i].re, im: z[i].im });
    out.iter().all(|e| e.re.is_finite() && e.im.is_finite()).then_some(out)
}
