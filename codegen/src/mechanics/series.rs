//! Truncated series in the bookkeeping symbol ε and small 3-vectors and 3 × 3 matrices of
//! expressions, the algebra of the exact linearisation of the Carvallo–Whipple bicycle.
//!
//! Every small quantity of the perturbed motion (lean φ, steer δ, yaw ψ, their rates and
//! accelerations, the pitch of the frame) is written as ε times a symbol (or ε² for the pitch,
//! which the contact constraint makes of second order). Truncating every product at a fixed
//! power of ε keeps exactly the terms the linear equations (order 1) or the potential energy
//! (order 2) need; the truncation is exact polynomial arithmetic, nothing is rounded.

use symbolica::atom::{Atom, AtomCore};

use crate::cas::var;

/// The bookkeeping symbol ε.
pub fn eps() -> Atom {
    var("eps")
}

/// The power of ε in the monomial `key` (a power of ε or 1).
fn eps_degree(key: &Atom) -> u32 {
    let e = eps();
    let sym = e.get_symbol().expect("eps is a symbol");
    let d = (&e * &key.derivative(sym) / key).expand();
    (0..16).find(|k| d == Atom::num(*k as i64)).unwrap_or(u32::MAX)
}

/// The coefficients of $\varepsilon^0, \dots, \varepsilon^n$ in `e` (after expansion).
pub fn coefficients(e: &Atom, n: u32) -> Vec<Atom> {
    let mut out = vec![Atom::num(0); n as usize + 1];
    let expanded = e.expand();
    for (key, coeff) in expanded.coefficient_list::<u8>(std::slice::from_ref(&eps())) {
        let k = eps_degree(&key);
        if k <= n {
            out[k as usize] += coeff;
        }
    }
    out.into_iter().map(|c| c.expand()).collect()
}

/// `e` truncated after the power $\varepsilon^n$.
pub fn trunc(e: &Atom, n: u32) -> Atom {
    let mut out = Atom::num(0);
    for (k, c) in coefficients(e, n).into_iter().enumerate() {
        out += c * eps().pow(Atom::num(k as i64));
    }
    out
}

/// A column vector of three expressions.
pub type V3 = [Atom; 3];
/// A 3 × 3 matrix of expressions, by rows.
pub type M3 = [[Atom; 3]; 3];

/// The vector (a, b, c).
pub fn v3(a: Atom, b: Atom, c: Atom) -> V3 {
    [a, b, c]
}

/// The zero vector.
pub fn zero3() -> V3 {
    [Atom::num(0), Atom::num(0), Atom::num(0)]
}

/// Sum of two vectors.
pub fn add(a: &V3, b: &V3) -> V3 {
    [&a[0] + &b[0], &a[1] + &b[1], &a[2] + &b[2]]
}

/// Difference of two vectors.
pub fn sub(a: &V3, b: &V3) -> V3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

/// Product of a vector by a scalar.
pub fn scale(k: &Atom, a: &V3) -> V3 {
    [k * &a[0], k * &a[1], k * &a[2]]
}

/// Scalar product, truncated at order `n`.
pub fn dot(a: &V3, b: &V3, n: u32) -> Atom {
    trunc(&(&a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]), n)
}

/// Cross product, truncated at order `n`.
pub fn cross(a: &V3, b: &V3, n: u32) -> V3 {
    [
        trunc(&(&a[1] * &b[2] - &a[2] * &b[1]), n),
        trunc(&(&a[2] * &b[0] - &a[0] * &b[2]), n),
        trunc(&(&a[0] * &b[1] - &a[1] * &b[0]), n),
    ]
}

/// Applies `f` to every component.
pub fn map3(a: &V3, f: impl Fn(&Atom) -> Atom) -> V3 {
    [f(&a[0]), f(&a[1]), f(&a[2])]
}

/// Matrix times vector, truncated at order `n`.
pub fn mv(m: &M3, a: &V3, n: u32) -> V3 {
    let row = |i: usize| trunc(&(&m[i][0] * &a[0] + &m[i][1] * &a[1] + &m[i][2] * &a[2]), n);
    [row(0), row(1), row(2)]
}

/// Matrix product, truncated at order `n`.
pub fn mm(a: &M3, b: &M3, n: u32) -> M3 {
    let e = |i: usize, j: usize| {
        trunc(&(&a[i][0] * &b[0][j] + &a[i][1] * &b[1][j] + &a[i][2] * &b[2][j]), n)
    };
    [[e(0, 0), e(0, 1), e(0, 2)], [e(1, 0), e(1, 1), e(1, 2)], [e(2, 0), e(2, 1), e(2, 2)]]
}

/// The transposed matrix.
pub fn transpose(a: &M3) -> M3 {
    let e = |i: usize, j: usize| a[j][i].clone();
    [[e(0, 0), e(0, 1), e(0, 2)], [e(1, 0), e(1, 1), e(1, 2)], [e(2, 0), e(2, 1), e(2, 2)]]
}

/// Rotation about x by the angle whose sine and cosine are `s`, `c`.
pub fn rot_x(s: &Atom, c: &Atom) -> M3 {
    let (o, z) = (Atom::num(1), Atom::num(0));
    [[o, z.clone(), z.clone()], [z.clone(), c.clone(), -s], [z, s.clone(), c.clone()]]
}

/// Rotation about y by the angle whose sine and cosine are `s`, `c`.
pub fn rot_y(s: &Atom, c: &Atom) -> M3 {
    let (o, z) = (Atom::num(1), Atom::num(0));
    [[c.clone(), z.clone(), s.clone()], [z.clone(), o, z.clone()], [-s, z, c.clone()]]
}

/// Rotation about z by the angle whose sine and cosine are `s`, `c`.
pub fn rot_z(s: &Atom, c: &Atom) -> M3 {
    let (o, z) = (Atom::num(1), Atom::num(0));
    [[c.clone(), -s, z.clone()], [s.clone(), c.clone(), z.clone()], [z.clone(), z, o]]
}

/// The inertia matrix with entries `xx, yy, zz` on the diagonal and `xz` off it (the bodies are
/// symmetric about their x–z plane).
pub fn inertia(xx: Atom, yy: Atom, zz: Atom, xz: Atom) -> M3 {
    let z = Atom::num(0);
    [[xx, z.clone(), xz.clone()], [z.clone(), yy, z.clone()], [xz, z, zz]]
}
